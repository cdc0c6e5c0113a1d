#include "autorig/SurfaceProbe.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <list>
#include <numbers>
#include <vector>

#include "autorig/JointsInside.h"
#include "mesh/CgalSurfaceMesh.h"

namespace rigmesh {

namespace {

using cgal::Kernel;
using cgal::Point;

// Directions tried in the cross-section's plane from a point outside.
constexpr int kDirections = 16;
// A hit this many times the ray's start offset away is a wall; nearer, the
// ray only left a face it started on (at an edge or a corner) and goes on.
constexpr double kNearHit = 100.0;
// Walls closer together along a ray than this fraction of the size count as
// one (tests/external/check_tails_inside_in_blender.py steps as far past
// each hit).
constexpr double kSameWall = 1e-5;
// The rays of ray-cast parity, in no plane of the axes so that they rarely
// run along a face: check_tails_inside_in_blender.py's three as they are in
// Blender's Z-up world, the same three in a Y-up frame (glTF's, which
// Blender's importer turns up), and one more. Inside when all but one say
// so: then any three of them, the checker's among them, vote inside by
// majority, and a point deep in a limb is not called outside for one ray
// through a gap between pieces.
const std::array<Vec3, 7> kParityRays = {
    Vec3(0.267, 0.534, 0.802).normalized(), Vec3(-0.7, 0.1, 0.3).normalized(),
    Vec3(0.2, -0.9, -0.35).normalized(),    Vec3(0.267, 0.802, -0.534).normalized(),
    Vec3(-0.7, 0.3, -0.1).normalized(),     Vec3(0.2, -0.35, 0.9).normalized(),
    Vec3(-0.43, -0.61, 0.66).normalized()};

Point point(const Vec3& v) {
    return {v.x(), v.y(), v.z()};
}

}  // namespace

struct SurfaceProbe::Tree {
    using Triangle = Kernel::Triangle_3;
    using Iterator = std::vector<Triangle>::const_iterator;
    using Primitive = CGAL::AABB_triangle_primitive<Kernel, Iterator>;
    using Aabb = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

    std::vector<Triangle> triangles;
    Aabb aabb;
    double epsilon = 0.0;
    double size = 0.0;

    // The first wall along the ray from `start` (none: the ray leaves).
    std::optional<Vec3> firstWall(const Vec3& start, const Vec3& direction) const {
        Vec3 from = start + epsilon * direction;
        for (int attempt = 0; attempt < 4; ++attempt) {
            const auto hit = aabb.first_intersection(Kernel::Ray_3(
                point(from), Kernel::Vector_3(direction.x(), direction.y(), direction.z())));
            if (!hit)
                return std::nullopt;
            const Point* wall = boost::get<Point>(&hit->first);
            if (!wall)
                return std::nullopt;
            const Vec3 found = cgal::toVec(*wall);
            if ((found - start).norm() > kNearHit * epsilon)
                return found;
            from = found + kNearHit * epsilon * direction;
        }
        return std::nullopt;
    }
};

SurfaceProbe::SurfaceProbe(const TriMesh& surface, InsideBy rule)
    : mesh_(surface), rule_(rule), tree_(new Tree) {
    Eigen::AlignedBox3d box;
    for (const Vec3& v : surface.vertices)
        box.extend(v);
    tree_->size = box.isEmpty() ? 0.0 : box.diagonal().norm();
    tree_->epsilon = 1e-7 * (box.isEmpty() ? 1.0 : tree_->size);
    // A face without area (two corners at one place, as a file's split
    // seams give: the same point under two vertex indices) is no wall: rays
    // and distances skip it, as Blender's ray casts and
    // tests/external/check_tails_inside_in_blender.py do. CGAL's ray
    // intersection takes non-degenerate triangles only: one with two equal
    // corners gave segment "hits" a ray never crosses, and so a wrong parity.
    for (const auto& [a, b, c] : surface.faces) {
        const Point pa = point(surface.vertices[a]);
        const Point pb = point(surface.vertices[b]);
        const Point pc = point(surface.vertices[c]);
        if (!CGAL::collinear(pa, pb, pc))
            tree_->triangles.emplace_back(pa, pb, pc);
    }
    tree_->aabb.insert(tree_->triangles.begin(), tree_->triangles.end());
    tree_->aabb.accelerate_distance_queries();
}

SurfaceProbe::~SurfaceProbe() = default;

bool SurfaceProbe::inside(const Vec3& p) const {
    if (rule_ == InsideBy::WindingNumber)
        return windingNumber(mesh_, p) > 0.5;
    if (tree_->triangles.empty())
        return false;
    const auto odd = std::count_if(kParityRays.begin(), kParityRays.end(),
                                   [&](const Vec3& ray) { return walls(p, ray).size() % 2 == 1; });
    return odd + 1 >= static_cast<long>(kParityRays.size());
}

std::vector<double> SurfaceProbe::walls(const Vec3& from, const Vec3& direction) const {
    using Hit = Tree::Aabb::Intersection_and_primitive_id<Kernel::Ray_3>::Type;
    const Vec3 d = direction.normalized();
    std::list<Hit> hits;
    tree_->aabb.all_intersections(Kernel::Ray_3(point(from), Kernel::Vector_3(d.x(), d.y(), d.z())),
                                  std::back_inserter(hits));
    std::vector<double> along;
    for (const Hit& hit : hits) {
        // A ray in a face's plane meets it along a segment: its near end.
        if (const Point* p = boost::get<Point>(&hit.first))
            along.push_back((cgal::toVec(*p) - from).dot(d));
        else if (const auto* s = boost::get<Kernel::Segment_3>(&hit.first))
            along.push_back(std::min((cgal::toVec(s->source()) - from).dot(d),
                                     (cgal::toVec(s->target()) - from).dot(d)));
    }
    std::sort(along.begin(), along.end());
    std::vector<double> result;
    for (double t : along)
        if (t >= 0.0 && (result.empty() || t > result.back() + kSameWall * tree_->size))
            result.push_back(t);
    return result;
}

double SurfaceProbe::size() const {
    return tree_->size;
}

double SurfaceProbe::distance(const Vec3& p) const {
    if (tree_->triangles.empty())
        return std::numeric_limits<double>::infinity();
    return std::sqrt(tree_->aabb.squared_distance(point(p)));
}

std::optional<Vec3> SurfaceProbe::middleOfCrossSection(const Vec3& p, const Vec3& direction) const {
    const Vec3 d = direction.norm() > 0.0 ? direction.normalized() : Vec3::UnitZ();
    const Vec3 u = d.unitOrthogonal();
    const Vec3 v = d.cross(u);
    // Halfway between the walls met both ways along `along` from inside.
    const auto centred = [&](const Vec3& from, const Vec3& along) -> std::optional<Vec3> {
        const std::optional<Vec3> ahead = tree_->firstWall(from, along);
        const std::optional<Vec3> behind = tree_->firstWall(from, -along);
        if (!ahead || !behind)
            return std::nullopt;
        return 0.5 * (*ahead + *behind);
    };
    Vec3 start = p;
    Vec3 first = u;
    if (!inside(p)) {
        // The nearest wall any ray in the plane meets, and the wall behind it.
        double nearest = INFINITY;
        std::optional<Vec3> middle;
        for (int k = 0; k < kDirections; ++k) {
            const double angle = 2.0 * std::numbers::pi * k / kDirections;
            const Vec3 ray = std::cos(angle) * u + std::sin(angle) * v;
            const std::optional<Vec3> in = tree_->firstWall(p, ray);
            if (!in || (*in - p).norm() >= nearest)
                continue;
            const std::optional<Vec3> out = tree_->firstWall(*in, ray);
            if (!out)
                continue;
            nearest = (*in - p).norm();
            middle = 0.5 * (*in + *out);
            first = ray;
        }
        if (!middle || !inside(*middle))
            return std::nullopt;
        start = *middle;
    } else {
        const std::optional<Vec3> once = centred(p, u);
        if (!once || !inside(*once))
            return std::nullopt;
        start = *once;
    }
    // Centred across the first direction too.
    const std::optional<Vec3> across = centred(start, d.cross(first).normalized());
    if (across && inside(*across))
        return across;
    return start;
}

Vec3 SurfaceProbe::entry(const Vec3& outsidePoint, const Vec3& insidePoint) const {
    double out = 0.0, in = 1.0;
    for (int step = 0; step < 30; ++step) {
        const double t = 0.5 * (out + in);
        (inside(outsidePoint + t * (insidePoint - outsidePoint)) ? in : out) = t;
    }
    return outsidePoint + in * (insidePoint - outsidePoint);
}

}  // namespace rigmesh
