#include "rig/BoneVisibility.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <utility>

#include "base/Error.h"
#include "mesh/VertexNormals.h"

namespace rigmesh {

namespace {

// Exact predicates: a segment grazing an edge is classified consistently.
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Triangle = Kernel::Triangle_3;

Point toPoint(const Vec3& p) {
    return Point(p.x(), p.y(), p.z());
}

// How far along the segment the test starts, relative to its length, so that
// the triangles around the starting vertex are not counted as crossings.
constexpr double kStartOffset = 1e-6;

// Pinocchio's vectorInCone: the direction from the bone point to the vertex
// must lie within 60 degrees of the vertex normal.
constexpr double kConeCosine = 0.5;

}  // namespace

// A bounding volume hierarchy over the triangles: the Morton order of their
// centroids halved down to leaves of at most kLeafSize triangles.
// A segment visits the boxes its slab test cannot rule out and is tested
// against each of their triangles with the kernel's exact do_intersect, so
// the answer is exactly "some triangle meets the segment", as CGAL's
// AABB_tree gave it; this tree only costs less to build (one sort of 64-bit
// keys and one box per node from its children, where CGAL partitions the
// triangles and bounds each node's range anew at every level).
struct BoneVisibility::Tree {
    static constexpr int kLeafSize = 4;
    struct Box {
        std::array<double, 3> low{}, high{};
    };
    struct Node {
        Box box;
        // A leaf: triangles [first, first + count) of `order`. An inner node
        // (count 0): its children are the next node and node `first`.
        int first = 0;
        int count = 0;
    };
    std::vector<Triangle> triangles;
    std::vector<Box> boxes;  // per triangle
    std::vector<int> order;  // triangle indices, leaves contiguous
    std::vector<Node> nodes;
    // Added to every node's box on each side: the slab test's rounding must
    // never rule out a box the segment meets.
    double margin = 0.0;

    void build();
    int buildNode(int begin, int end);
    bool segmentMayMeet(const Box& box, const std::array<double, 3>& start,
                        const std::array<double, 3>& inverse,
                        const std::array<double, 3>& direction) const;
    bool intersects(const Kernel::Segment_3& segment, const Vec3& start, const Vec3& end) const;
};

namespace {

// Spreads the low 10 bits of `x` to every third bit.
std::uint32_t spreadBits(std::uint32_t x) {
    x &= 0x3ffu;
    x = (x | (x << 16)) & 0x030000ffu;
    x = (x | (x << 8)) & 0x0300f00fu;
    x = (x | (x << 4)) & 0x030c30c3u;
    x = (x | (x << 2)) & 0x09249249u;
    return x;
}

// Sorts keys (Morton code << 32 | index, the indices ascending) as
// std::sort would: a stable radix sort on the code's 30 bits in three passes
// of ten keeps equal codes in index order (a quarter of the time of
// std::sort on a 21k-triangle part, which was a third of building the tree).
void sortByMortonCode(std::vector<std::uint64_t>& keys) {
    constexpr int kBits = 10, kBuckets = 1 << kBits;
    std::vector<std::uint64_t> sorted(keys.size());
    std::vector<int> start(kBuckets + 1);
    for (int shift = 32; shift < 62; shift += kBits) {
        std::fill(start.begin(), start.end(), 0);
        for (std::uint64_t key : keys)
            ++start[((key >> shift) & (kBuckets - 1)) + 1];
        std::partial_sum(start.begin(), start.end(), start.begin());
        for (std::uint64_t key : keys)
            sorted[start[(key >> shift) & (kBuckets - 1)]++] = key;
        keys.swap(sorted);
    }
}

}  // namespace

void BoneVisibility::Tree::build() {
    const int count = static_cast<int>(triangles.size());
    boxes.resize(count);
    std::vector<std::array<double, 3>> centroids(count);
    std::array<double, 3> low{}, high{};
    low.fill(std::numeric_limits<double>::infinity());
    high.fill(-std::numeric_limits<double>::infinity());
    double extent = 0.0;
    for (int t = 0; t < count; ++t) {
        for (int axis = 0; axis < 3; ++axis) {
            const double a = triangles[t][0][axis];
            const double b = triangles[t][1][axis];
            const double c = triangles[t][2][axis];
            boxes[t].low[axis] = std::min({a, b, c});
            boxes[t].high[axis] = std::max({a, b, c});
            centroids[t][axis] = a + b + c;
            low[axis] = std::min(low[axis], centroids[t][axis]);
            high[axis] = std::max(high[axis], centroids[t][axis]);
            extent = std::max({extent, std::abs(a), std::abs(b), std::abs(c)});
        }
    }
    margin = 1e-9 * extent;
    // Triangles in the Morton order of their centroids (10 bits per axis),
    // the index breaking ties: nearby triangles share subtrees.
    std::vector<std::uint64_t> keys(count);
    for (int t = 0; t < count; ++t) {
        std::uint32_t code = 0;
        for (int axis = 0; axis < 3; ++axis) {
            const double span = high[axis] - low[axis];
            const double unit = span > 0.0 ? (centroids[t][axis] - low[axis]) / span : 0.0;
            const auto cell = static_cast<std::uint32_t>(std::clamp(unit * 1023.0, 0.0, 1023.0));
            code |= spreadBits(cell) << axis;
        }
        keys[t] = (static_cast<std::uint64_t>(code) << 32) | static_cast<std::uint32_t>(t);
    }
    sortByMortonCode(keys);
    order.resize(count);
    for (int i = 0; i < count; ++i) {
        order[i] = static_cast<int>(keys[i] & 0xffffffffu);
    }
    nodes.clear();
    nodes.reserve(2 * (count / kLeafSize + 1));
    nodes.emplace_back();
    if (count > 0) {
        buildNode(0, count);
    }
}

// Fills the node at the back of `nodes` with triangles order[begin, end):
// halves of the Morton order down to leaves of kLeafSize; a box holds its
// children's.
int BoneVisibility::Tree::buildNode(int begin, int end) {
    const int self = static_cast<int>(nodes.size()) - 1;
    if (end - begin <= kLeafSize) {
        Box box = boxes[order[begin]];
        for (int i = begin + 1; i < end; ++i) {
            const Box& b = boxes[order[i]];
            for (int axis = 0; axis < 3; ++axis) {
                box.low[axis] = std::min(box.low[axis], b.low[axis]);
                box.high[axis] = std::max(box.high[axis], b.high[axis]);
            }
        }
        for (int axis = 0; axis < 3; ++axis) {
            box.low[axis] -= margin;
            box.high[axis] += margin;
        }
        nodes[self].box = box;
        nodes[self].first = begin;
        nodes[self].count = end - begin;
        return self;
    }
    const int middle = begin + (end - begin) / 2;
    nodes.emplace_back();
    buildNode(begin, middle);
    const int second = static_cast<int>(nodes.size());
    nodes.emplace_back();
    buildNode(middle, end);
    Box box = nodes[self + 1].box;
    const Box& other = nodes[second].box;
    for (int axis = 0; axis < 3; ++axis) {
        box.low[axis] = std::min(box.low[axis], other.low[axis]);
        box.high[axis] = std::max(box.high[axis], other.high[axis]);
    }
    nodes[self].box = box;
    nodes[self].first = second;
    return self;
}

// The slab test of the segment start + s * direction, s in [0, 1], against
// `box` (already widened by `margin`).
bool BoneVisibility::Tree::segmentMayMeet(const Box& box, const std::array<double, 3>& start,
                                          const std::array<double, 3>& inverse,
                                          const std::array<double, 3>& direction) const {
    double enter = 0.0, leave = 1.0;
    for (int axis = 0; axis < 3; ++axis) {
        if (direction[axis] == 0.0) {
            if (start[axis] < box.low[axis] || start[axis] > box.high[axis]) {
                return false;
            }
            continue;
        }
        double a = (box.low[axis] - start[axis]) * inverse[axis];
        double b = (box.high[axis] - start[axis]) * inverse[axis];
        if (a > b) {
            std::swap(a, b);
        }
        enter = std::max(enter, a);
        leave = std::min(leave, b);
        if (enter > leave) {
            return false;
        }
    }
    return true;
}

bool BoneVisibility::Tree::intersects(const Kernel::Segment_3& segment, const Vec3& start,
                                      const Vec3& end) const {
    if (triangles.empty()) {
        return false;
    }
    const std::array<double, 3> origin{start.x(), start.y(), start.z()};
    std::array<double, 3> direction{}, inverse{};
    for (int axis = 0; axis < 3; ++axis) {
        direction[axis] = end[axis] - start[axis];
        inverse[axis] = direction[axis] == 0.0 ? 0.0 : 1.0 / direction[axis];
    }
    std::vector<int> stack;
    stack.reserve(64);
    stack.push_back(0);
    while (!stack.empty()) {
        const Node& node = nodes[stack.back()];
        const int index = stack.back();
        stack.pop_back();
        if (!segmentMayMeet(node.box, origin, inverse, direction)) {
            continue;
        }
        if (node.count == 0) {
            stack.push_back(node.first);
            stack.push_back(index + 1);
            continue;
        }
        for (int i = node.first; i < node.first + node.count; ++i) {
            if (CGAL::do_intersect(segment, triangles[order[i]])) {
                return true;
            }
        }
    }
    return false;
}

BoneVisibility::BoneVisibility(const TriMesh& mesh) : tree_(std::make_unique<Tree>()) {
    tree_->triangles.reserve(mesh.faces.size());
    for (const auto& face : mesh.faces) {
        for (int corner : face) {
            if (corner < 0 || corner >= mesh.vertexCount()) {
                throw Error(MessageId::MeshTriangleMissingVertex);
            }
        }
        const Kernel::Point_3 a = toPoint(mesh.vertices[face[0]]);
        const Kernel::Point_3 b = toPoint(mesh.vertices[face[1]]);
        const Kernel::Point_3 c = toPoint(mesh.vertices[face[2]]);
        // Degenerate triangles bound no volume and break CGAL's predicates.
        // CGAL::collinear is Triangle_3::is_degenerate's own test (CGAL's
        // Cartesian/Triangle_3.h), called directly for its static filter:
        // is_degenerate goes through the interval filter, 0.9% of sketch to
        // part on the biped in perf.
        if (!CGAL::collinear(a, b, c)) {
            tree_->triangles.emplace_back(a, b, c);
        }
    }
    // Built now: queries are const and may run concurrently.
    tree_->build();
}

BoneVisibility::~BoneVisibility() = default;
BoneVisibility::BoneVisibility(BoneVisibility&&) noexcept = default;
BoneVisibility& BoneVisibility::operator=(BoneVisibility&&) noexcept = default;

bool BoneVisibility::segmentIsInside(const Vec3& from, const Vec3& to) const {
    const Vec3 start = from + kStartOffset * (to - from);
    if (!start.allFinite() || !to.allFinite()) {
        return false;
    }
    if (start == to || tree_->triangles.empty()) {
        return true;
    }
    return !tree_->intersects(Kernel::Segment_3(toPoint(start), toPoint(to)), start, to);
}

std::vector<std::vector<std::pair<int, double>>> closestVisibleBones(
    const TriMesh& mesh, const std::vector<BoneSegment>& bones, const BoneVisibility& visibility,
    const std::vector<int>& verticesToTest, double tieTolerance, int* verticesWithoutVisibleBone) {
    return closestVisibleBones(mesh, vertexNormals(mesh), bones, visibility, verticesToTest,
                               tieTolerance, verticesWithoutVisibleBone);
}

std::vector<std::vector<std::pair<int, double>>> closestVisibleBones(
    const TriMesh& mesh, const std::vector<Vec3>& normals, const std::vector<BoneSegment>& bones,
    const BoneVisibility& visibility, const std::vector<int>& verticesToTest, double tieTolerance,
    int* verticesWithoutVisibleBone) {
    if (normals.size() != mesh.vertices.size())
        throw std::logic_error("Bone visibility needs one normal per vertex.");
    std::vector<std::vector<std::pair<int, double>>> result(verticesToTest.size());
    std::vector<std::pair<double, int>> byDistance;
    int withoutVisible = 0;
    for (std::size_t t = 0; t < verticesToTest.size(); ++t) {
        const int v = verticesToTest[t];
        if (v < 0 || v >= mesh.vertexCount()) {
            throw std::logic_error("A vertex to test for bone visibility is not in the mesh.");
        }
        const Vec3& position = mesh.vertices[v];

        byDistance.clear();
        for (int b = 0; b < static_cast<int>(bones.size()); ++b) {
            const double d = pointSegmentDistance(position, bones[b]);
            if (std::isfinite(d)) {
                byDistance.emplace_back(d, b);
            }
        }
        std::sort(byDistance.begin(), byDistance.end());

        // Walk the bones nearest first; once one is visible, keep only the
        // visible ones that tie with it (Pinocchio factors in equally close
        // bones so that neither wins arbitrarily).
        auto& chosen = result[t];
        const Vec3& normal = normals[v];
        for (const auto& [d, b] : byDistance) {
            if (!chosen.empty() && d > chosen.front().second * (1.0 + tieTolerance)) {
                break;
            }
            const Vec3 p = closestPointOnSegment(position, bones[b]);
            const Vec3 outward = position - p;
            const bool inCone =
                outward.norm() == 0.0 || outward.dot(normal) > kConeCosine * outward.norm();
            if (inCone && visibility.segmentIsInside(position, p)) {
                chosen.emplace_back(b, d);
            }
        }
        if (chosen.empty() && !byDistance.empty()) {
            ++withoutVisible;
            const double nearest = byDistance.front().first;
            for (const auto& [d, b] : byDistance) {
                if (d > nearest * (1.0 + tieTolerance)) {
                    break;
                }
                chosen.emplace_back(b, d);
            }
        }
    }
    if (verticesWithoutVisibleBone != nullptr) {
        *verticesWithoutVisibleBone = withoutVisible;
    }
    return result;
}

}  // namespace rigmesh
