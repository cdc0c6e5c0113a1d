#include "pipeline/SketchToPart.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <limits>
#include <optional>
#include <utility>

#include "base/Stopwatch.h"
#include "rig/BoneSegments.h"
#include "rig/SkeletonSymmetry.h"

namespace rigmesh {
namespace {

// A bone split to match its mirror image (rig/SkeletonSymmetry) hands the
// cross sections beyond its new joint to the new bone (2.3: each bone owns
// the sections between its joints). The new joint sits at the bone's
// middle, so it takes the section halfway along the axis between the
// bone's end sections.
void recordSplit(PartSkeleton& rig, const std::vector<CylinderSections>& cylinders,
                 const BoneSplit& split) {
    const Skeleton& skeleton = rig.skeleton;
    for (std::size_t c = 0; c < rig.cylinderBones.size(); ++c) {
        std::vector<BoneId>& bones = rig.cylinderBones[c];
        std::vector<int>& joints = rig.jointSections[c];
        const auto at = std::find(bones.begin(), bones.end(), split.bone);
        if (at == bones.end())
            continue;
        const std::size_t m = static_cast<std::size_t>(at - bones.begin());
        const CylinderSections& cylinder = cylinders[c];
        const int last = static_cast<int>(cylinder.sections.size()) - 1;
        const int from = std::clamp(joints[m], 0, last), to = std::clamp(joints[m + 1], 0, last);
        int middle = (from + to) / 2;
        if (static_cast<int>(cylinder.axisPosition.size()) > to) {
            const double halfway = 0.5 * (cylinder.axisPosition[from] + cylinder.axisPosition[to]);
            for (int s = from; s <= to; ++s)
                if (std::abs(cylinder.axisPosition[s] - halfway) <
                    std::abs(cylinder.axisPosition[middle] - halfway))
                    middle = s;
        }
        // The kept bone now runs from its head to the new joint: it keeps
        // the half at its head's end of the range.
        const Vec3 head = skeleton.joint(skeleton.bone(split.bone).head).position;
        const Vec2 head2(head.x(), head.y());
        const bool keptAtStart = (head2 - cylinder.sections[from].centre()).norm() <=
                                 (head2 - cylinder.sections[to].centre()).norm();
        bones.insert(bones.begin() + static_cast<std::ptrdiff_t>(keptAtStart ? m + 1 : m),
                     split.added);
        joints.insert(joints.begin() + static_cast<std::ptrdiff_t>(m + 1), middle);
        return;
    }
}

// The skeleton's bones and joints by position, looked up once per part
// rather than per vertex: ids, segments, the bones at each joint in the
// order of skeleton.bones() (as Skeleton::bonesAt lists them). Every distance
// below is taken to the same segment as before, so the lists are unchanged.
struct BoneTables {
    std::vector<BoneId> ids;
    std::vector<BoneSegment> segments;
    std::vector<std::array<int, 2>> ends;  // head and tail joint, by position
    std::vector<std::vector<int>> bonesAtJoint;

    explicit BoneTables(const Skeleton& skeleton) : segments(segmentsOf(skeleton)) {
        bonesAtJoint.resize(skeleton.joints().size());
        for (const Bone& bone : skeleton.bones()) {
            const int b = static_cast<int>(ids.size());
            ids.push_back(bone.id);
            ends.push_back({skeleton.indexOfJoint(bone.head), skeleton.indexOfJoint(bone.tail)});
            for (int joint : ends.back())
                bonesAtJoint[joint].push_back(b);
        }
    }
    int degree(int joint) const { return static_cast<int>(bonesAtJoint[joint].size()); }
};

void addUnique(std::vector<int>& bones, int bone) {
    if (std::find(bones.begin(), bones.end(), bone) == bones.end())
        bones.push_back(bone);
}

// A section's bone owns a vertex only between the planes through its end
// joints normal to it: past the plane at a joint with one other
// bone, that bone competes too (it is the closer one there, or ties at the
// joint); past a branching joint's plane the vertex is left to the
// visibility test (false). Otherwise a limb bone could reach past its joint
// into the next bone's territory. Bones are by position in skeleton.bones().
bool ownersWithinJointPlanes(const BoneTables& tables, const std::vector<int>& sectionBones,
                             const Vec3& p, std::vector<int>& owners) {
    owners.clear();
    for (int bone : sectionBones) {
        addUnique(owners, bone);
        const double t = closestSegmentParameter(p, tables.segments[bone]);
        const auto [head, tail] = tables.ends[bone];
        for (const auto& [past, end] : {std::pair{t <= 0.0, head}, {t >= 1.0, tail}}) {
            if (!past || tables.degree(end) < 2)
                continue;  // within the bone, or beyond a tip (the cap is its own)
            if (tables.degree(end) > 2)
                return false;
            for (int other : tables.bonesAtJoint[end])
                addUnique(owners, other);
        }
    }
    return true;
}

// The closest of `owners` and their neighbours, with every bone within the
// tie tolerance, as closestVisibleBones would list them. Near a joint a
// neighbouring bone (across the joint, or across a junction: up to two joints
// away) may be closer than the owners: then the shortcut does not hold and
// the vertex is left to the visibility test (empty list).
std::vector<std::pair<int, double>> closestAmongNeighbours(const BoneTables& tables,
                                                           const std::vector<int>& owners,
                                                           const Vec3& p, double tieTolerance) {
    auto distanceTo = [&](int bone) { return pointSegmentDistance(p, tables.segments[bone]); };
    std::vector<std::pair<int, double>> candidates;
    double best = std::numeric_limits<double>::infinity();
    for (int bone : owners) {
        candidates.emplace_back(bone, distanceTo(bone));
        best = std::min(best, candidates.back().second);
    }
    const std::size_t ownerCount = candidates.size();
    double nearest = best;
    for (std::size_t o = 0; o < ownerCount; ++o)
        for (int joint : tables.ends[owners[o]])
            for (int across : tables.bonesAtJoint[joint])
                for (int end : tables.ends[across])
                    for (int other : tables.bonesAtJoint[end]) {
                        if (std::any_of(candidates.begin(), candidates.end(),
                                        [&](const auto& c) { return c.first == other; }))
                            continue;
                        const double d = distanceTo(other);
                        if (d < best * (1 - tieTolerance))
                            return {};
                        if (d <= best * (1 + tieTolerance)) {
                            // A tie the visibility test would list too.
                            candidates.emplace_back(other, d);
                            nearest = std::min(nearest, d);
                        }
                    }
    std::vector<std::pair<int, double>> closest;
    for (const auto& [bone, d] : candidates)
        if (d <= nearest * (1 + tieTolerance))
            closest.emplace_back(bone, d);
    return closest;
}

}  // namespace

ClosestBones closestBonesFromConstruction(const SketchSurface& surface,
                                          const std::vector<CylinderSections>& cylinders,
                                          const PartSkeleton& rig, double tieTolerance) {
    const Skeleton& skeleton = rig.skeleton;
    const BoneTables tables(skeleton);
    ClosestBones closest(surface.mesh.vertices.size());
    std::vector<int> sectionBones, owners;
    for (std::size_t v = 0; v < closest.size(); ++v) {
        const VertexOrigin& origin = surface.origins[v];
        if (origin.kind != RegionKind::Cylindrical)
            continue;
        const CylinderSections& cylinder = cylinders[origin.region];
        int section = origin.section;
        if (section < 0)
            section = origin.axisPosition > 0 ? -2 : -1;  // which tip
        const int count = static_cast<int>(cylinder.sections.size());
        const Vec3& p = surface.mesh.vertices[v];
        sectionBones.clear();
        for (BoneId id : bonesOfSection(rig, origin.region, section, count))
            if (skeleton.hasBone(id))
                sectionBones.push_back(skeleton.indexOfBone(id));
        if (!ownersWithinJointPlanes(tables, sectionBones, p, owners) || owners.empty())
            continue;
        closest[v] = closestAmongNeighbours(tables, owners, p, tieTolerance);
    }
    return closest;
}

SketchToPartResult sketchToPart(const std::vector<Vec2>& stroke, const std::string& name,
                                const SketchToPartOptions& options) {
    SketchToPartResult result;
    result.surface = sketchToSurface(stroke, options.surface);

    auto start = std::chrono::steady_clock::now();
    result.skeleton =
        buildSkeleton(result.surface.decomposition, result.surface.cylinders, options.skeleton);
    // A symmetric outline gets mirrored joints (rig/SkeletonSymmetry): the
    // mirror is the outline's own, a plane containing the sketch plane's
    // normal. A limb with fewer joints than its image gets as many, its
    // bones split and their cross sections shared out (recordSplit).
    if (options.mirrorJoints) {
        SymmetrizeOptions symmetry;
        symmetry.search.containing = Vec3::UnitZ();
        const SymmetrizeReport report = symmetrizeSkeleton(
            result.skeleton.skeleton, outlinePoints(result.surface.polygon.points), symmetry);
        for (const BoneSplit& split : report.splits)
            recordSplit(result.skeleton, result.surface.cylinders, split);
    }
    result.skeletonMilliseconds = millisecondsSince(start);

    Part& part = result.part;
    part.name = name;
    part.outline = result.surface.polygon.points;
    part.mesh = result.surface.surface.mesh;
    part.origins = result.surface.surface.origins;
    part.mirror = result.surface.surface.mirror;
    part.skeleton = result.skeleton.skeleton;

    start = std::chrono::steady_clock::now();
    // The solver works by bone position; the part keeps bone ids.
    const ClosestBones closest =
        closestBonesFromConstruction(result.surface.surface, result.surface.cylinders,
                                     result.skeleton, options.weights.tieTolerance);
    // The surface is its own mirror image in the sketch plane and the bones
    // lie in it: the heat is solved for mirror-symmetric weights on half the
    // unknowns (rig/BoneHeatSolver.h).
    part.weights =
        weightsById(part.skeleton, computeBoneHeatWeights(part.mesh, part.boneSegments(), closest,
                                                          options.weights, part.mirror));
    part.knownClosestBones = closestById(part.skeleton, closest);
    result.weightsMilliseconds = millisecondsSince(start);
    result.totalMilliseconds = result.surface.milliseconds.total + result.skeletonMilliseconds +
                               result.weightsMilliseconds;
    return result;
}

}  // namespace rigmesh
