#include "autorig/BoneCoverage.h"

#include <algorithm>
#include <limits>
#include <optional>

#include "autorig/SkeletonFromCurve.h"
#include "autorig/SurfaceProbe.h"
#include "rig/BoneSegment.h"

namespace rigmesh {

namespace {

// At most this many bones added or bent.
constexpr int kMaxSteps = 12;
// Points tested along a bone for being inside.
constexpr int kSamples = 8;
// A new joint for a far point sits this fraction of the way back from the
// point towards the bone, then in the middle of the cross-section there.
constexpr double kTipDepth = 0.2;
// Far points tried per step before giving up (each try casts rays).
constexpr std::size_t kTriesPerStep = 40;
// Bones tried for a bend, bone points tried as a new branch's start.
constexpr std::size_t kBonesTried = 6;
constexpr std::size_t kAnchorsTried = 12;
// A bend brings the far point this fraction of the limit near a bone.
constexpr double kMargin = 0.9;
// A bone point this close to an end (as a fraction) is that end.
constexpr double kAtEnd = 0.1;

struct Nearest {
    BoneId bone = 0;
    double t = 0.0;
    double distance = std::numeric_limits<double>::infinity();
};

Nearest nearestBone(const Skeleton& skeleton, const Vec3& p) {
    Nearest best;
    for (const Bone& bone : skeleton.bones()) {
        const BoneSegment segment{skeleton.joint(bone.head).position,
                                  skeleton.joint(bone.tail).position};
        const double d = pointSegmentDistance(p, segment);
        if (d < best.distance) {
            const Vec3 axis = segment.tail - segment.head;
            const double length2 = axis.squaredNorm();
            best = {
                bone.id,
                length2 > 0.0 ? std::clamp((p - segment.head).dot(axis) / length2, 0.0, 1.0) : 0.0,
                d};
        }
    }
    return best;
}

bool segmentInside(const SurfaceProbe& surface, const Vec3& a, const Vec3& b) {
    for (int i = 0; i <= kSamples; ++i)
        if (!surface.inside(a + (b - a) * (static_cast<double>(i) / kSamples)))
            return false;
    return true;
}

// The points farther than `limit` from every bone, farthest first.
std::vector<int> uncovered(const Skeleton& skeleton, const std::vector<Vec3>& points, double limit,
                           double& farthest) {
    std::vector<std::pair<double, int>> far;
    farthest = 0.0;
    for (int i = 0; i < static_cast<int>(points.size()); ++i) {
        const double d = nearestBone(skeleton, points[i]).distance;
        farthest = std::max(farthest, d);
        if (d > limit)
            far.emplace_back(-d, i);
    }
    std::sort(far.begin(), far.end());
    std::vector<int> result;
    for (const auto& [negative, i] : far)
        result.push_back(i);
    return result;
}

// Where a joint for the far point goes: back from it towards the bone,
// in the middle of the cross-section there.
std::optional<Vec3> jointFor(const SurfaceProbe& surface, const Vec3& far, const Vec3& onBone) {
    const Vec3 p = far + kTipDepth * (onBone - far);
    const std::optional<Vec3> middle = surface.middleOfCrossSection(p, far - onBone);
    if (middle)
        return middle;
    if (surface.inside(p))
        return p;
    return std::nullopt;
}

// The bones nearest to `p` first, each with its point nearest to `p`.
std::vector<Nearest> bonesByDistance(const Skeleton& skeleton, const Vec3& p) {
    std::vector<Nearest> all;
    for (const Bone& bone : skeleton.bones()) {
        const Vec3 head = skeleton.joint(bone.head).position;
        const Vec3 axis = skeleton.joint(bone.tail).position - head;
        const double length2 = axis.squaredNorm();
        const double t = length2 > 0.0 ? std::clamp((p - head).dot(axis) / length2, 0.0, 1.0) : 0.0;
        all.push_back({bone.id, t, (head + t * axis - p).norm()});
    }
    std::sort(all.begin(), all.end(),
              [](const Nearest& a, const Nearest& b) { return a.distance < b.distance; });
    return all;
}

// Bend: a joint inserted on one of the nearest bones (away from its ends)
// and moved towards the far point, as little as covers it, both halves
// inside and no shorter than the minimum bone.
bool bend(Skeleton& skeleton, const SurfaceProbe& surface, const Vec3& far, double limit,
          double minimumBone) {
    const std::vector<Nearest> nearest = bonesByDistance(skeleton, far);
    for (std::size_t k = 0; k < nearest.size() && k < kBonesTried; ++k) {
        const Bone bone = skeleton.bone(nearest[k].bone);
        const Vec3 head = skeleton.joint(bone.head).position;
        const Vec3 tail = skeleton.joint(bone.tail).position;
        const double t = std::clamp(nearest[k].t, kAtEnd, 1.0 - kAtEnd);
        const Vec3 onBone = head + t * (tail - head);
        // Towards the middle of the region's cross-section first; where
        // that lies too deep to cover the point (a hump on a thick body),
        // towards the point itself, a little inside it.
        std::vector<Vec3> targets;
        if (const std::optional<Vec3> middle = jointFor(surface, far, onBone))
            targets.push_back(*middle);
        if (const Vec3 near = far + kTipDepth * (onBone - far); surface.inside(near))
            targets.push_back(near);
        for (const Vec3& target : targets)
            for (double s : {0.5, 0.75, 1.0}) {
                const Vec3 bent = onBone + s * (target - onBone);
                if ((far - bent).norm() > limit || (bent - head).norm() < minimumBone ||
                    (bent - tail).norm() < minimumBone || !segmentInside(surface, head, bent) ||
                    !segmentInside(surface, bent, tail))
                    continue;
                skeleton.splitBone(bone.id, bent);
                return true;
            }
    }
    return false;
}

// Reach or branch: a new bone into the region from the nearest tip (which
// then reaches on) or bone point that sees the region's joint from inside.
bool grow(Skeleton& skeleton, const SurfaceProbe& surface, const Vec3& far, double minimumBone,
          BoneCoverageReport& report) {
    struct Anchor {
        double distance;
        BoneId bone;
        double t;
    };
    std::vector<Anchor> anchors;
    for (const Bone& bone : skeleton.bones()) {
        const Vec3 head = skeleton.joint(bone.head).position;
        const Vec3 tail = skeleton.joint(bone.tail).position;
        for (double t : {0.0, 0.25, 0.5, 0.75, 1.0})
            anchors.push_back({(head + t * (tail - head) - far).norm(), bone.id, t});
    }
    std::sort(anchors.begin(), anchors.end(),
              [](const Anchor& a, const Anchor& b) { return a.distance < b.distance; });
    // First a bone point that sees the region from inside; else the
    // nearest, whose new bone autorig/BonesInside then bends along the
    // shape (a wing behind a shoulder).
    const std::size_t tried = std::min(anchors.size(), kAnchorsTried);
    for (std::size_t k = 0; k < 2 * tried; ++k) {
        const bool seen = k < tried;
        const Anchor& anchor = anchors[seen ? k : k - tried];
        const Bone bone = skeleton.bone(anchor.bone);
        const Vec3 head = skeleton.joint(bone.head).position;
        const Vec3 tail = skeleton.joint(bone.tail).position;
        const Vec3 onBone = head + anchor.t * (tail - head);
        const std::optional<Vec3> target = jointFor(surface, far, onBone);
        if (!target || (*target - onBone).norm() < minimumBone ||
            (seen && !segmentInside(surface, onBone, *target)))
            continue;
        JointId from = anchor.t == 0.0 ? bone.head : bone.tail;
        if (anchor.t > 0.0 && anchor.t < 1.0) {
            if ((onBone - head).norm() < minimumBone || (onBone - tail).norm() < minimumBone)
                continue;
            from = skeleton.splitBone(bone.id, onBone);
        }
        ++(skeleton.degree(from) == 1 ? report.reaches : report.branches);
        skeleton.addBone(from, skeleton.addJoint(*target));
        return true;
    }
    return false;
}

bool coverOne(Skeleton& skeleton, const SurfaceProbe& surface, const Vec3& far, double limit,
              double minimumBone, BoneCoverageReport& report) {
    if (bend(skeleton, surface, far, limit, minimumBone)) {
        ++report.bends;
        return true;
    }
    return grow(skeleton, surface, far, minimumBone, report);
}

}  // namespace

BoneCoverageReport coverWithBones(Skeleton& skeleton, const TriMesh& surfaceMesh,
                                  const std::vector<Vec3>& points, double limit,
                                  double minimumBone) {
    BoneCoverageReport report;
    if (skeleton.boneCount() == 0 || surfaceMesh.faces.empty())
        return report;
    // A chain stays a chain: a blob's body is rigged along its main axis
    // (autorig/AxisChain), not given branches into its sides.
    if (leafCount(skeleton) <= 2)
        return report;
    const SurfaceProbe surface(surfaceMesh);
    for (int step = 0; step < kMaxSteps; ++step) {
        bool covered = false;
        // The farthest point that a bend, a reach or a branch can cover,
        // with a margin below the limit (joints may move afterwards).
        const std::vector<int> far = uncovered(skeleton, points, limit, report.farthest);
        for (std::size_t k = 0; k < far.size() && k < kTriesPerStep; ++k)
            if ((covered = coverOne(skeleton, surface, points[far[k]], kMargin * limit, minimumBone,
                                    report)))
                break;
        if (!covered)
            break;
    }
    double farthest = 0.0;
    uncovered(skeleton, points, limit, farthest);
    report.farthest = farthest;
    return report;
}

}  // namespace rigmesh
