#include "autorig/BonesInside.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <utility>
#include <vector>

#include "autorig/SurfaceProbe.h"
#include "rig/BoneSegment.h"

namespace rigmesh {

namespace {

// Rounds of moving and splitting: each split's halves are checked again,
// until nothing changes. The spider of assimp-testmodels on wraps finer and
// coarser than the default kept 1-3 points outside after six.
constexpr int kRounds = 20;
// Points tested along a bone, its joints included (as the tests count).
constexpr int kSamples = 8;
// A tip outside slides along its bone past where it enters the surface by
// this fraction of the way to the joint it hangs from.
constexpr double kTipDepth = 0.15;
// A joint inside the mesh keeps this fraction of its size from the surface,
// far above single precision (what Blender keeps of a position).
constexpr double kClearance = 1e-4;
// Directions searched from a joint outside the mesh (a Fibonacci sphere).
constexpr int kSearchRays = 96;
// Rounds of moving joints into the mesh (a move turns its neighbours' limb).
constexpr int kMeshRounds = 3;

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

// The bones of `skeleton` as segments with `joint` at `p`.
std::vector<BoneSegment> segmentsWith(const Skeleton& skeleton, JointId joint, const Vec3& p) {
    std::vector<BoneSegment> segments;
    for (const Bone& bone : skeleton.bones())
        segments.push_back({bone.head == joint ? p : skeleton.joint(bone.head).position,
                            bone.tail == joint ? p : skeleton.joint(bone.tail).position});
    return segments;
}

// The farthest of `points` from every bone.
double farthestFromBones(const Skeleton& skeleton, const std::vector<Vec3>& points) {
    const std::vector<BoneSegment> segments = segmentsWith(skeleton, kNoJoint, Vec3::Zero());
    double farthest = 0.0;
    for (const Vec3& p : points) {
        double nearest = INFINITY;
        for (const BoneSegment& segment : segments)
            nearest = std::min(nearest, pointSegmentDistance(p, segment));
        farthest = std::max(farthest, nearest);
    }
    return farthest;
}

// The points a joint's moves must keep near a bone: each within `allowed`
// of one (the coverage limit, or the farthest point's distance when
// keepBonesInside began, if farther: autorig/BoneCoverage placed bones to
// cover them).
struct Cover {
    const std::vector<Vec3>& points;
    double allowed = 0.0;

    // With `joint` at `place`, no point that a bone at the joint covered is
    // left uncovered. Only such points can lose their cover, and only they
    // are compared with the other bones: a move costs the points times the
    // joint's bones, not times all bones (100k-vertex meshes).
    bool keptWith(const Skeleton& skeleton, JointId joint, const Vec3& place) const {
        std::vector<BoneSegment> before, after, others;
        for (const Bone& bone : skeleton.bones()) {
            const BoneSegment segment{skeleton.joint(bone.head).position,
                                      skeleton.joint(bone.tail).position};
            if (bone.head != joint && bone.tail != joint) {
                others.push_back(segment);
                continue;
            }
            before.push_back(segment);
            after.push_back({bone.head == joint ? place : segment.head,
                             bone.tail == joint ? place : segment.tail});
        }
        const auto within = [&](const Vec3& p, const std::vector<BoneSegment>& segments) {
            return std::any_of(segments.begin(), segments.end(), [&](const BoneSegment& s) {
                return pointSegmentDistance(p, s) <= allowed;
            });
        };
        return std::all_of(points.begin(), points.end(), [&](const Vec3& p) {
            return !within(p, before) || within(p, after) || within(p, others);
        });
    }
};

// A joint outside: a tip slides along its bone into the surface, and every
// joint then goes to the middle of its cross-section. In a sheet (a wing
// wrapped thin) that cross-section runs across the sheet and its middle
// can lie far from the limb: the middle is taken only when it keeps every
// point of `cover` covered, else the tip stays where it slid in.
bool moveJointInside(Skeleton& skeleton, JointId joint, const SurfaceProbe& surface,
                     const std::optional<Cover>& cover) {
    Vec3 p = skeleton.joint(joint).position;
    bool slid = false;
    const std::vector<BoneId> bones = skeleton.bonesAt(joint);
    if (bones.size() == 1) {
        const Vec3 anchor = otherEnd(skeleton, bones.front(), joint);
        if (surface.inside(anchor)) {
            const Vec3 in = surface.entry(p, anchor);
            p = in + kTipDepth * (anchor - in);
            slid = surface.inside(p);
        }
    }
    std::vector<Vec3> places;
    if (const std::optional<Vec3> middle =
            surface.middleOfCrossSection(p, limbDirection(skeleton, joint)))
        places.push_back(*middle);
    if (slid)
        places.push_back(p);
    if (cover)
        std::erase_if(places,
                      [&](const Vec3& place) { return !cover->keptWith(skeleton, joint, place); });
    if (places.empty())
        return false;
    skeleton.setJointPosition(joint, places.front());
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

// Directions evenly spread over the sphere (a Fibonacci lattice).
std::vector<Vec3> sphereDirections(int count) {
    std::vector<Vec3> directions;
    const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < count; ++i) {
        const double z = 1.0 - (2.0 * i + 1.0) / count;
        const double r = std::sqrt(1.0 - z * z);
        directions.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
    }
    return directions;
}

struct MeshJoints {
    const SurfaceProbe& mesh;
    const SurfaceProbe& surface;
    double clearance;
    double reach;
    double minimumBone;
    const std::vector<Vec3>& points;
    double coverage;

    bool inMesh(const Vec3& p) const { return mesh.inside(p) && mesh.distance(p) >= clearance; }

    // Every bone at `joint` with the joint at `p`: long enough, inside the
    // rig surface at 9 points.
    bool bonesFit(const Skeleton& skeleton, JointId joint, const Vec3& p) const {
        for (BoneId bone : skeleton.bonesAt(joint)) {
            const Vec3 other = otherEnd(skeleton, bone, joint);
            if ((other - p).norm() < minimumBone)
                return false;
            for (int i = 0; i <= kSamples; ++i)
                if (!surface.inside(p + (other - p) * (i / double(kSamples))))
                    return false;
        }
        return true;
    }

    // With the joint at `p`, every point still within `coverage` of a bone
    // (all are at the start: coverage is at least the farthest then, and
    // only joint moves that keep them so are made).
    bool keepsCovered(const Skeleton& skeleton, JointId joint, const Vec3& p) const {
        return Cover{points, coverage}.keptWith(skeleton, joint, p);
    }

    // Places inside the mesh near `p`, nearest entry first: along each
    // search ray, past every wall within the search radius, halfway to the
    // next wall (or the radius), after the middle of the cross-section there.
    std::vector<std::pair<double, Vec3>> candidates(const Skeleton& skeleton, JointId joint) const {
        const Vec3 p = skeleton.joint(joint).position;
        const double radius = 2.0 * surface.distance(p) + reach;
        const Vec3 limb = limbDirection(skeleton, joint);
        std::vector<std::pair<double, Vec3>> found;
        // The middle of the limb there first (a sketched part's joints sit
        // on its chordal axis, paper 2.1), when it lies within the half
        // chord the ray measured of `q`, else the point past the wall.
        const auto add = [&](double entry, const Vec3& q, double halfChord) {
            if (!inMesh(q))
                return;
            const std::optional<Vec3> middle = mesh.middleOfCrossSection(q, limb);
            if (middle && (*middle - q).norm() <= halfChord && inMesh(*middle))
                found.emplace_back(entry, *middle);
            found.emplace_back(entry, q);
        };
        for (const Vec3& ray : sphereDirections(kSearchRays)) {
            const std::vector<double> walls = mesh.walls(p, ray);
            for (std::size_t k = 0; k < walls.size() && walls[k] < radius; ++k) {
                const double next = k + 1 < walls.size() ? walls[k + 1] : radius;
                const double halfChord = 0.5 * (std::min(next, radius) - walls[k]);
                add(walls[k], p + ray * (walls[k] + halfChord), halfChord);
            }
        }
        // A tip slides along its bone into the mesh.
        const std::vector<BoneId> bones = skeleton.bonesAt(joint);
        if (bones.size() == 1) {
            const Vec3 anchor = otherEnd(skeleton, bones.front(), joint);
            const Vec3 along = (anchor - p).normalized();
            const std::vector<double> walls = mesh.walls(p, along);
            if (!walls.empty() && walls.front() < (anchor - p).norm()) {
                const double entry = walls.front();
                const double next =
                    std::min(walls.size() > 1 ? walls[1] : INFINITY, (anchor - p).norm());
                const double depth =
                    std::min(kTipDepth * ((anchor - p).norm() - entry), 0.5 * (next - entry));
                if (inMesh(p + along * (entry + depth)))
                    found.emplace_back(entry, p + along * (entry + depth));
            }
        }
        std::stable_sort(found.begin(), found.end(),
                         [](const auto& a, const auto& b) { return a.first < b.first; });
        return found;
    }
};

}  // namespace

BonesInsideReport keepBonesInside(Skeleton& skeleton, const TriMesh& surfaceMesh,
                                  double minimumBone, const std::vector<Vec3>& cover,
                                  double coverage) {
    BonesInsideReport report;
    if (surfaceMesh.faces.empty() || skeleton.boneCount() == 0)
        return report;
    const SurfaceProbe surface(surfaceMesh);
    std::optional<Cover> guard;
    if (!cover.empty())
        guard.emplace(Cover{cover, std::max(coverage, farthestFromBones(skeleton, cover))});
    for (int round = 0; round < kRounds; ++round) {
        bool changed = false;
        for (const Joint& joint : std::vector<Joint>(skeleton.joints()))
            if (!surface.inside(joint.position) &&
                moveJointInside(skeleton, joint.id, surface, guard)) {
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

JointsInMeshReport keepJointsInMesh(Skeleton& skeleton, const TriMesh& mesh, const TriMesh& surface,
                                    const JointsInMeshLimits& limits) {
    JointsInMeshReport report;
    if (mesh.faces.empty() || surface.faces.empty() || skeleton.boneCount() == 0)
        return report;
    const SurfaceProbe meshProbe(mesh, InsideBy::RayParity);
    const SurfaceProbe surfaceProbe(surface);
    const MeshJoints joints{meshProbe,
                            surfaceProbe,
                            kClearance * meshProbe.size(),
                            limits.reach,
                            limits.minimumBone,
                            mesh.vertices,
                            std::max(limits.coverage, farthestFromBones(skeleton, mesh.vertices))};
    for (int round = 0; round < kMeshRounds; ++round) {
        bool changed = false;
        for (const Joint& joint : std::vector<Joint>(skeleton.joints())) {
            if (joints.inMesh(joint.position))
                continue;
            for (const auto& [entry, q] : joints.candidates(skeleton, joint.id))
                if (joints.bonesFit(skeleton, joint.id, q) &&
                    joints.keepsCovered(skeleton, joint.id, q)) {
                    skeleton.setJointPosition(joint.id, q);
                    ++report.jointsMoved;
                    changed = true;
                    break;
                }
        }
        if (!changed)
            break;
    }
    for (const Joint& joint : skeleton.joints())
        report.jointsOutside += joints.inMesh(joint.position) ? 0 : 1;
    return report;
}

}  // namespace rigmesh
