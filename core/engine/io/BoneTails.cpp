#include "io/BoneTails.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

#include "autorig/SurfaceProbe.h"

namespace rigmesh {
namespace {

// Two points closer than this fraction of the size are one place (files
// store 32-bit floats; a head comes from inverting a rotated bind matrix).
constexpr double kSamePlace = 1e-5;
// A child lies on a bone's axis when its offset leaves the axis by at most
// this fraction of the offset's length (32-bit frames: ~1e-7).
constexpr double kOnAxis = 1e-3;
// The share of bones with children that must have one on the file's axis.
constexpr double kAxisShare = 0.75;
// Where along its line a bone's led vertices end: this quantile of their
// distances along it.
constexpr double kVertexReach = 0.9;
// How far inside a guessed tail that left the surface is put back (times the
// size): as io/ExportRig's kPullInside, ten times the step
// check_tails_inside_in_blender.py takes past a hit, far below what a rigger
// sees.
constexpr double kPullInside = 1e-4;

Vec3 signedAxis(const Eigen::Matrix3d& axes, int axis) {
    const Vec3 column = axes.col(axis / 2);
    return axis % 2 == 0 ? column : Vec3(-column);
}

bool onAxis(const Vec3& offset, const Vec3& axis, double tolerance) {
    const double along = offset.dot(axis);
    return along > tolerance && (offset - along * axis).norm() <= kOnAxis * along + tolerance;
}

// The signed axis along which most bones with children have one, if at
// least kAxisShare of them do; else -1.
int fileBoneAxis(const std::vector<TailBone>& bones, const std::vector<std::vector<int>>& children,
                 double tolerance) {
    std::array<int, 6> count{};
    int withChildren = 0;
    for (std::size_t b = 0; b < bones.size(); ++b) {
        bool any = false;
        std::array<bool, 6> has{};
        for (int c : children[b]) {
            const Vec3 offset = bones[static_cast<std::size_t>(c)].head - bones[b].head;
            if (offset.norm() <= tolerance)
                continue;
            any = true;
            for (int axis = 0; axis < 6; ++axis)
                has[axis] = has[axis] || onAxis(offset, signedAxis(bones[b].axes, axis), tolerance);
        }
        withChildren += any ? 1 : 0;
        for (int axis = 0; axis < 6; ++axis)
            count[axis] += has[axis] ? 1 : 0;
    }
    const int best = static_cast<int>(std::max_element(count.begin(), count.end()) - count.begin());
    return withChildren > 0 && count[best] >= kAxisShare * withChildren ? best : -1;
}

// The quantile kVertexReach of how far along `direction` from `head` the
// vertices led by bone `b` lie (those ahead of the head only); 0 if none.
double vertexReach(int b, const Vec3& head, const Vec3& direction,
                   const std::vector<Vec3>& vertices, const std::vector<int>& dominantBone) {
    std::vector<double> along;
    for (std::size_t v = 0; v < vertices.size(); ++v)
        if (dominantBone[v] == b) {
            const double d = (vertices[v] - head).dot(direction);
            if (d > 0)
                along.push_back(d);
        }
    if (along.empty())
        return 0.0;
    const auto k =
        static_cast<std::ptrdiff_t>(kVertexReach * static_cast<double>(along.size() - 1));
    std::nth_element(along.begin(), along.begin() + k, along.end());
    return along[static_cast<std::size_t>(k)];
}

// The direction toward the centroid of the vertices bone `b` leads, if they
// lie away from its head.
std::optional<Vec3> towardLedVertices(int b, const Vec3& head, const std::vector<Vec3>& vertices,
                                      const std::vector<int>& dominantBone, double tolerance) {
    Vec3 sum = Vec3::Zero();
    int count = 0;
    for (std::size_t v = 0; v < vertices.size(); ++v)
        if (dominantBone[v] == b) {
            sum += vertices[v];
            ++count;
        }
    if (count == 0)
        return std::nullopt;
    const Vec3 offset = sum / count - head;
    if (offset.norm() <= tolerance)
        return std::nullopt;
    return offset.normalized();
}

// `tail`, or, when it lies outside `surface` and `head` inside, the point
// kPullInside of the size before where the bone leaves the surface (at most
// halfway back to the head; that point if it is not inside, the crossing
// itself).
Vec3 keptInside(const Vec3& head, const Vec3& tail, const SurfaceProbe& surface, double size) {
    if (surface.inside(tail) || !surface.inside(head))
        return tail;
    // Inside, within 1e-9 of the bone's length of the surface.
    const Vec3 leaves = surface.entry(tail, head);
    const double reach = (leaves - head).norm();
    const Vec3 pulled =
        head + std::max(reach - kPullInside * size, 0.5 * reach) * (tail - head).normalized();
    return surface.inside(pulled) ? pulled : leaves;
}

}  // namespace

BoneTailsResult guessBoneTails(const std::vector<TailBone>& bones, const TriMesh& mesh,
                               const std::vector<int>& dominantBone, double size) {
    const std::vector<Vec3>& vertices = mesh.vertices;
    // Built on the first guess that needs it (an AABB tree of the faces).
    std::unique_ptr<SurfaceProbe> surface;
    const double tolerance = kSamePlace * size;
    const int n = static_cast<int>(bones.size());
    std::vector<std::vector<int>> children(bones.size());
    for (int b = 0; b < n; ++b)
        if (bones[static_cast<std::size_t>(b)].parent >= 0)
            children[static_cast<std::size_t>(bones[static_cast<std::size_t>(b)].parent)].push_back(
                b);

    BoneTailsResult result;
    result.boneAxis = fileBoneAxis(bones, children, tolerance);
    result.tails.resize(bones.size());
    result.connected.assign(bones.size(), false);
    for (int b = 0; b < n; ++b) {
        const TailBone& bone = bones[static_cast<std::size_t>(b)];
        auto headOf = [&](int c) { return bones[static_cast<std::size_t>(c)].head; };
        // Children the file does not flag as disconnected, away from the head.
        std::vector<int> candidates;
        std::optional<int> flagged;
        for (int c : children[static_cast<std::size_t>(b)]) {
            const std::optional<bool> flag = bones[static_cast<std::size_t>(c)].connectFlag;
            if ((headOf(c) - bone.head).norm() <= tolerance || (flag && !*flag))
                continue;
            candidates.push_back(c);
            if (flag && *flag && !flagged)
                flagged = c;
        }
        std::optional<Vec3> tail;
        if (flagged) {
            tail = headOf(*flagged);
        } else if (bone.statedTail && (*bone.statedTail - bone.head).norm() > tolerance) {
            tail = bone.statedTail;
        } else if (result.boneAxis >= 0) {
            const Vec3 axis = signedAxis(bone.axes, result.boneAxis);
            for (int c : candidates)
                if (onAxis(headOf(c) - bone.head, axis, tolerance) &&
                    (!tail || (headOf(c) - bone.head).norm() < (*tail - bone.head).norm()))
                    tail = headOf(c);
        } else if (!candidates.empty()) {
            // The child best in line with all of them.
            Vec3 mean = Vec3::Zero();
            for (int c : candidates)
                mean += (headOf(c) - bone.head).normalized();
            int best = candidates.front();
            for (int c : candidates)
                if ((headOf(c) - bone.head).normalized().dot(mean) >
                    (headOf(best) - bone.head).normalized().dot(mean))
                    best = c;
            tail = headOf(best);
        }
        if (!tail) {
            const Vec3 up = bone.parent >= 0 ? Vec3(bone.head - headOf(bone.parent)) : Vec3::Zero();
            Vec3 direction = bone.axes.col(1);
            if (result.boneAxis >= 0)
                direction = signedAxis(bone.axes, result.boneAxis);
            else if (const auto toward =
                         towardLedVertices(b, bone.head, vertices, dominantBone, tolerance))
                direction = *toward;
            else if (bone.parent >= 0 && up.norm() > tolerance)
                direction = up.normalized();
            double length = vertexReach(b, bone.head, direction, vertices, dominantBone);
            if (length <= tolerance)
                for (int c : candidates)
                    if (length <= tolerance || (headOf(c) - bone.head).norm() < length)
                        length = (headOf(c) - bone.head).norm();
            if (length <= tolerance && bone.parent >= 0)
                length = (result.tails[static_cast<std::size_t>(bone.parent)] - headOf(bone.parent))
                             .norm();
            if (length <= tolerance)
                length = 0.1 * size;
            tail = bone.head + length * direction;
            if (!mesh.faces.empty()) {
                if (!surface)
                    surface = std::make_unique<SurfaceProbe>(mesh);
                if (const Vec3 inside = keptInside(bone.head, *tail, *surface, size);
                    (inside - bone.head).norm() > tolerance)
                    tail = inside;
            }
        }
        result.tails[static_cast<std::size_t>(b)] = *tail;
        for (int c : children[static_cast<std::size_t>(b)]) {
            const std::optional<bool> flag = bones[static_cast<std::size_t>(c)].connectFlag;
            result.connected[static_cast<std::size_t>(c)] =
                flag ? *flag && (headOf(c) - *tail).norm() <= tolerance
                     : (headOf(c) - *tail).norm() <= tolerance;
        }
    }
    return result;
}

}  // namespace rigmesh
