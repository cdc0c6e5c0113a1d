#include "autorig/AutoRig.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <optional>

#include "autorig/AxisChain.h"
#include "autorig/BoneCoverage.h"
#include "autorig/BonesInside.h"
#include "autorig/CurveSkeleton.h"
#include "autorig/FusedLimbs.h"
#include "autorig/HeldProps.h"
#include "autorig/WeightTransfer.h"
#include "autorig/WornPieces.h"
#include "base/Error.h"
#include "part/BoneWeights.h"
#include "rig/ShortBones.h"
#include "rig/SkeletonSymmetry.h"

namespace rigmesh {

namespace {

// The share of the progress bar each stage takes (measured on the assimp
// test characters: the wrap and the flow are most of the time).
constexpr double kSurfaceDone = 0.35;
constexpr double kSkeletonDone = 0.8;
constexpr double kHeatDone = 0.95;
// At most this many "pieces follow bone" notes; the rest are counted.
constexpr int kPieceNotes = 3;
constexpr BoneId kNoLeader = std::numeric_limits<BoneId>::max();

double diagonalOf(const TriMesh& mesh) {
    Eigen::AlignedBox3d box;
    for (const Vec3& v : mesh.vertices)
        box.extend(v);
    return box.isEmpty() ? 0.0 : box.diagonal().norm();
}

RigProgress stage(const RigProgress& progress, double from, double to) {
    if (!progress)
        return {};
    return [=](double fraction) { return progress(from + (to - from) * fraction); };
}

// Every input vertex's weights: its own surface vertex's, or those at its
// closest point of the surface.
WeightsById weightsOfInput(const TriMesh& input, const RigSurface& surface,
                           const WeightsById& surfaceWeights) {
    std::vector<char> wanted(input.vertices.size(), 0);
    bool any = false;
    for (std::size_t v = 0; v < wanted.size(); ++v)
        any |= (wanted[v] = surface.surfaceVertexOf[v] < 0 ? 1 : 0) != 0;
    WeightsById weights =
        any ? weightsAtClosestPoints(surface.mesh, surfaceWeights, input.vertices, wanted)
            : WeightsById(input.vertices.size());
    for (std::size_t v = 0; v < wanted.size(); ++v)
        if (!wanted[v])
            weights[v] = surfaceWeights[surface.surfaceVertexOf[v]];
    return weights;
}

// Small pieces (eyes, teeth, buttons) move as a whole with the bone that
// leads their vertices' weights. Returns bone -> pieces.
std::map<BoneId, int> followOneBone(const TriMesh& input, const RigSurface& surface,
                                    double fraction, WeightsById& weights) {
    std::map<BoneId, int> following;
    if (surface.pieces < 2)
        return following;
    std::vector<Eigen::AlignedBox3d> boxes(surface.pieces);
    std::vector<int> sizes(surface.pieces, 0);
    Eigen::AlignedBox3d all;
    for (int v = 0; v < input.vertexCount(); ++v)
        if (surface.pieceOf[v] >= 0) {
            boxes[surface.pieceOf[v]].extend(input.vertices[v]);
            ++sizes[surface.pieceOf[v]];
            all.extend(input.vertices[v]);
        }
    const double limit = fraction * all.diagonal().norm();
    const int largest =
        static_cast<int>(std::max_element(sizes.begin(), sizes.end()) - sizes.begin());
    std::vector<std::map<BoneId, double>> sums(surface.pieces);
    for (int v = 0; v < input.vertexCount(); ++v)
        if (surface.pieceOf[v] >= 0)
            for (const auto& [bone, w] : weights[v])
                sums[surface.pieceOf[v]][bone] += w;
    std::vector<BoneId> leader(surface.pieces, kNoLeader);
    for (int p = 0; p < surface.pieces; ++p) {
        if (p == largest || sums[p].empty() || boxes[p].diagonal().norm() > limit)
            continue;
        leader[p] = std::max_element(sums[p].begin(), sums[p].end(), [](auto& a, auto& b) {
                        return a.second < b.second;
                    })->first;
        ++following[leader[p]];
    }
    for (int v = 0; v < input.vertexCount(); ++v)
        if (surface.pieceOf[v] >= 0 && leader[surface.pieceOf[v]] != kNoLeader)
            weights[v] = {{leader[surface.pieceOf[v]], 1.0}};
    return following;
}

void notePieces(const std::map<BoneId, int>& following, const std::string& partName,
                std::vector<Message>& notes) {
    std::vector<std::pair<int, BoneId>> byCount;
    for (const auto& [bone, count] : following)
        byCount.emplace_back(-count, bone);
    std::sort(byCount.begin(), byCount.end());
    int rest = 0;
    for (std::size_t i = 0; i < byCount.size(); ++i) {
        if (static_cast<int>(i) < kPieceNotes)
            notes.push_back({MessageId::AutoRigPiecesFollowBone,
                             {messageArgument(-byCount[i].first),
                              partName + "_bone" + std::to_string(byCount[i].second)}});
        else
            rest -= byCount[i].first;
    }
    if (rest > 0)
        notes.push_back({MessageId::AutoRigMorePiecesFollowBones, {messageArgument(rest)}});
}

}  // namespace

AutoRigResult autoRigPart(const Part& part, const AutoRigOptions& options,
                          const RigProgress& progress) {
    if (part.skeleton.jointCount() > 0)
        throw Error(MessageId::AutoRigPartIsRigged, part.name);
    if (part.mesh.faceCount() == 0)
        throw Error(MessageId::AutoRigNoSurface, part.name);
    reportRigProgress(progress, 0.0);
    RigSurface surface =
        rigSurfaceFor(part.mesh, options.surface, stage(progress, 0.0, kSurfaceDone));
    reportRigProgress(progress, kSurfaceDone);

    AutoRigResult result;
    result.part.name = part.name;
    // The part keeps the mesh as given, but for faces that repeat a corner:
    // they show nothing and a part may not have them (Part::validate).
    result.part.mesh = part.mesh;
    // The mesh is still the file's (maybe open): a document keeps checking
    // only surfaces made here for being closed (model/DocumentFile.cpp).
    result.part.surfaceFromFile = part.surfaceFromFile;
    const int repeating =
        static_cast<int>(std::erase_if(result.part.mesh.faces, [](const std::array<int, 3>& f) {
            return f[0] == f[1] || f[1] == f[2] || f[0] == f[2];
        }));
    FusedLimbsReport fused;
    int propsHeld = 0;
    int piecesWorn = 0;
    try {
        const CurveSkeleton curve =
            extractCurveSkeleton(surface.mainPiece, stage(progress, kSurfaceDone, kSkeletonDone));
        result.part.skeleton = skeletonFromCurve(curve, surface.mainPiece, options.bones);
        // Limbs a small gap apart are one on the proxy (it bridges gaps
        // narrower than alpha) but two in the mesh: their chain becomes two
        // (autorig/FusedLimbs).
        if (surface.kind == RigSurface::Kind::Proxy) {
            fused = splitFusedLimbs(result.part.skeleton, part.mesh, surface.mainPiece);
            // A prop gripped in a fist (an axe, a staff) is one chain on
            // from the hand, not a branch at each of its ends
            // (autorig/HeldProps).
            propsHeld =
                pruneHeldProps(result.part.skeleton, part.mesh, surface.pieceOf, surface.pieces,
                               options.bones.coverageFraction * diagonalOf(part.mesh))
                    .propsHeld;
            // Horns on a helmet, a crest: pieces worn at a limb's end ride
            // on its last bone, not a leaf each (autorig/WornPieces).
            piecesWorn =
                pruneWornPieces(result.part.skeleton, part.mesh, surface.pieceOf, surface.pieces,
                                options.bones.coverageFraction * diagonalOf(part.mesh))
                    .branchesPruned;
        }
    } catch (const Error& error) {
        // A blob the flow contracts to a point: a chain along its main axis.
        if (!flowGaveNoSkeleton(error.message().id))
            throw;
        result.part.skeleton = mainAxisChain(surface.mainPiece);
    }
    // A mirror-symmetric mesh gets a mirror-symmetric rig: mirrored limbs
    // get as many bones, mirrored joints (rig/SkeletonSymmetry). The skeleton
    // lives in the rig surface's main piece, so that is the mesh mirrored.
    symmetrizeSkeleton(result.part.skeleton, surface.mainPiece);
    // No bone shorter than the shortest an edit may make (rig/ShortBones.h):
    // such a bone joins its neighbour.
    const double minimum = minimumBoneLength(surface.mainPiece);
    collapseShortBones(result.part.skeleton, minimum);
    const auto tooShort = [&] {
        const auto shortest = shortestBone(result.part.skeleton);
        return shortest && shortest->length < minimum ? shortest : std::nullopt;
    };
    if (tooShort()) {
        // Only such a bone is left: the flow contracted a blob (a ball, a
        // box) to a segment shorter than a bone, as it contracts others to a
        // point. It gets a chain along its main axis likewise.
        result.part.skeleton = mainAxisChain(surface.mainPiece);
        symmetrizeSkeleton(result.part.skeleton, surface.mainPiece);
        collapseShortBones(result.part.skeleton, minimum);
    }
    if (const auto shortest = tooShort())
        throw Error(MessageId::AutoRigBoneTooShort, shortNumber(shortest->length),
                    shortNumber(minimum));
    // Every region near a bone (autorig/BoneCoverage): a bone bends or a
    // branch grows into a region the curve skeleton left without one.
    coverWithBones(result.part.skeleton, surface.mainPiece, part.mesh.vertices,
                   options.bones.coverageFraction * diagonalOf(part.mesh), minimum);
    // Straight bones of a thin, bent limb cut its corners, and mirroring can
    // move a thin limb's joint out of it: back to the middle of the limb
    // (autorig/BonesInside).
    keepBonesInside(result.part.skeleton, surface.mainPiece, minimum, part.mesh.vertices,
                    options.bones.coverageFraction * diagonalOf(part.mesh));
    // A proxy is fatter than the mesh it wraps: joints it holds can lie
    // outside the mesh the part keeps, and show so in Blender. They move
    // into it where it has an inside nearby (autorig/BonesInside), before
    // the heat, so the weights follow the bones where they end.
    if (surface.kind == RigSurface::Kind::Proxy)
        keepJointsInMesh(
            result.part.skeleton, result.part.mesh, surface.mainPiece,
            {surface.alpha, minimum, options.bones.coverageFraction * diagonalOf(part.mesh)});
    result.part.skeleton.reorient();
    reportRigProgress(progress, kSkeletonDone);

    // Paper 2.4: no construction shortcut here, every vertex is tested for
    // the bones it sees from inside.
    const BoneHeatSolver solver(surface.mesh, result.part.boneSegments(), {}, options.heat);
    const WeightsById surfaceWeights =
        weightsById(result.part.skeleton, solver.solveAll()).perVertex;
    result.verticesWithoutVisibleBone = solver.verticesWithoutVisibleBone();
    reportRigProgress(progress, kHeatDone);

    result.part.weights.perVertex = weightsOfInput(part.mesh, surface, surfaceWeights);
    // Limbs the proxy fused share its heat; the mesh tells them apart.
    separateFusedLimbWeights(part.mesh, result.part.skeleton, fused, result.part.weights.perVertex);
    const std::map<BoneId, int> following = followOneBone(
        part.mesh, surface, options.floatingPieceFraction, result.part.weights.perVertex);
    for (const auto& [bone, count] : following)
        result.floatingPieces += count;
    result.repairs = std::move(surface.notes);
    if (repeating > 0 &&
        std::none_of(result.repairs.begin(), result.repairs.end(),
                     [](const Message& m) { return m.id == MessageId::AutoRigRepairDegenerate; }))
        result.repairs.push_back(
            {MessageId::AutoRigRepairDegenerate, {messageArgument(repeating)}});
    notePieces(following, part.name, result.repairs);
    if (propsHeld > 0)
        result.repairs.push_back({MessageId::AutoRigHeldProps, {messageArgument(propsHeld)}});
    if (piecesWorn > 0)
        result.repairs.push_back({MessageId::AutoRigWornPieces, {messageArgument(piecesWorn)}});
    result.rigSurface = std::move(surface.mesh);
    result.surfaceKind = surface.kind;
    const std::vector<Message> problems = result.part.validate();
    if (!problems.empty())
        throw Error(MessageId::AutoRigSkeletonFailed, problems.front());
    reportRigProgress(progress, 1.0);
    return result;
}

}  // namespace rigmesh
