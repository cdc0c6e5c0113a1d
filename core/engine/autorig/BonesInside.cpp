#include "autorig/BonesInside.h"

#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

#include "autorig/SurfaceProbe.h"

namespace rigmesh {

namespace {

// Rounds of moving and splitting: each split's halves are checked again.
constexpr int kRounds = 6;
// Points tested along a bone, its joints included (as the tests count).
constexpr int kSamples = 8;
// A tip outside slides along its bone past where it enters the surface by
// this fraction of the way to the joint it hangs from.
constexpr double kTipDepth = 0.15;

Vec3 otherEnd(const Skeleton& skeleton, BoneId bone, JointId joint) {
    const Bone& b = skeleton.bone(bone);
    return skeleton.joint(b.head == joint ? b.tail : b.head).position;
}

// The direction of the limb at a joint: the mean of its bones' directions
// (each pointing the same way along the limb).
Vec3 limbDirection(const Skeleton& skeleton, JointId joint) {
    const Vec3 here = skeleton.joint(joint).position;
    Vec3 sum = Vec3::Zero();
    for (BoneId bone : skeleton.bonesAt(joint)) {
        Vec3 d = otherEnd(skeleton, bone, joint) - here;
        if (d.norm() == 0.0)
            continue;
        d.normalize();
        if (sum.norm() > 0.0 && sum.dot(d) < 0.0)
            d = -d;
        sum += d;
    }
    return sum.norm() > 0.0 ? sum.normalized() : Vec3::UnitZ();
}

// A joint outside: a tip slides along its bone into the surface, and every
// joint then goes to the middle of its cross-section.
bool moveJointInside(Skeleton& skeleton, JointId joint, const SurfaceProbe& surface) {
    Vec3 p = skeleton.joint(joint).position;
    const std::vector<BoneId> bones = skeleton.bonesAt(joint);
    if (bones.size() == 1) {
        const Vec3 anchor = otherEnd(skeleton, bones.front(), joint);
        if (surface.inside(anchor)) {
            const Vec3 in = surface.entry(p, anchor);
            p = in + kTipDepth * (anchor - in);
        }
    }
    const std::optional<Vec3> middle =
        surface.middleOfCrossSection(p, limbDirection(skeleton, joint));
    if (!middle)
        return false;
    skeleton.setJointPosition(joint, *middle);
    return true;
}

// The bone's points outside, as fractions along it, farthest from the
// surface first.
std::vector<double> outsideFarthestFirst(const Skeleton& skeleton, BoneId bone,
                                         const SurfaceProbe& surface) {
    const Vec3 head = skeleton.joint(skeleton.bone(bone).head).position;
    const Vec3 tail = skeleton.joint(skeleton.bone(bone).tail).position;
    std::vector<std::pair<double, double>> outside;  // (-distance, t)
    for (int i = 1; i < kSamples; ++i) {
        const double t = static_cast<double>(i) / kSamples;
        const Vec3 p = head + t * (tail - head);
        if (!surface.inside(p))
            outside.emplace_back(-surface.distance(p), t);
    }
    std::sort(outside.begin(), outside.end());
    std::vector<double> result;
    for (const auto& [negative, t] : outside)
        result.push_back(t);
    return result;
}

int pointsOutside(const Skeleton& skeleton, const SurfaceProbe& surface) {
    int outside = 0;
    for (const Bone& bone : skeleton.bones()) {
        const Vec3 head = skeleton.joint(bone.head).position;
        const Vec3 tail = skeleton.joint(bone.tail).position;
        for (int i = 0; i <= kSamples; ++i)
            outside += surface.inside(head + (tail - head) * (i / double(kSamples))) ? 0 : 1;
    }
    return outside;
}

}  // namespace

BonesInsideReport keepBonesInside(Skeleton& skeleton, const TriMesh& surfaceMesh,
                                  double minimumBone) {
    BonesInsideReport report;
    if (surfaceMesh.faces.empty() || skeleton.boneCount() == 0)
        return report;
    const SurfaceProbe surface(surfaceMesh);
    for (int round = 0; round < kRounds; ++round) {
        bool changed = false;
        for (const Joint& joint : std::vector<Joint>(skeleton.joints()))
            if (!surface.inside(joint.position) && moveJointInside(skeleton, joint.id, surface)) {
                ++report.jointsMoved;
                changed = true;
            }
        for (const Bone& bone : std::vector<Bone>(skeleton.bones())) {
            const Vec3 head = skeleton.joint(bone.head).position;
            const Vec3 tail = skeleton.joint(bone.tail).position;
            // The first point outside, farthest first, that gives a joint.
            for (double t : outsideFarthestFirst(skeleton, bone.id, surface)) {
                const std::optional<Vec3> middle =
                    surface.middleOfCrossSection(head + t * (tail - head), tail - head);
                if (!middle || (*middle - head).norm() < minimumBone ||
                    (*middle - tail).norm() < minimumBone)
                    continue;
                skeleton.splitBone(bone.id, *middle);
                ++report.bonesSplit;
                changed = true;
                break;
            }
        }
        if (!changed)
            break;
    }
    report.pointsOutside = pointsOutside(skeleton, surface);
    return report;
}

}  // namespace rigmesh
