#include "pipeline/SketchToPart.h"

#include <algorithm>
#include <chrono>
#include <limits>

namespace rigmesh {
namespace {

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

}  // namespace

ClosestBones closestBonesFromConstruction(const SketchSurface& surface,
                                          const std::vector<CylinderSections>& cylinders,
                                          const PartSkeleton& rig) {
    constexpr double kTieTolerance = 1e-2;  // relative, as in the bone heat solver
    const Skeleton& skeleton = rig.skeleton;
    ClosestBones closest(surface.mesh.vertices.size());
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
        auto distanceTo = [&](BoneId id) {
            const Bone& bone = skeleton.bone(id);
            return pointSegmentDistance(p, BoneSegment{skeleton.joint(bone.head).position,
                                                       skeleton.joint(bone.tail).position});
        };
        std::vector<BoneId> owners;
        for (BoneId id : bonesOfSection(rig, origin.region, section, count))
            if (skeleton.hasBone(id))
                owners.push_back(id);
        if (owners.empty())
            continue;
        double best = std::numeric_limits<double>::infinity();
        for (BoneId id : owners)
            best = std::min(best, distanceTo(id));
        // Near a joint a neighbouring bone (across the joint, or across a
        // junction: up to two joints away) may be closer than the section's
        // own: then the shortcut does not hold and the vertex is left to the
        // visibility test.
        std::vector<JointId> nearJoints;
        for (BoneId id : owners)
            for (JointId joint : {skeleton.bone(id).head, skeleton.bone(id).tail})
                for (BoneId other : skeleton.bonesAt(joint))
                    for (JointId end : {skeleton.bone(other).head, skeleton.bone(other).tail})
                        nearJoints.push_back(end);
        bool neighbourCloser = false;
        for (JointId joint : nearJoints)
            for (BoneId other : skeleton.bonesAt(joint))
                if (std::find(owners.begin(), owners.end(), other) == owners.end() &&
                    distanceTo(other) < best * (1 - kTieTolerance))
                    neighbourCloser = true;
        if (neighbourCloser)
            continue;
        for (BoneId id : owners) {
            const double d = distanceTo(id);
            if (d <= best * (1 + kTieTolerance))
                closest[v].emplace_back(skeleton.indexOfBone(id), d);
        }
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
    result.skeletonMilliseconds = millisecondsSince(start);

    Part& part = result.part;
    part.name = name;
    part.outline = result.surface.polygon.points;
    part.mesh = result.surface.surface.mesh;
    part.origins = result.surface.surface.origins;
    part.mirror = result.surface.surface.mirror;
    part.skeleton = result.skeleton.skeleton;

    start = std::chrono::steady_clock::now();
    part.knownClosestBones = closestBonesFromConstruction(
        result.surface.surface, result.surface.cylinders, result.skeleton);
    part.weights = computeBoneHeatWeights(part.mesh, part.boneSegments(), part.knownClosestBones,
                                          options.weights);
    result.weightsMilliseconds = millisecondsSince(start);
    result.totalMilliseconds = result.surface.milliseconds.total + result.skeletonMilliseconds +
                               result.weightsMilliseconds;
    return result;
}

}  // namespace rigmesh
