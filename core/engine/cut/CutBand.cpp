#include "cut/CutBand.h"

#include <CGAL/Polygon_mesh_processing/clip.h>

#include <array>
#include <cmath>
#include <initializer_list>
#include <limits>

namespace rigmesh {

using namespace cgal;
namespace PMP = CGAL::Polygon_mesh_processing;

namespace {

using HalfedgeIndex = SurfaceMesh::Halfedge_index;

// Faces around the ones CGAL can touch: what keeps its changes away from the
// band's border (an edge it splits changes both its faces; a vertex it
// duplicates, every face around it).
constexpr int kRings = 2;
// Above this share of the faces the band saves too little: split the whole.
constexpr double kLargestBand = 0.6;

struct Box {
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
    Vec3 hi = Vec3::Constant(-std::numeric_limits<double>::infinity());
    void extend(const Vec3& p) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
};

// Closed boxes, as CGAL's box intersection (Box_intersection_d::CLOSED)
// reports them.
bool overlap(const Box& a, const Box& b) {
    for (int d = 0; d < 3; ++d)
        if (a.lo[d] > b.hi[d] || b.lo[d] > a.hi[d])
            return false;
    return true;
}

// A plane through three points, for telling on which side a point lies with
// a margin far above the rounding of the double computation, so that a point
// CGAL's exact orientation may find on the plane (or across it) is never
// called strictly on one side.
struct SidePlane {
    Vec3 origin, normal;
    double scale = 0.0;

    SidePlane(const Vec3& a, const Vec3& b, const Vec3& c)
        : origin(a), normal((b - a).cross(c - a)), scale((b - a).norm() * (c - a).norm()) {}

    // -1 or +1: strictly on that side; 0: on the plane or too near to tell.
    int side(const Vec3& q) const {
        const Vec3 d = q - origin;
        const double s = normal.dot(d);
        const double margin = 1e-10 * scale * d.norm() + 1e-300;
        return s > margin ? 1 : s < -margin ? -1 : 0;
    }
    // Whether the segment p-q may meet the plane (CGAL looks at it unless
    // both ends lie strictly on one side).
    bool mayMeet(const Vec3& p, const Vec3& q) const {
        const int sp = side(p);
        return sp == 0 || sp != side(q);
    }
};

Vec3 pointOf(const SurfaceMesh& mesh, VertexIndex v) {
    return toVec(mesh.point(v));
}

Box boxOf(std::initializer_list<Vec3> points) {
    Box box;
    for (const Vec3& p : points)
        box.extend(p);
    return box;
}

// Which faces of `whole` CGAL's split by `splitter` depends on (CutBand.h),
// grown by kRings rings.
std::vector<char> bandFaces(const SurfaceMesh& whole, const SurfaceMesh& splitter) {
    const int faceCount = static_cast<int>(whole.num_faces());
    std::vector<char> inBand(faceCount, 0);

    // Each vertex's position once (not once per edge and face around it).
    std::vector<Vec3> position(whole.num_vertices());
    Box wholeBox;
    for (VertexIndex v : whole.vertices()) {
        position[v.idx()] = pointOf(whole, v);
        wholeBox.extend(position[v.idx()]);
    }
    struct Triangle {
        Box box;
        SidePlane plane;
    };
    // The splitter's triangles and edges near the input, and the boxes
    // around all of each: what misses those boxes meets none of them.
    std::vector<Triangle> triangles;
    Box trianglesBox;
    for (FaceIndex t : splitter.faces()) {
        const HalfedgeIndex h = splitter.halfedge(t);
        const Vec3 a = pointOf(splitter, splitter.source(h));
        const Vec3 b = pointOf(splitter, splitter.target(h));
        const Vec3 c = pointOf(splitter, splitter.target(splitter.next(h)));
        const Box box = boxOf({a, b, c});
        if (overlap(box, wholeBox)) {
            triangles.push_back({box, SidePlane(a, b, c)});
            trianglesBox.extend(box.lo);
            trianglesBox.extend(box.hi);
        }
    }
    struct Segment {
        Box box;
        Vec3 p, q;
    };
    std::vector<Segment> segments;
    Box segmentsBox;
    for (EdgeIndex e : splitter.edges()) {
        const HalfedgeIndex h = splitter.halfedge(e);
        const Vec3 p = pointOf(splitter, splitter.source(h));
        const Vec3 q = pointOf(splitter, splitter.target(h));
        const Box box = boxOf({p, q});
        if (overlap(box, wholeBox)) {
            segments.push_back({box, p, q});
            segmentsBox.extend(box.lo);
            segmentsBox.extend(box.hi);
        }
    }

    // Each face's corners, from the source of its halfedge, read once (the
    // tests and rings below read these, not the halfedges).
    std::vector<std::array<int, 3>> corners(faceCount);
    for (FaceIndex f : whole.faces()) {
        const HalfedgeIndex h = whole.halfedge(f);
        corners[f.idx()] = {static_cast<int>(whole.source(h).idx()),
                            static_cast<int>(whole.target(h).idx()),
                            static_cast<int>(whole.target(whole.next(h)).idx())};
    }
    // The input's edges that may cross a splitter triangle: both their
    // faces (each face tests its own three edges; the test is the same
    // either way along an edge). A vertex's side of a triangle's plane is
    // taken once (kUnknownSide until then), not once per edge around it.
    constexpr signed char kUnknownSide = 2;
    const std::size_t triangleCount = triangles.size();
    std::vector<signed char> sides(position.size() * triangleCount, kUnknownSide);
    const auto sideOf = [&](int vertex, std::size_t t) {
        signed char& side = sides[vertex * triangleCount + t];
        if (side == kUnknownSide)
            side = static_cast<signed char>(triangles[t].plane.side(position[vertex]));
        return side;
    };
    for (int f = 0; f < faceCount; ++f)
        for (int k = 0; k < 3 && !inBand[f]; ++k) {
            const int from = corners[f][k], to = corners[f][(k + 1) % 3];
            const Box box = boxOf({position[from], position[to]});
            if (!overlap(box, trianglesBox))
                continue;
            for (std::size_t t = 0; t < triangleCount; ++t) {
                if (!overlap(box, triangles[t].box))
                    continue;
                // SidePlane::mayMeet on the sides kept.
                const signed char sideFrom = sideOf(from, t);
                if (sideFrom == 0 || sideFrom != sideOf(to, t)) {
                    inBand[f] = 1;
                    break;
                }
            }
        }
    // The input's faces a splitter edge may cross.
    for (int f = 0; f < faceCount; ++f) {
        if (inBand[f])
            continue;
        const Vec3& a = position[corners[f][0]];
        const Vec3& b = position[corners[f][1]];
        const Vec3& c = position[corners[f][2]];
        const Box box = boxOf({a, b, c});
        if (!overlap(box, segmentsBox))
            continue;
        for (const Segment& s : segments)
            if (overlap(box, s.box) && SidePlane(a, b, c).mayMeet(s.p, s.q)) {
                inBand[f] = 1;
                break;
            }
    }

    // Rings: every face around a vertex of the band joins it.
    std::vector<char> marked(whole.num_vertices(), 0);
    for (int ring = 0; ring < kRings; ++ring) {
        for (int f = 0; f < faceCount; ++f)
            if (inBand[f])
                for (int v : corners[f])
                    marked[v] = 1;
        for (int f = 0; f < faceCount; ++f)
            if (!inBand[f] &&
                (marked[corners[f][0]] || marked[corners[f][1]] || marked[corners[f][2]]))
                inBand[f] = 1;
    }
    return inBand;
}

// One halfedge's connectivity, to check that the split left it alone.
struct HalfedgeState {
    HalfedgeIndex h;
    VertexIndex target;
    HalfedgeIndex next;
    FaceIndex face;
    bool operator==(const HalfedgeState&) const = default;
};

HalfedgeState stateOf(const SurfaceMesh& mesh, HalfedgeIndex h) {
    return {h, mesh.target(h), mesh.next(h), mesh.face(h)};
}

}  // namespace

void splitAlong(SurfaceMesh& tm, SurfaceMesh& splitter) {
    PMP::split(tm, splitter, CGAL::parameters::default_values(),
               CGAL::parameters::do_not_modify(true));
}

BandOutcome splitInBand(const SurfaceMesh& whole, SurfaceMesh& splitter) {
    BandOutcome outcome;
    const int vertexCount = static_cast<int>(whole.num_vertices());
    const int halfedgeCount = static_cast<int>(whole.num_halfedges());
    const int faceCount = static_cast<int>(whole.num_faces());
    if (whole.has_garbage()) {
        outcome.whyNot = "the input has removed elements";
        return outcome;
    }

    const std::vector<char> inBand = bandFaces(whole, splitter);
    for (char b : inBand)
        outcome.bandFaces += b;
    if (outcome.bandFaces == 0) {
        outcome.whyNot = "no face near the cut";
        return outcome;
    }
    if (outcome.bandFaces > kLargestBand * faceCount) {
        outcome.whyNot = "the band is most of the surface";
        return outcome;
    }

    // Vertices with a face in the band; those also with a face outside are
    // on its border.
    std::vector<char> vertexInBand(vertexCount, 0), vertexOutside(vertexCount, 0);
    for (FaceIndex f : whole.faces())
        for (VertexIndex v : CGAL::vertices_around_face(whole.halfedge(f), whole))
            (inBand[f.idx()] ? vertexInBand : vertexOutside)[v.idx()] = 1;

    // The band: the whole surface with the faces outside removed, indices
    // kept, garbage not recycled (new elements get the indices they get on
    // the whole surface).
    SurfaceMesh band = whole;
    band.set_recycle_garbage(false);
    std::vector<HalfedgeIndex> borderHalfedges;
    for (int h = 0; h < halfedgeCount; ++h) {
        const HalfedgeIndex half(h);
        if (!inBand[whole.face(half).idx()] && inBand[whole.face(whole.opposite(half)).idx()])
            borderHalfedges.push_back(half);
    }
    for (HalfedgeIndex h : borderHalfedges) {
        // The next border halfedge: around the target from the band's side,
        // the first edge whose face is outside.
        HalfedgeIndex g = whole.opposite(h);
        do
            g = whole.opposite(whole.prev(g));
        while (inBand[whole.face(g).idx()]);
        band.set_face(h, SurfaceMesh::null_face());
        band.set_next(h, g);
        band.set_halfedge(whole.target(h), h);
    }
    for (FaceIndex f : whole.faces())
        if (!inBand[f.idx()])
            band.remove_face(f);
    for (EdgeIndex e : whole.edges()) {
        const HalfedgeIndex h = whole.halfedge(e);
        if (!inBand[whole.face(h).idx()] && !inBand[whole.face(whole.opposite(h)).idx()])
            band.remove_edge(e);
    }
    for (VertexIndex v : whole.vertices())
        if (!vertexInBand[v.idx()])
            band.remove_vertex(v);

    // What the split must leave alone: every halfedge at the band's border
    // vertices, and their halfedges.
    std::vector<HalfedgeState> guarded;
    std::vector<std::pair<VertexIndex, HalfedgeIndex>> guardedVertices;
    for (VertexIndex v : whole.vertices()) {
        if (!vertexInBand[v.idx()] || !vertexOutside[v.idx()])
            continue;
        guardedVertices.emplace_back(v, band.halfedge(v));
        const HalfedgeIndex first = whole.halfedge(v);
        HalfedgeIndex h = first;
        do {
            guarded.push_back(stateOf(band, h));
            guarded.push_back(stateOf(band, whole.opposite(h)));
            h = whole.opposite(whole.next(h));
        } while (h != first);
    }
    const auto removedVertices = band.number_of_removed_vertices();
    const auto removedHalfedges = band.number_of_removed_halfedges();
    const auto removedFaces = band.number_of_removed_faces();

    splitAlong(band, splitter);

    for (const HalfedgeState& s : guarded)
        if (!(stateOf(band, s.h) == s)) {
            outcome.whyNot = "the split reached the band's border";
            return outcome;
        }
    for (const auto& [v, h] : guardedVertices)
        if (band.halfedge(v) != h) {
            outcome.whyNot = "the split reached the band's border";
            return outcome;
        }
    if (band.number_of_removed_vertices() != removedVertices ||
        band.number_of_removed_halfedges() != removedHalfedges ||
        band.number_of_removed_faces() != removedFaces) {
        outcome.whyNot = "the split removed elements";
        return outcome;
    }

    // The whole split surface: the band's connectivity where it is the band,
    // the whole input's elsewhere (the split left it alone).
    const int splitVertices = static_cast<int>(band.num_vertices());
    const int splitHalfedges = static_cast<int>(band.num_halfedges());
    const int splitFaces = static_cast<int>(band.num_faces());
    std::vector<int> target(splitHalfedges), next(splitHalfedges), face(splitHalfedges);
    for (int h = 0; h < splitHalfedges; ++h) {
        const HalfedgeIndex half(h);
        const bool outside = h < halfedgeCount && !inBand[whole.face(half).idx()];
        const SurfaceMesh& from = outside ? whole : band;
        target[h] = static_cast<int>(from.target(half).idx());
        next[h] = static_cast<int>(from.next(half).idx());
        const FaceIndex f = from.face(half);
        face[h] = f == SurfaceMesh::null_face() ? -1 : static_cast<int>(f.idx());
    }
    std::vector<int> vertexHalfedge(splitVertices);
    for (int v = 0; v < splitVertices; ++v) {
        const VertexIndex vertex(v);
        const bool outside = v < vertexCount && vertexOutside[v];
        vertexHalfedge[v] = static_cast<int>((outside ? whole : band).halfedge(vertex).idx());
    }
    std::vector<int> faceHalfedge(splitFaces);
    for (int f = 0; f < splitFaces; ++f) {
        const FaceIndex index(f);
        const bool outside = f < faceCount && !inBand[f];
        faceHalfedge[f] = static_cast<int>((outside ? whole : band).halfedge(index).idx());
    }

    // Connected components as PMP::connected_components numbers them: in
    // the order of their first face.
    std::vector<int> label(splitFaces, -1);
    int components = 0;
    std::vector<int> stack;
    for (int f = 0; f < splitFaces; ++f) {
        if (label[f] >= 0)
            continue;
        stack.assign(1, f);
        while (!stack.empty()) {
            const int g = stack.back();
            stack.pop_back();
            if (label[g] >= 0)
                continue;
            label[g] = components;
            int h = faceHalfedge[g];
            for (int k = 0; k < 3; ++k, h = next[h]) {
                const int other = face[h ^ 1];
                if (other >= 0 && label[other] < 0)
                    stack.push_back(other);
            }
        }
        ++components;
    }
    // Each vertex in one component (split_connected_components's copies
    // would otherwise share it).
    std::vector<int> vertexLabel(splitVertices, -1);
    for (int f = 0; f < splitFaces; ++f) {
        int h = faceHalfedge[f];
        for (int k = 0; k < 3; ++k, h = next[h]) {
            int& l = vertexLabel[target[h]];
            if (l < 0)
                l = label[f];
            else if (l != label[f]) {
                outcome.whyNot = "a vertex lies on two pieces";
                return outcome;
            }
        }
    }

    // copy_face_graph's order: a vertex where its halfedge comes up among
    // the halfedges in index order; faces by index, from the source of their
    // halfedge; border loops from their first halfedge by index.
    std::vector<SplitComponent> pieces(components);
    std::vector<int> outIndex(splitVertices, -1);
    for (int h = 0; h < splitHalfedges; ++h) {
        const int v = target[h];
        if (vertexHalfedge[v] != h)
            continue;
        if (vertexLabel[v] < 0) {
            outcome.whyNot = "an edge without a face";
            return outcome;
        }
        SplitComponent& piece = pieces[vertexLabel[v]];
        outIndex[v] = static_cast<int>(piece.points.size());
        piece.points.push_back(pointOf(band, VertexIndex(v)));
        piece.wholeVertex.push_back(v);
    }
    for (int v = 0; v < splitVertices; ++v)
        if (vertexLabel[v] >= 0 && outIndex[v] < 0) {
            outcome.whyNot = "a vertex's halfedge is not its own";
            return outcome;
        }
    for (int f = 0; f < splitFaces; ++f) {
        const int h = faceHalfedge[f];
        pieces[label[f]].faces.push_back(
            {outIndex[target[h ^ 1]], outIndex[target[h]], outIndex[target[next[h]]]});
    }
    std::vector<char> seen(splitHalfedges, 0);
    for (int h = 0; h < splitHalfedges; ++h) {
        if (face[h] >= 0 || seen[h])
            continue;
        if (face[h ^ 1] < 0) {
            outcome.whyNot = "an edge without a face";
            return outcome;
        }
        std::vector<int> loop;
        int g = h;
        do {
            seen[g] = 1;
            loop.push_back(outIndex[target[g ^ 1]]);
            g = next[g];
        } while (g != h && loop.size() <= static_cast<std::size_t>(splitHalfedges));
        if (g != h) {
            outcome.whyNot = "a border loop does not close";
            return outcome;
        }
        pieces[label[face[h ^ 1]]].holes.push_back(std::move(loop));
    }
    outcome.components = std::move(pieces);
    outcome.inBand = inBand;
    return outcome;
}

}  // namespace rigmesh
