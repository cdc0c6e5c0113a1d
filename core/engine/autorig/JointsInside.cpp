#include "autorig/JointsInside.h"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

namespace rigmesh {

namespace {

bool inside(const TriMesh& mesh, const Vec3& p) {
    return windingNumber(mesh, p) > 0.5;
}

}  // namespace

double windingNumber(const TriMesh& mesh, const Vec3& point) {
    double sum = 0.0;
    for (const auto& face : mesh.faces) {
        // Van Oosterom and Strackee 1983: the solid angle of one triangle.
        const Vec3 a = mesh.vertices[face[0]] - point;
        const Vec3 b = mesh.vertices[face[1]] - point;
        const Vec3 c = mesh.vertices[face[2]] - point;
        const double la = a.norm(), lb = b.norm(), lc = c.norm();
        const double numerator = a.dot(b.cross(c));
        const double denominator = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
        sum += 2.0 * std::atan2(numerator, denominator);
    }
    return sum / (4.0 * std::numbers::pi);
}

int pullJointsInside(Skeleton& skeleton, const TriMesh& mesh,
                     const std::function<double(JointId)>& margin) {
    int moved = 0;
    for (const Joint& joint : std::vector<Joint>(skeleton.joints())) {
        if (inside(mesh, joint.position))
            continue;
        // Towards the nearest neighbouring joint that is inside.
        const Vec3* anchor = nullptr;
        double nearest = INFINITY;
        for (BoneId bone : skeleton.bonesAt(joint.id)) {
            const Bone& b = skeleton.bone(bone);
            const Joint& other = skeleton.joint(b.head == joint.id ? b.tail : b.head);
            const double distance = (other.position - joint.position).norm();
            if (distance < nearest && inside(mesh, other.position)) {
                nearest = distance;
                anchor = &skeleton.joint(other.id).position;
            }
        }
        if (!anchor)
            continue;
        // Bisect for where the segment enters the surface.
        const Vec3 from = joint.position, to = *anchor;
        double outsideT = 0.0, insideT = 1.0;
        for (int step = 0; step < 30; ++step) {
            const double t = 0.5 * (outsideT + insideT);
            (inside(mesh, from + t * (to - from)) ? insideT : outsideT) = t;
        }
        const double length = (to - from).norm();
        const double depth = std::min(margin(joint.id), 0.5 * (1.0 - insideT) * length);
        const double t = length > 0.0 ? insideT + depth / length : insideT;
        skeleton.setJointPosition(joint.id, from + t * (to - from));
        ++moved;
    }
    return moved;
}

}  // namespace rigmesh
