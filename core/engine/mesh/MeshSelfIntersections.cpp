#include "mesh/MeshSelfIntersections.h"

#include "mesh/MeshMirror.h"
#include "mesh/MirroredHeightField.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/box_intersection_d.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <iterator>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace rigmesh {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Triangle = Kernel::Triangle_3;
using Segment = Kernel::Segment_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;
using Polygon = std::array<std::size_t, 3>;
namespace PMP = CGAL::Polygon_mesh_processing;

std::vector<Point> toPoints(const TriMesh& mesh) {
    std::vector<Point> points;
    points.reserve(mesh.vertices.size());
    for (const Vec3& v : mesh.vertices)
        points.emplace_back(v.x(), v.y(), v.z());
    return points;
}

// Pairs counted by PMP on a halfedge mesh, or -1 if the soup does not convert
// to one without duplicating vertices (non-orientable surfaces).
int countWithSurfaceMesh(const TriMesh& mesh) {
    for (const auto& [a, b, c] : mesh.faces)
        if (a == b || b == c || c == a)
            return -1;  // not a polygon mesh; orient_polygon_soup expects none
    std::vector<Point> points = toPoints(mesh);
    std::vector<Polygon> polygons;
    polygons.reserve(mesh.faces.size());
    for (const auto& [a, b, c] : mesh.faces)
        polygons.push_back({static_cast<std::size_t>(a), static_cast<std::size_t>(b),
                            static_cast<std::size_t>(c)});
    // Surface_mesh needs consistent orientation; flipping faces does not move them.
    if (!PMP::orient_polygon_soup(points, polygons) ||
        !PMP::is_polygon_soup_a_polygon_mesh(polygons))
        return -1;

    SurfaceMesh surface;
    PMP::polygon_soup_to_polygon_mesh(points, polygons, surface);
    std::vector<std::pair<SurfaceMesh::Face_index, SurfaceMesh::Face_index>> pairs;
    PMP::self_intersections(surface, std::back_inserter(pairs));
    // PMP reports a collinear face as a pair with itself; those are degenerate
    // faces, which the report counts separately.
    return static_cast<int>(std::count_if(pairs.begin(), pairs.end(),
                                          [](const auto& p) { return p.first != p.second; }));
}

// Relative margin for the floating-point rejection tests below: far above
// their rounding error (about 1e-15), so a rejection is never wrong.
constexpr double kRejectMargin = 1e-10;

// True only when every point in `points` certainly lies outside the triangle
// (a, b, c): strictly beyond its plane, or strictly beyond one of its edges
// within that plane's perpendicular slab. Cheap and conservative, it spares
// the exact predicates the many flat, coplanar neighbours of meshes made of
// strips, where CGAL's filters fail and fall back to exact arithmetic.
template <std::size_t N>
bool certainlyOutside(const Vec3& a, const Vec3& b, const Vec3& c,
                      const std::array<Vec3, N>& points) {
    const std::array<Vec3, 3> corner{a, b, c};
    const Vec3 n = (b - a).cross(c - a);
    double extent = std::max((b - a).norm(), (c - a).norm());
    for (const Vec3& q : points)
        extent = std::max(extent, (q - a).norm());
    const double margin = kRejectMargin * extent * extent * extent;
    // Beyond the plane: all points on one side.
    bool above = true, below = true;
    for (const Vec3& q : points) {
        const double d = n.dot(q - a);
        above = above && d > margin;
        below = below && d < -margin;
    }
    if (above || below)
        return true;
    // Beyond an edge: n x edge points into the triangle.
    for (int k = 0; k < 3; ++k) {
        const Vec3& from = corner[k];
        const Vec3 inward = n.cross(corner[(k + 1) % 3] - from);
        bool outside = true;
        for (const Vec3& q : points)
            outside = outside && inward.dot(q - from) < -margin * extent;
        if (outside)
            return true;
    }
    return false;
}

// True when the corners of `g` other than its `shared` shared ones (their
// positions in `g`: `sharedInG`) lie strictly on one side of the plane of
// `f` (a face with a zero-area triangle has no plane: false).
bool strictlyBeyondPlane(const std::vector<Point>& points, const std::array<int, 3>& f,
                         const std::array<int, 3>& g, const std::array<int, 3>& sharedInG,
                         int shared) {
    CGAL::Orientation side = CGAL::COPLANAR;
    for (int j = 0; j < 3; ++j) {
        if ((shared > 0 && sharedInG[0] == j) || (shared > 1 && sharedInG[1] == j))
            continue;
        const CGAL::Orientation o =
            CGAL::orientation(points[f[0]], points[f[1]], points[f[2]], points[g[j]]);
        if (o == CGAL::COPLANAR || (side != CGAL::COPLANAR && o != side))
            return false;
        side = o;
    }
    return side != CGAL::COPLANAR;
}

// PMP's "does not merely share a vertex or edge" rule, with sharing decided by
// vertex index so that it works on non-manifold soups.
bool facesIntersect(const TriMesh& mesh, const std::vector<Point>& points,
                    const std::array<int, 3>& f, const std::array<int, 3>& g) {
    std::array<int, 3> sharedInF{}, sharedInG{};  // positions of shared vertices
    int shared = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (f[i] == g[j] && shared < 3) {
                sharedInF[shared] = i;
                sharedInG[shared] = j;
                ++shared;
            }
    const auto p = [&](int index) -> const Point& { return points[index]; };

    if (shared >= 2) {
        // A shared edge (a, b): the faces overlap only if they are coplanar and
        // their third vertices lie on the same side of the edge.
        // Third vertices clearly on opposite sides of the edge cannot overlap.
        const Vec3& va = mesh.vertices[f[sharedInF[0]]];
        const Vec3 edge = mesh.vertices[f[sharedInF[1]]] - va;
        const auto across = [&](const Vec3& q) {
            const Vec3 d = q - va;
            return Vec3(d - edge * (d.dot(edge) / edge.squaredNorm()));
        };
        if (shared == 2) {
            const Vec3 u = across(mesh.vertices[f[3 - sharedInF[0] - sharedInF[1]]]);
            const Vec3 w = across(mesh.vertices[g[3 - sharedInG[0] - sharedInG[1]]]);
            if (u.dot(w) < -kRejectMargin * u.norm() * w.norm())
                return false;
        }
        const Point& a = p(f[sharedInF[0]]);
        const Point& b = p(f[sharedInF[1]]);
        const Point& thirdF = p(f[3 - sharedInF[0] - sharedInF[1]]);
        const Point& thirdG = shared == 3 ? thirdF : p(g[3 - sharedInG[0] - sharedInG[1]]);
        return CGAL::coplanar(a, b, thirdF, thirdG) &&
               CGAL::coplanar_orientation(a, b, thirdF, thirdG) == CGAL::POSITIVE;
    }
    // Every corner of one face but the shared ones strictly on one side of
    // the other's plane (exact predicates, CGAL's static filter decides
    // nearly all of them in double arithmetic): the faces meet in their
    // shared vertex at most, which is no intersection. On a smooth surface
    // this settles most neighbours around a vertex before the tests below.
    if (strictlyBeyondPlane(points, f, g, sharedInG, shared) ||
        strictlyBeyondPlane(points, g, f, sharedInF, shared))
        return false;
    const Triangle tf(p(f[0]), p(f[1]), p(f[2]));
    const Triangle tg(p(g[0]), p(g[1]), p(g[2]));
    if (shared == 1) {
        // A shared vertex: intersect each face with the other's opposite edge.
        const int i = sharedInF[0], j = sharedInG[0];
        const auto& v = mesh.vertices;
        const bool gMissesF = certainlyOutside(
            v[f[0]], v[f[1]], v[f[2]], std::array<Vec3, 2>{v[g[(j + 1) % 3]], v[g[(j + 2) % 3]]});
        const bool fMissesG = certainlyOutside(
            v[g[0]], v[g[1]], v[g[2]], std::array<Vec3, 2>{v[f[(i + 1) % 3]], v[f[(i + 2) % 3]]});
        if (gMissesF && fMissesG)
            return false;
        const Segment oppositeF(p(f[(i + 1) % 3]), p(f[(i + 2) % 3]));
        const Segment oppositeG(p(g[(j + 1) % 3]), p(g[(j + 2) % 3]));
        return CGAL::do_intersect(tf, oppositeG) || CGAL::do_intersect(tg, oppositeF);
    }
    const auto& v = mesh.vertices;
    if (certainlyOutside(v[f[0]], v[f[1]], v[f[2]],
                         std::array<Vec3, 3>{v[g[0]], v[g[1]], v[g[2]]}) ||
        certainlyOutside(v[g[0]], v[g[1]], v[g[2]], std::array<Vec3, 3>{v[f[0]], v[f[1]], v[f[2]]}))
        return false;
    return CGAL::do_intersect(tf, tg);
}

// Every pair of overlapping boxes (closed, as CGAL's box intersection takes
// them), each once, by a sweep along the axis in which the boxes' lower
// corners spread most: sorted by their lower end there, a box meets a later
// one in that axis exactly while the later one starts before it ends, and
// the other two axes are then compared. Nothing (false) when that would
// compare more than `budget` pairs: a soup bunched along every axis, left to
// CGAL's segment tree.
bool sweepOverlappingBoxes(const std::vector<CGAL::Bbox_3>& boxes, std::size_t budget,
                           std::vector<std::array<int, 2>>& overlapping) {
    const int count = static_cast<int>(boxes.size());
    if (count < 2)
        return true;
    int axis = 0;
    double widest = -1;
    for (int d = 0; d < 3; ++d) {
        double low = std::numeric_limits<double>::infinity(), high = -low;
        for (const CGAL::Bbox_3& box : boxes) {
            low = std::min(low, box.min(d));
            high = std::max(high, box.min(d));
        }
        if (high - low > widest) {
            widest = high - low;
            axis = d;
        }
    }
    std::vector<int> order(count);
    for (int i = 0; i < count; ++i)
        order[i] = i;
    std::sort(order.begin(), order.end(), [&](int a, int b) {
        return boxes[a].min(axis) < boxes[b].min(axis) ||
               (boxes[a].min(axis) == boxes[b].min(axis) && a < b);
    });
    // The sorted boxes' bounds side by side: the sweep axis's in two arrays,
    // the other two axes' together per box, as the inner loop reads them.
    struct Across {
        double lowU, highU, lowV, highV;
    };
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    std::vector<double> low(count), high(count);
    std::vector<Across> across(count);
    for (int k = 0; k < count; ++k) {
        const CGAL::Bbox_3& box = boxes[order[k]];
        low[k] = box.min(axis);
        high[k] = box.max(axis);
        across[k] = {box.min(u), box.max(u), box.min(v), box.max(v)};
    }
    // The boxes also go into cells of a grid across the sweep axis (u, v),
    // each box into every cell its u and v ranges reach; two boxes
    // overlapping in u and v both reach the cell of the larger of their lower
    // ends in each, and only there is the pair reported, so every pair comes
    // once. A cell's boxes keep the sweep order, and box i meets, in the
    // sweep axis, the cell's later boxes up to the first that starts past its
    // end (a binary search: the lower ends are sorted); the other two axes
    // are then compared without a branch per axis (the comparisons were most
    // of the self-intersection check's own time in perf). Cells about
    // kCellBoxes boxes wide: a slab across the sweep axis holds a whole
    // cross-section of the surface, of which a cell holds a piece.
    constexpr double kCellBoxes = 2.0;
    constexpr int kMostCellsPerAxis = 64;
    struct Grid {
        double lowest = 0, perSpan = 0;
        int cells = 1;
        int of(double x) const {
            return std::clamp(static_cast<int>((x - lowest) * perSpan), 0, cells - 1);
        }
    };
    const auto gridFor = [&](double Across::*lowOf, double Across::*highOf) {
        Grid grid;
        double lowest = std::numeric_limits<double>::infinity(), highest = -lowest, width = 0;
        for (const Across& a : across) {
            lowest = std::min(lowest, a.*lowOf);
            highest = std::max(highest, a.*lowOf);
            width += a.*highOf - a.*lowOf;
        }
        width /= count;
        const double span = highest - lowest;
        if (width > 0 && span > 0) {
            grid.cells = static_cast<int>(std::clamp(span / (kCellBoxes * width), 1.0,
                                                     static_cast<double>(kMostCellsPerAxis)));
            grid.lowest = lowest;
            grid.perSpan = grid.cells / span;
        }
        return grid;
    };
    const Grid gridU = gridFor(&Across::lowU, &Across::highU);
    const Grid gridV = gridFor(&Across::lowV, &Across::highV);
    const int cells = gridU.cells * gridV.cells;
    const auto forCells = [&](const Across& a, auto&& visit) {
        const int lastU = gridU.of(a.highU), firstV = gridV.of(a.lowV), lastV = gridV.of(a.highV);
        for (int cu = gridU.of(a.lowU); cu <= lastU; ++cu)
            for (int cv = firstV; cv <= lastV; ++cv)
                visit(cu * gridV.cells + cv);
    };
    std::vector<int> cellStart(cells + 1, 0);
    for (int k = 0; k < count; ++k)
        forCells(across[k], [&](int cell) { ++cellStart[cell + 1]; });
    for (int cell = 0; cell < cells; ++cell)
        cellStart[cell + 1] += cellStart[cell];
    std::vector<int> member(cellStart[cells]);
    {
        std::vector<int> next(cellStart.begin(), cellStart.end() - 1);
        for (int k = 0; k < count; ++k)
            forCells(across[k], [&](int cell) { member[next[cell]++] = k; });
    }
    std::vector<double> memberLow(member.size());
    std::vector<Across> memberAcross(member.size());
    for (std::size_t m = 0; m < member.size(); ++m) {
        memberLow[m] = low[member[m]];
        memberAcross[m] = across[member[m]];
    }
    std::size_t compared = 0;
    for (int cell = 0; cell < cells; ++cell) {
        const int first = cellStart[cell], stop = cellStart[cell + 1];
        const int cellU = cell / gridV.cells, cellV = cell % gridV.cells;
        for (int i = first; i < stop; ++i) {
            const double highI = high[member[i]];
            const int end = static_cast<int>(
                std::upper_bound(memberLow.begin() + i + 1, memberLow.begin() + stop, highI) -
                memberLow.begin());
            compared += static_cast<std::size_t>(end - i - 1);
            if (compared > budget) {
                overlapping.clear();
                return false;
            }
            const Across a = memberAcross[i];
            const Across* const others = memberAcross.data();
            for (int j = i + 1; j < end; ++j) {
                const Across& b = others[j];
                if ((b.lowU <= a.highU) & (a.lowU <= b.highU) & (b.lowV <= a.highV) &
                        (a.lowV <= b.highV) &&
                    (cells == 1 || (gridU.of(std::max(a.lowU, b.lowU)) == cellU &&
                                    gridV.of(std::max(a.lowV, b.lowV)) == cellV)))
                    overlapping.push_back({order[member[i]], order[member[j]]});
            }
        }
    }
    return true;
}

// The same test as PMP::self_intersections, run on the soup itself: every
// pair of faces whose boxes overlap (closed boxes, as PMP's) is tested with
// facesIntersect. The pairs come from a sweep (sweepOverlappingBoxes: on
// the sketch surfaces about a fifth of the time of CGAL's segment tree, which
// was most of this test in perf), or, for a soup the sweep would take
// quadratic time on, from CGAL's box intersection on pointers to the boxes
// with PMP's cutoff of 2000 boxes. Both give every overlapping pair, so the
// pairs found are the same. `faces`, when given, are the only faces tested
// (pairs among them, by their indices in the mesh).
std::vector<std::array<int, 2>> pairsOnSoup(const TriMesh& mesh,
                                            const std::vector<int>* faces = nullptr) {
    const std::vector<Point> points = toPoints(mesh);
    std::vector<CGAL::Bbox_3> bounds;
    std::vector<int> boxFace;
    bounds.reserve(faces ? faces->size() : mesh.faces.size());
    boxFace.reserve(bounds.capacity());
    const auto addBox = [&](int i) {
        const auto& [a, b, c] = mesh.faces[i];
        if (!CGAL::collinear(points[a], points[b], points[c])) {
            bounds.push_back(points[a].bbox() + points[b].bbox() + points[c].bbox());
            boxFace.push_back(i);
        }
    };
    if (faces)
        for (int i : *faces)
            addBox(i);
    else
        for (int i = 0; i < mesh.faceCount(); ++i)
            addBox(i);
    std::vector<std::array<int, 2>> pairs;
    const auto test = [&](int x, int y) {
        if (facesIntersect(mesh, points, mesh.faces[x], mesh.faces[y]))
            pairs.push_back({std::min(x, y), std::max(x, y)});
    };
    // On a surface of even edges a box meets a few dozen others along the
    // sweep axis; far more means a soup bunched up in every axis.
    constexpr std::size_t kSweepComparisonsPerBox = 256;
    std::vector<std::array<int, 2>> overlapping;
    if (sweepOverlappingBoxes(bounds, kSweepComparisonsPerBox * bounds.size(), overlapping)) {
        for (const auto& [x, y] : overlapping)
            test(boxFace[x], boxFace[y]);
    } else {
        using Box = CGAL::Box_intersection_d::Box_with_info_d<
            double, 3, int, CGAL::Box_intersection_d::ID_FROM_BOX_ADDRESS>;
        std::vector<Box> boxes;
        boxes.reserve(bounds.size());
        for (std::size_t k = 0; k < bounds.size(); ++k)
            boxes.emplace_back(bounds[k], boxFace[k]);
        std::vector<const Box*> handles;
        handles.reserve(boxes.size());
        for (const Box& box : boxes)
            handles.push_back(&box);
        const auto callback = [&](const Box* x, const Box* y) { test(x->info(), y->info()); };
        constexpr std::ptrdiff_t kCutoff = 2000;  // PMP::self_intersections' own
        CGAL::box_self_intersection_d(handles.begin(), handles.end(), callback, kCutoff);
    }
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

// The faces that decide whether a surface that is exactly its own mirror
// image in the plane z = 0 intersects itself, or nothing when it is not
// exactly that: every vertex v has its image mirror[v] at (x, y, -z) (bit for
// bit; a vertex on the plane is its own), and every face (a, b, c) has a face
// on (mirror[a], mirror[b], mirror[c]) whose image it is in turn
// (mirrorFaceImages: no face listed twice, which the argument would miss).
//
// Why these suffice. Reflection maps intersecting face pairs to intersecting
// face pairs: facesIntersect decides with CGAL's exact predicates (its
// floating-point tests only reject certain misses), and face boxes are
// exact, so the verdict on a pair is the verdict on its image. Split the
// faces into U (one face of each pair of images: the higher one), D (their
// images) and H (faces that are their own image). A pair within D is the
// image of one within U; a pair (h, d) with h in H, d in D the image of
// (h, image of d), within U and H. A pair (u, image of v), u and v in U, can
// only meet where their boxes do: zmin(u) <= zmax(image of v) = -zmin(v).
// With m the least zmin in U, that needs zmin(u) <= -m and zmin(v) <= -m:
// both in S, U's faces reaching down to -m. So testing every pair within
// U, H and the images of S finds an intersection if the whole surface has
// one. On the sketch surfaces (SketchSurface.h: built as the upper half and
// mirrored) U is the upper half, m is 0 and S the faces touching the
// outline: about half the faces to test.
std::optional<std::vector<int>> mirrorDecidingFaces(const TriMesh& mesh,
                                                    const std::vector<int>& mirror) {
    const std::optional<std::vector<int>> images = mirrorFaceImages(mesh, mirror);
    if (!images)
        return std::nullopt;
    const std::vector<int>& image = *images;
    const int faceTotal = mesh.faceCount();
    const auto zSum = [&](int face) {
        const auto& f = mesh.faces[face];
        return mesh.vertices[f[0]].z() + mesh.vertices[f[1]].z() + mesh.vertices[f[2]].z();
    };
    const auto zMin = [&](int face) {
        const auto& f = mesh.faces[face];
        return std::min(
            {mesh.vertices[f[0]].z(), mesh.vertices[f[1]].z(), mesh.vertices[f[2]].z()});
    };
    std::vector<int> kept;  // U, then H
    for (int i = 0; i < faceTotal; ++i) {
        const int j = image[i];
        if (j == i || zSum(i) > zSum(j) || (zSum(i) == zSum(j) && i < j))
            kept.push_back(i);
    }
    double lowest = std::numeric_limits<double>::infinity();  // m
    for (int i : kept)
        if (image[i] != i)
            lowest = std::min(lowest, zMin(i));
    const std::size_t keptTotal = kept.size();
    for (std::size_t k = 0; k < keptTotal; ++k) {
        const int i = kept[k];
        if (image[i] != i && zMin(i) <= -lowest)
            kept.push_back(image[i]);
    }
    return kept;
}

}  // namespace

int countSelfIntersectingFacePairs(const TriMesh& mesh) {
    return static_cast<int>(pairsOnSoup(mesh).size());
}

std::vector<std::array<int, 2>> selfIntersectingFacePairs(const TriMesh& mesh) {
    return pairsOnSoup(mesh);
}

std::vector<std::array<int, 2>> selfIntersectingFacePairs(const TriMesh& mesh,
                                                          const std::vector<int>& mirror) {
    // Sketch surfaces are mostly proven free of crossings by their shape, a
    // height field over the sketch plane and its image; every crossing pair
    // lies among the faces over a fold of it, if any.
    if (const auto suspects = mirroredHeightFieldSuspects(mesh, mirror))
        return suspects->empty() ? std::vector<std::array<int, 2>>{}
                                 : pairsOnSoup(mesh, &*suspects);
    const std::optional<std::vector<int>> deciding = mirrorDecidingFaces(mesh, mirror);
    if (deciding && pairsOnSoup(mesh, &*deciding).empty())
        return {};
    return pairsOnSoup(mesh);
}

int countSelfIntersectingFacePairsWithSurfaceMesh(const TriMesh& mesh) {
    return countWithSurfaceMesh(mesh);
}

}  // namespace rigmesh
