#include "rig/MirrorSymmetry.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "geometry/PrincipalAxes.h"
#include "mesh/VertexTree.h"
#include "part/Part.h"

namespace rigmesh {

Eigen::Quaterniond MirrorPlane::reflectRotation(const Eigen::Quaterniond& q) const {
    // (w, v) -> (w, -M v): the axis reflected and the angle reversed.
    const Vec3 v = -reflectDirection(q.vec());
    return Eigen::Quaterniond(q.w(), v.x(), v.y(), v.z());
}

namespace {

// The search reflects a sample of at most this many vertices.
constexpr int kSampleCount = 3000;
// Refinement rounds per candidate (pairs, then the plane refitted).
constexpr int kRefinements = 6;

// The closest point of triangle abc to p (Ericson, Real-Time Collision
// Detection, 5.1.5).
Vec3 closestOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0 && d2 <= 0)
        return a;
    const Vec3 bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0 && d4 <= d3)
        return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0)
        return a + d1 / (d1 - d3) * ab;
    const Vec3 cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0 && d5 <= d6)
        return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0)
        return a + d2 / (d2 - d6) * ac;
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
        return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
    const double denominator = 1.0 / (va + vb + vc);
    return a + ab * (vb * denominator) + ac * (vc * denominator);
}

// Distances to the surface: to the faces around the nearest vertex (or to
// the vertex when there are no faces).
class SurfaceDistance {
  public:
    explicit SurfaceDistance(const TriMesh& mesh)
        : mesh_(mesh), tree_(mesh.vertices), faces_(mesh.vertices.size()) {
        for (int f = 0; f < mesh.faceCount(); ++f)
            for (int v : mesh.faces[f])
                faces_[v].push_back(f);
    }
    struct Closest {
        int vertex = -1;  // the nearest vertex
        double distance = std::numeric_limits<double>::infinity();
        Vec3 point = Vec3::Zero();  // the closest point of the faces around it
    };
    // The nearest vertex, and the closest point of the surface there.
    Closest operator()(const Vec3& p) const {
        Closest closest;
        closest.vertex = tree_.nearest(p);
        if (closest.vertex < 0)
            return closest;
        closest.point = mesh_.vertices[closest.vertex];
        closest.distance = (closest.point - p).norm();
        for (int f : faces_[closest.vertex]) {
            const auto& face = mesh_.faces[f];
            const Vec3 q = closestOnTriangle(p, mesh_.vertices[face[0]], mesh_.vertices[face[1]],
                                             mesh_.vertices[face[2]]);
            if ((q - p).norm() < closest.distance) {
                closest.distance = (q - p).norm();
                closest.point = q;
            }
        }
        return closest;
    }

  private:
    const TriMesh& mesh_;
    VertexTree tree_;
    std::vector<std::vector<int>> faces_;
};

double diagonalOf(const std::vector<Vec3>& points) {
    Eigen::AlignedBox3d box;
    for (const Vec3& p : points)
        box.extend(p);
    return box.isEmpty() ? 0.0 : box.diagonal().norm();
}

// Every k-th vertex, at most kSampleCount of them.
std::vector<int> sampleOf(const TriMesh& mesh) {
    const int n = mesh.vertexCount();
    const int stride = std::max(1, n / kSampleCount);
    std::vector<int> sample;
    for (int v = 0; v < n; v += stride)
        sample.push_back(v);
    return sample;
}

double meanError(const TriMesh& mesh, const SurfaceDistance& distance,
                 const std::vector<int>& sample, const MirrorPlane& plane, double diagonal) {
    double sum = 0.0;
    for (int v : sample)
        sum += distance(plane.reflect(mesh.vertices[v])).distance;
    return sample.empty() || diagonal <= 0.0 ? 0.0 : sum / sample.size() / diagonal;
}

Vec3 keepContaining(Vec3 normal, const std::optional<Vec3>& axis) {
    if (axis) {
        const Vec3 a = axis->normalized();
        normal -= a * a.dot(normal);
    }
    return normal;
}

// ICP on the reflection: each sampled vertex paired with the surface point
// closest to its reflection; the new normal is the main direction of the
// pairs' differences, the new point their midpoints' mean.
MirrorPlane refine(const TriMesh& mesh, const SurfaceDistance& distance,
                   const std::vector<int>& sample, MirrorPlane plane,
                   const std::optional<Vec3>& containing) {
    for (int round = 0; round < kRefinements; ++round) {
        Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
        Vec3 midpoints = Vec3::Zero();
        int count = 0;
        for (int v : sample) {
            const Vec3& p = mesh.vertices[v];
            // The partner is the surface point closest to p's reflection:
            // the nearest vertex would tilt the plane wherever the two
            // sides are sampled differently.
            const auto closest = distance(plane.reflect(p));
            if (closest.vertex < 0)
                continue;
            const Vec3& q = closest.point;
            const Vec3 d = keepContaining(p - q, containing);
            scatter += d * d.transpose();
            midpoints += 0.5 * (p + q);
            ++count;
        }
        if (count == 0)
            break;
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(scatter);
        Vec3 normal = keepContaining(eigen.eigenvectors().col(2), containing);
        if (!(normal.norm() > 0.0))
            break;
        normal.normalize();
        if (normal.dot(plane.normal) < 0.0)
            normal = -normal;
        plane.normal = normal;
        plane.point = midpoints / count;
    }
    return plane;
}

}  // namespace

double mirrorError(const TriMesh& mesh, const MirrorPlane& plane) {
    const double diagonal = diagonalOf(mesh.vertices);
    const SurfaceDistance distance(mesh);
    std::vector<int> all(mesh.vertexCount());
    for (int v = 0; v < mesh.vertexCount(); ++v)
        all[v] = v;
    return meanError(mesh, distance, all, plane, diagonal);
}

std::optional<MirrorFit> findMirrorPlane(const TriMesh& mesh, const MirrorSearch& search) {
    if (mesh.vertexCount() < 4)
        return std::nullopt;
    const double diagonal = diagonalOf(mesh.vertices);
    if (!(diagonal > 0.0))
        return std::nullopt;
    const PrincipalAxes principal = principalAxesOf(mesh.vertices);
    const Vec3& centroid = principal.centroid;
    const auto& pca = principal.scatter;

    const SurfaceDistance distance(mesh);
    const std::vector<int> sample = sampleOf(mesh);
    std::vector<Vec3> candidates;
    for (int k = 0; k < 3; ++k) {
        candidates.push_back(pca.eigenvectors().col(k));
        candidates.push_back(Vec3::Unit(k));
    }
    std::optional<MirrorFit> best;
    for (Vec3 normal : candidates) {
        normal = keepContaining(normal, search.containing);
        if (normal.norm() < 0.5)
            continue;  // (nearly) the contained axis itself
        MirrorPlane plane{centroid, normal.normalized()};
        plane = refine(mesh, distance, sample, plane, search.containing);
        const double error = meanError(mesh, distance, sample, plane, diagonal);
        if (error <= search.tolerance && (!best || error < best->error))
            best = MirrorFit{plane, error};
    }
    return best;
}

double mirrorJointTolerance(const Skeleton& skeleton, const MirrorFit& fit, double diagonal) {
    double meanBone = 0.0;
    for (const Bone& bone : skeleton.bones())
        meanBone += skeleton.boneLength(bone.id);
    meanBone /= std::max(1, skeleton.boneCount());
    return std::max(0.25 * meanBone, 4.0 * fit.error * diagonal);
}

std::map<JointId, JointId> mirrorJoints(const Skeleton& skeleton, const MirrorPlane& plane,
                                        double tolerance) {
    auto nearestTo = [&](const Vec3& p) {
        JointId best = kNoJoint;
        double bestDistance = std::numeric_limits<double>::infinity();
        for (const Joint& joint : skeleton.joints()) {
            const double d = (joint.position - p).norm();
            if (d < bestDistance) {
                bestDistance = d;
                best = joint.id;
            }
        }
        return std::pair{best, bestDistance};
    };
    std::map<JointId, JointId> images;
    for (const Joint& joint : skeleton.joints()) {
        const auto [image, d] = nearestTo(plane.reflect(joint.position));
        if (image == kNoJoint || d > tolerance)
            continue;
        const JointId back = nearestTo(plane.reflect(skeleton.joint(image).position)).first;
        if (back == joint.id)
            images[joint.id] = image;
    }
    return images;
}

std::map<BoneId, BoneId> mirrorBones(const Skeleton& skeleton,
                                     const std::map<JointId, JointId>& joints) {
    std::map<std::pair<JointId, JointId>, BoneId> byJoints;
    for (const Bone& bone : skeleton.bones()) {
        byJoints[{bone.head, bone.tail}] = bone.id;
        byJoints[{bone.tail, bone.head}] = bone.id;
    }
    std::map<BoneId, BoneId> images;
    for (const Bone& bone : skeleton.bones()) {
        auto head = joints.find(bone.head), tail = joints.find(bone.tail);
        BoneId image = bone.id;
        if (head != joints.end() && tail != joints.end()) {
            auto found = byJoints.find({head->second, tail->second});
            if (found != byJoints.end())
                image = found->second;
        }
        images[bone.id] = image;
    }
    return images;
}

TriMesh outlinePoints(const std::vector<Vec2>& outline) {
    TriMesh points;
    for (const Vec2& p : outline)
        points.vertices.emplace_back(p.x(), p.y(), 0.0);
    // Each segment as a degenerate triangle (a, b, b): distances are then to
    // the closed polyline, not to its points, whose spacing differs from
    // side to side.
    const int n = static_cast<int>(outline.size());
    if (n >= 3)
        for (int i = 0; i < n; ++i)
            points.faces.push_back({i, (i + 1) % n, (i + 1) % n});
    return points;
}

std::optional<PartSymmetry> findPartSymmetry(const Part& part) {
    std::optional<MirrorFit> fit;
    if (!part.outline.empty()) {
        // A sketched part: the mirror of its outline (left and right of the
        // sketch). Its surface is also mirrored through the sketch plane
        // z = 0 (Part::mirror), but that is front and back, never what
        // X-mirror means: an outline without a mirror has none.
        MirrorSearch search;
        search.containing = Vec3::UnitZ();
        fit = findMirrorPlane(outlinePoints(part.outline), search);
    } else {
        fit = findMirrorPlane(part.mesh);
    }
    if (!fit)
        return std::nullopt;
    PartSymmetry symmetry;
    symmetry.plane = fit->plane;
    symmetry.joints =
        mirrorJoints(part.skeleton, symmetry.plane,
                     mirrorJointTolerance(part.skeleton, *fit, diagonalOf(part.mesh.vertices)));
    symmetry.bones = mirrorBones(part.skeleton, symmetry.joints);
    return symmetry;
}

}  // namespace rigmesh
