#include "autorig/AutoRig.h"

#include "autorig/CurveSkeleton.h"
#include "base/Error.h"
#include "part/BoneWeights.h"
#include "rig/ShortBones.h"
#include "rig/SkeletonSymmetry.h"

namespace rigmesh {

namespace {

// The share of the progress bar each stage takes (measured: the flow is
// most of the time).
constexpr double kRepairDone = 0.05;
constexpr double kSkeletonDone = 0.75;

RigProgress stage(const RigProgress& progress, double from, double to) {
    if (!progress)
        return {};
    return [=](double fraction) { return progress(from + (to - from) * fraction); };
}

}  // namespace

AutoRigResult autoRigPart(const Part& part, const AutoRigOptions& options,
                          const RigProgress& progress) {
    if (part.skeleton.jointCount() > 0)
        throw Error(MessageId::AutoRigPartIsRigged, part.name);
    if (part.mesh.faceCount() == 0)
        throw Error(MessageId::AutoRigNoSurface, part.name);
    reportRigProgress(progress, 0.0);
    RepairedMesh repaired = repairForRigging(part.mesh, options.repair);
    reportRigProgress(progress, kRepairDone);

    const CurveSkeleton curve =
        extractCurveSkeleton(repaired.mesh, stage(progress, kRepairDone, kSkeletonDone));
    AutoRigResult result;
    result.part.name = part.name;
    result.part.mesh = std::move(repaired.mesh);
    result.part.skeleton = skeletonFromCurve(curve, result.part.mesh, options.bones);
    // A mirror-symmetric mesh gets a mirror-symmetric rig: mirrored limbs
    // get as many bones, mirrored joints (rig/SkeletonSymmetry).
    symmetrizeSkeleton(result.part.skeleton, result.part.mesh);
    // No bone shorter than the shortest an edit may make (rig/ShortBones.h):
    // such a bone joins its neighbour; a mesh with only such a bone is refused.
    const double minimum = minimumBoneLength(result.part.mesh);
    collapseShortBones(result.part.skeleton, minimum);
    if (const auto shortest = shortestBone(result.part.skeleton);
        shortest && shortest->length < minimum)
        throw Error(MessageId::AutoRigBoneTooShort, shortNumber(shortest->length),
                    shortNumber(minimum));
    reportRigProgress(progress, kSkeletonDone);

    // Paper 2.4: no construction shortcut here, every vertex is tested for
    // the bones it sees from inside.
    const BoneHeatSolver solver(result.part.mesh, result.part.boneSegments(), {}, options.heat);
    result.part.weights = weightsById(result.part.skeleton, solver.solveAll());
    result.verticesWithoutVisibleBone = solver.verticesWithoutVisibleBone();
    result.sourceVertex = std::move(repaired.sourceVertex);
    result.repairs = std::move(repaired.repairs);
    const std::vector<std::string> problems = result.part.validateSolid();
    if (!problems.empty())
        throw Error(MessageId::AutoRigSkeletonFailed, problems.front());
    reportRigProgress(progress, 1.0);
    return result;
}

}  // namespace rigmesh
