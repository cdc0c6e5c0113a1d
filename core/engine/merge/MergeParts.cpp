#include "merge/MergeParts.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <exception>
#include <functional>
#include <set>

#include "base/Error.h"
#include "base/ParallelFor.h"
#include "base/Stopwatch.h"
#include "merge/MeshUnion.h"
#include "merge/SeamSmoothing.h"
#include "mesh/MeshAdjacency.h"
#include "mesh/MeshSelfIntersections.h"
#include "part/BoneAnnotations.h"
#include "part/BoneConnection.h"
#include "part/CarryAcross.h"
#include "rig/BoneSegments.h"
#include "rig/LocalBoneHeat.h"
#include "rig/ShortBones.h"

namespace rigmesh {

namespace {

using Clock = std::chrono::steady_clock;

// The target's weights by merged bone id. After a split the bone keeps its
// id and its weights, and the vertices weighted on it seed the inclusion
// test: those nearer the new tail half fail it and are solved again (3.2.2).
WeightsById targetWeights(const Part& target, const SkeletonJoin& join, BoneId splitBone,
                          std::vector<int>& seeds) {
    WeightsById weights = target.weights.perVertex;
    if (!join.splitTail)
        return weights;
    for (std::size_t v = 0; v < weights.size(); ++v)
        for (const auto& entry : weights[v])
            if (entry.first == splitBone)
                seeds.push_back(static_cast<int>(v));
    return weights;
}

WeightsById draggedWeights(const Part& dragged, const SkeletonJoin& join) {
    WeightsById weights = dragged.weights.perVertex;
    for (auto& list : weights) {
        for (auto& entry : list)
            entry.first = join.draggedBones.at(entry.first);
        normaliseWeights(list);
    }
    return weights;
}

// A new bone (connect, split) may now be the closest bone of vertices far
// from the loop, inside the target (paper Fig. 9: the connecting bone runs
// through the body). Those whose distance to it is below the distance to
// their leading bone join the seeds; the inclusion test (3.2.2) then decides.
void addVerticesNearerToNewBones(const TriMesh& mesh, const Skeleton& skeleton,
                                 const WeightsById& weights, const std::vector<BoneId>& added,
                                 std::vector<int>& seeds) {
    if (added.empty())
        return;
    std::vector<BoneSegment> newBones;
    for (BoneId id : added)
        newBones.push_back(segmentOf(skeleton, id));
    for (int v = 0; v < mesh.vertexCount(); ++v) {
        if (weights[v].empty())
            continue;
        const BoneId leading = leadingBone(weights[v]);
        if (!skeleton.hasBone(leading))
            continue;
        const double own = pointSegmentDistance(mesh.vertices[v], segmentOf(skeleton, leading));
        for (const BoneSegment& bone : newBones)
            if (pointSegmentDistance(mesh.vertices[v], bone) < own) {
                seeds.push_back(v);
                break;
            }
    }
}

// The bones that are some vertex's largest weight.
std::set<BoneId> leadingBones(const WeightsById& weights) {
    std::set<BoneId> leading;
    for (const auto& list : weights)
        if (!list.empty())
            leading.insert(leadingBone(list));
    return leading;
}

// Paper 3.2: bones that are no vertex's largest weight go (a leaf bone with
// its end joint; an inner bone collapses onto its busier end). Only bones
// that led vertices before the merge are candidates, i.e. bones the union
// buried: a bone that never led any (a connecting bone, made for posing)
// stays. Returns the removed bones; vertices that lost weight join `touched`.
std::vector<BoneId> pruneBones(Skeleton& skeleton, WeightsById& weights,
                               const std::set<BoneId>& candidates,
                               std::map<JointId, JointId>& renamed, std::vector<int>& touched) {
    std::vector<BoneId> pruned;
    while (skeleton.boneCount() > 1) {
        const std::set<BoneId> leading = leadingBones(weights);
        std::optional<BoneId> victim;
        for (const Bone& bone : skeleton.bones()) {
            if (leading.contains(bone.id) || !candidates.contains(bone.id))
                continue;
            const bool leaf = skeleton.degree(bone.head) == 1 || skeleton.degree(bone.tail) == 1;
            if (!victim || leaf) {
                victim = bone.id;
                if (leaf)
                    break;
            }
        }
        if (!victim)
            break;
        const Bone bone = skeleton.bone(*victim);
        if (skeleton.degree(bone.tail) == 1 || skeleton.degree(bone.head) == 1) {
            const JointId end = skeleton.degree(bone.tail) == 1 ? bone.tail : bone.head;
            skeleton.removeJoint(end);
        } else {
            const bool tailBusier = skeleton.degree(bone.tail) > skeleton.degree(bone.head);
            const Vec3 at = skeleton.joint(tailBusier ? bone.tail : bone.head).position;
            skeleton.collapseBone(bone.id, at);
            for (auto& [from, to] : renamed)
                if (to == bone.tail)
                    to = bone.head;
        }
        pruned.push_back(bone.id);
        for (std::size_t v = 0; v < weights.size(); ++v) {
            const auto before = weights[v].size();
            std::erase_if(weights[v], [&](const auto& e) { return e.first == bone.id; });
            if (weights[v].size() != before) {
                normaliseWeights(weights[v]);
                touched.push_back(static_cast<int>(v));
            }
        }
    }
    std::erase_if(renamed, [&](const auto& entry) { return !skeleton.hasJoint(entry.second); });
    return pruned;
}

// An input's self-intersecting face pairs: decided on about half the faces
// when it is exactly its own mirror image (mesh/MeshSelfIntersections.h;
// the pairs are counted in full only if there are any).
int selfIntersectingPairs(const Part& part) {
    if (part.mirror.empty())
        return countSelfIntersectingFacePairs(part.mesh);
    return static_cast<int>(selfIntersectingFacePairs(part.mesh, part.mirror).size());
}

// The union needs closed, oriented surfaces that do not cross themselves
// anywhere (CGAL's corefinement only notices a self-intersection near the
// other surface): each input is checked and refused by name, the target
// first, each for its topology before its self-intersections. The
// self-intersection checks (a box intersection over each whole surface)
// run on a second thread while `unionStep` runs on this one; a refusal of
// an input is thrown before anything `unionStep` threw. Validation cannot
// be skipped for parts made here: a merge's smoothed seam, a cut's faired
// patch and an imported surface are not checked for self-intersections
// when they are made.
void checkInputsDuring(const Part& target, const Part& dragged,
                       const std::function<void()>& unionStep) {
    if (const std::vector<Message> problems = target.validateSolid(); !problems.empty())
        throw Error(MessageId::MergeTargetNotSolid, problems.front());
    const std::vector<Message> draggedProblems = dragged.validateSolid();
    if (!draggedProblems.empty()) {
        if (const int pairs = selfIntersectingPairs(target); pairs > 0)
            throw Error(MessageId::MergeTargetIntersectsItself, pairs);
        throw Error(MessageId::MergeDraggedNotSolid, draggedProblems.front());
    }
    std::array<int, 2> pairs{0, 0};
    std::exception_ptr unionError;
    parallelFor(2, 2, [&](int begin, int end, int) {
        for (int k = begin; k < end; ++k) {
            if (k == 1) {
                pairs[0] = selfIntersectingPairs(target);
                pairs[1] = selfIntersectingPairs(dragged);
                continue;
            }
            try {
                unionStep();
            } catch (...) {
                unionError = std::current_exception();
            }
        }
    });
    if (pairs[0] > 0)
        throw Error(MessageId::MergeTargetIntersectsItself, pairs[0]);
    if (pairs[1] > 0)
        throw Error(MessageId::MergeDraggedIntersectsItself, pairs[1]);
    if (unionError)
        std::rethrow_exception(unionError);
}

}  // namespace

std::vector<double> weightDifferences(const WeightsById& a, const WeightsById& b) {
    std::vector<double> differences;
    for (std::size_t v = 0; v < a.size() && v < b.size(); ++v) {
        std::map<BoneId, double> d;
        for (const auto& [bone, w] : a[v])
            d[bone] += w;
        for (const auto& [bone, w] : b[v])
            d[bone] -= w;
        double l1 = 0.0;
        for (const auto& [bone, w] : d)
            l1 += std::abs(w);
        differences.push_back(l1);
    }
    return differences;
}

MergeResult mergeParts(const Part& target, const Part& dragged, const MergeRequest& request) {
    const auto start = Clock::now();
    if (target.skeleton.boneCount() == 0 || dragged.skeleton.boneCount() == 0)
        throw Error(MessageId::MergeNeedsRiggedParts);
    // The joined skeleton is one connected tree (SkeletonJoin).
    requireConnectedSkeleton(target);
    requireConnectedSkeleton(dragged);
    MergeResult result;
    SkeletonJoin join;
    TriMesh draggedMesh;
    MeshUnionResult merged;
    auto stage = Clock::now();
    checkInputsDuring(target, dragged, [&] {
        // The target's mean edge, measured once: the shortest bone the join
        // may make and the seam's edge length unless the request gives one.
        const double meanEdge = meanEdgeLength(target.mesh);
        join = joinSkeletons(target.skeleton, dragged.skeleton, request.join,
                             minimumBoneLength(meanEdge));
        result.draggedTranslation = join.draggedTranslation;
        draggedMesh = dragged.mesh;
        for (Vec3& p : draggedMesh.vertices)
            p += join.draggedTranslation;

        // 3.2.1: the union and the seam remeshed at the part's edge length.
        stage = Clock::now();
        const double edge = request.edgeLength > 0.0 ? request.edgeLength : meanEdge;
        merged = unionMeshes(target.mesh, draggedMesh, edge);
        result.stats.unionMs = millisecondsSince(stage);
    });

    std::vector<CarrySource> inputs(2);
    inputs[0].mesh = &target.mesh;
    std::vector<int> splitSeeds;
    inputs[0].weights = targetWeights(target, join, request.join.targetBone, splitSeeds);
    inputs[0].mirror = target.mirror;
    inputs[1].mesh = &draggedMesh;
    inputs[1].weights = draggedWeights(dragged, join);
    inputs[1].mirror = dragged.mirror;
    CarriedData carried = carryAcross(merged.sources, inputs);

    stage = Clock::now();
    result.movedVertices = smoothSeam(merged.mesh, merged.loop);
    result.stats.smoothingMs = millisecondsSince(stage);

    // Prune (3.2), keeping the bones the user asked for, then a central root.
    std::set<BoneId> keep;
    if (join.connectingBone)
        keep.insert(*join.connectingBone);
    if (join.splitTail) {
        keep.insert(*join.splitTail);
        keep.insert(request.join.targetBone);
    }
    std::vector<int> seeds;
    for (int v = 0; v < merged.mesh.vertexCount(); ++v) {
        const VertexSource& source = merged.sources[v];
        if (merged.onLoop[v] ||
            (source.kind == VertexSource::Kind::Vertex && source.mesh == 0 &&
             std::binary_search(splitSeeds.begin(), splitSeeds.end(), source.index)))
            seeds.push_back(v);
    }
    result.draggedJoints = join.draggedJoints;
    std::set<BoneId> candidates = leadingBones(inputs[0].weights);
    candidates.merge(leadingBones(inputs[1].weights));
    for (BoneId id : keep)
        candidates.erase(id);
    result.prunedBones =
        pruneBones(join.skeleton, carried.weights, candidates, result.draggedJoints, seeds);
    join.skeleton.setRoot(chooseCentralRoot(join.skeleton));
    join.skeleton.reorient();

    // 3.2.2 (or 2.4 on the whole part).
    stage = Clock::now();
    std::vector<int> unknown = carried.needWeights;
    for (int v = 0; v < merged.mesh.vertexCount(); ++v)
        if (carried.weights[v].empty())
            unknown.push_back(v);
    std::sort(unknown.begin(), unknown.end());
    unknown.erase(std::unique(unknown.begin(), unknown.end()), unknown.end());
    WeightsById weights;
    std::vector<BoneId> extra(keep.begin(), keep.end());
    std::erase_if(extra, [&](BoneId id) { return !join.skeleton.hasBone(id); });
    result.requestedBones = extra;
    addVerticesNearerToNewBones(merged.mesh, join.skeleton, carried.weights, extra, seeds);
    if (request.reskin == Reskin::Local) {
        LocalBoneHeatOptions options;
        options.heat = request.heat;
        LocalBoneHeatResult local = recomputeWeightsLocally(
            merged.mesh, join.skeleton, std::move(carried.weights), seeds, unknown, extra, options);
        weights = std::move(local.weights);
        result.stats.verticesInvolved = local.verticesInvolved();
        result.stats.bonesInvolved = static_cast<int>(local.bones.size());
    } else {
        weights = recomputeWeightsGlobally(merged.mesh, join.skeleton, request.heat);
        result.stats.verticesInvolved = merged.mesh.vertexCount();
        result.stats.bonesInvolved = join.skeleton.boneCount();
    }
    result.stats.reskinMs = millisecondsSince(stage);
    if (request.compareGlobal) {
        stage = Clock::now();
        const WeightsById global =
            recomputeWeightsGlobally(merged.mesh, join.skeleton, request.heat);
        result.stats.globalMs = millisecondsSince(stage);
        const std::vector<double> differences = weightDifferences(weights, global);
        result.stats.p90WeightDifference = percentile(differences, 0.9);
        result.stats.p99WeightDifference = percentile(differences, 0.99);
        double sum = 0.0;
        for (double d : differences)
            sum += d;
        result.stats.meanWeightDifference = sum / static_cast<double>(differences.size());
    }

    Part& part = result.part;
    part.name = target.name;
    // A merged part is no longer one sketch: outline and sketch regions say so
    // by being empty (Part.h).
    part.mesh = std::move(merged.mesh);
    part.mirror = std::move(carried.mirror);
    part.skeleton = std::move(join.skeleton);
    part.weights.perVertex = std::move(weights);
    // Names, locks and hand-painted weights outside the re-skinned band
    // survive: both parts' on surviving bones, painted if either was.
    carryBoneAnnotations(target, part);
    carryBoneAnnotations(dragged, part, &join.draggedBones);
    result.sources = std::move(merged.sources);
    result.stats.vertices = part.mesh.vertexCount();
    result.stats.bones = part.skeleton.boneCount();
    result.stats.prunedBones = static_cast<int>(result.prunedBones.size());
    result.stats.smoothedVertices = static_cast<int>(result.movedVertices.size());

    const std::vector<Message> problems = part.validateSolid();
    if (!problems.empty())
        throw Error(MessageId::MergeInvalidResult, problems.front());

    result.stats.totalMs = millisecondsSince(start);
    return result;
}

}  // namespace rigmesh
