#include "autorig/AxisChain.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "autorig/JointsInside.h"
#include "base/Error.h"
#include "geometry/PrincipalAxes.h"
#include "rig/BoneSegment.h"

namespace rigmesh {

Skeleton mainAxisChain(const TriMesh& mesh) {
    const int n = mesh.vertexCount();
    if (n < 4)
        throw Error(MessageId::AutoRigTooFewVertices);
    const PrincipalAxes principal = principalAxesOf(mesh.vertices);
    const Vec3& centroid = principal.centroid;
    // The largest eigenvalue's.
    const Vec3 axis = principal.scatter.eigenvectors().col(2).normalized();
    std::vector<double> along(n);
    double radiusSum = 0.0;
    for (int v = 0; v < n; ++v) {
        along[v] = (mesh.vertices[v] - centroid).dot(axis);
        radiusSum += (mesh.vertices[v] - centroid - along[v] * axis).norm();
    }
    std::vector<double> sorted = along;
    std::sort(sorted.begin(), sorted.end());
    const double low = sorted[n / 20], high = sorted[n - 1 - n / 20];
    const double radius = radiusSum / n;
    if (!(high - low > 0.0))
        throw Error(MessageId::AutoRigNoExtent);
    const int bones =
        std::clamp(static_cast<int>(std::lround((high - low) / (2.0 * radius))), 1, 4);
    Skeleton skeleton;
    JointId previous = skeleton.addJoint(centroid + low * axis);
    for (int b = 1; b <= bones; ++b) {
        const JointId next = skeleton.addJoint(centroid + (low + (high - low) * b / bones) * axis);
        skeleton.addBone(previous, next);
        previous = next;
    }
    pullJointsInside(skeleton, mesh, [&](JointId) { return 0.5 * radius; });
    skeleton.setRoot(chooseCentralRoot(skeleton));
    skeleton.reorient();
    return skeleton;
}

double farthestFromBones(const TriMesh& mesh, const Skeleton& skeleton) {
    std::vector<BoneSegment> segments;
    for (const Bone& bone : skeleton.bones())
        segments.push_back(
            {skeleton.joint(bone.head).position, skeleton.joint(bone.tail).position});
    double farthest = 0.0;
    for (const Vec3& v : mesh.vertices) {
        double nearest = std::numeric_limits<double>::infinity();
        for (const BoneSegment& segment : segments)
            nearest = std::min(nearest, pointSegmentDistance(v, segment));
        farthest = std::max(farthest, nearest);
    }
    return farthest;
}

}  // namespace rigmesh
