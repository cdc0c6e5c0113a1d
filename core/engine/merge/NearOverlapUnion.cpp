#include "merge/NearOverlapUnion.h"

#include <CGAL/Polygon_mesh_processing/corefinement.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <numeric>
#include <unordered_map>
#include <unordered_set>

#include "base/Error.h"
#include "mesh/CgalSurfaceMesh.h"
#include "mesh/MeshChecks.h"
#include "mesh/MeshTopologyCheck.h"
#include "mesh/MeshVolume.h"

namespace rigmesh {

namespace {

using namespace cgal;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace params = CGAL::parameters;

Eigen::AlignedBox3d faceBox(const TriMesh& mesh, const std::array<int, 3>& face) {
    Eigen::AlignedBox3d box(mesh.vertices[face[0]]);
    box.extend(mesh.vertices[face[1]]);
    box.extend(mesh.vertices[face[2]]);
    return box;
}

// Flags an edge through a vertex of the other surface, an edge's end on the
// other surface and coplanar faces: there the sides of the pieces need not
// alternate across a loop. An edge crossing a face or an edge of the other
// is a plain crossing (two parts mirrored in the same plane cross so, edge
// on edge, where their loop meets the plane).
struct CrossingsOnlyVisitor : PMP::Corefinement::Default_visitor<SurfaceMesh> {
    bool* touching = nullptr;
    void intersection_point_detected(std::size_t, int type, SurfaceMesh::Halfedge_index,
                                     SurfaceMesh::Halfedge_index, const SurfaceMesh&,
                                     const SurfaceMesh&, bool targetCoplanar,
                                     bool sourceCoplanar) const {
        if (type == PMP::Corefinement::ON_VERTEX || targetCoplanar || sourceCoplanar)
            *touching = true;
    }
    void start_handling_intersection_of_coplanar_faces(std::size_t pairs) const {
        if (pairs > 0)
            *touching = true;
    }
};

// The faces of `mesh` whose boxes meet `region`, as a CGAL mesh whose
// vertices remember their input index ("v:input"; -1 for a vertex the
// corefinement adds). Empty optional when the faces do not make a surface
// CGAL can hold.
struct NearMesh {
    SurfaceMesh surface;
    SurfaceMesh::Property_map<VertexIndex, int> input;
    SurfaceMesh::Property_map<EdgeIndex, bool> onLoop;
    std::vector<char> isNear;  // per input face
};

bool buildNearMesh(const TriMesh& mesh, const Eigen::AlignedBox3d& region, NearMesh& near) {
    near.input = near.surface.add_property_map<VertexIndex, int>("v:input", -1).first;
    near.onLoop = near.surface.add_property_map<EdgeIndex, bool>("e:loop", false).first;
    near.isNear.assign(mesh.faces.size(), 0);
    std::vector<int> local(mesh.vertices.size(), -1);
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        if (!region.intersects(faceBox(mesh, mesh.faces[f])))
            continue;
        near.isNear[f] = 1;
        std::array<VertexIndex, 3> corners;
        for (int k = 0; k < 3; ++k) {
            const int v = mesh.faces[f][k];
            if (local[v] < 0) {
                const Vec3& p = mesh.vertices[v];
                const VertexIndex added = near.surface.add_vertex(Point(p.x(), p.y(), p.z()));
                near.input[added] = v;
                local[v] = static_cast<int>(added.idx());
            }
            corners[k] = VertexIndex(local[v]);
        }
        if (near.surface.add_face(corners[0], corners[1], corners[2]) == SurfaceMesh::null_face())
            return false;
    }
    return near.surface.number_of_faces() > 0;
}

enum Side : signed char { Unknown = -1, Outside = 0, Inside = 1 };

// Whether `p` lies inside the closed surface `mesh`, by the parity of a
// ray's crossings (exact orientation tests); Unknown when every ray tried
// meets an edge, a vertex or a face's plane at `p`.
Side sideOf(const Vec3& p, const TriMesh& mesh) {
    const Eigen::AlignedBox3d box = boundingBox(mesh);
    const double reach = 2.0 * box.diagonal().norm() + (p - box.center()).norm();
    const Point from(p.x(), p.y(), p.z());
    for (int axis = 0; axis < 6; ++axis) {
        Vec3 direction = Vec3::Zero();
        direction[axis / 2] = axis % 2 == 0 ? 1.0 : -1.0;
        const Vec3 end = p + reach * direction;
        const Point to(end.x(), end.y(), end.z());
        Eigen::AlignedBox3d ray(p);
        ray.extend(end);
        int crossings = 0;
        bool degenerate = false;
        for (const auto& face : mesh.faces) {
            if (!ray.intersects(faceBox(mesh, face)))
                continue;
            const Vec3& a0 = mesh.vertices[face[0]];
            const Vec3& b0 = mesh.vertices[face[1]];
            const Vec3& c0 = mesh.vertices[face[2]];
            const Point a(a0.x(), a0.y(), a0.z()), b(b0.x(), b0.y(), b0.z()),
                c(c0.x(), c0.y(), c0.z());
            const CGAL::Orientation sFrom = CGAL::orientation(a, b, c, from);
            const CGAL::Orientation sTo = CGAL::orientation(a, b, c, to);
            if (sFrom == CGAL::COPLANAR || sTo == CGAL::COPLANAR) {
                degenerate = true;
                break;
            }
            if (sFrom == sTo)
                continue;
            const std::array<CGAL::Orientation, 3> around{CGAL::orientation(from, to, a, b),
                                                          CGAL::orientation(from, to, b, c),
                                                          CGAL::orientation(from, to, c, a)};
            const bool anyPositive = std::count(around.begin(), around.end(), CGAL::POSITIVE) > 0;
            const bool anyNegative = std::count(around.begin(), around.end(), CGAL::NEGATIVE) > 0;
            if (anyPositive && anyNegative)
                continue;
            if (std::count(around.begin(), around.end(), CGAL::COPLANAR) > 0) {
                degenerate = true;
                break;
            }
            ++crossings;
        }
        if (!degenerate)
            return crossings % 2 == 1 ? Inside : Outside;
    }
    return Unknown;
}

// The side of `other` each face of the corefined near mesh lies on, or
// nothing when the pieces' sides are not settled consistently. Pieces are
// the faces joined without crossing a loop edge; a piece reaching the near
// mesh's border joins the far faces, which lie outside `other`'s box; a
// loop edge parts pieces on opposite sides; a piece reached by neither is
// told by sideOf one of its vertices that is not on a loop.
std::optional<std::vector<Side>> faceSides(const NearMesh& near, const TriMesh& mesh,
                                           const TriMesh& other) {
    const SurfaceMesh& s = near.surface;
    std::vector<int> piece(s.number_of_faces() + s.number_of_removed_faces(), -1);
    std::vector<Side> sides;
    std::vector<FaceIndex> stack;
    for (FaceIndex seed : s.faces()) {
        if (piece[seed.idx()] >= 0)
            continue;
        const int id = static_cast<int>(sides.size());
        sides.push_back(Unknown);
        piece[seed.idx()] = id;
        stack.push_back(seed);
        while (!stack.empty()) {
            const FaceIndex f = stack.back();
            stack.pop_back();
            for (auto h : CGAL::halfedges_around_face(s.halfedge(f), s)) {
                if (near.onLoop[s.edge(h)])
                    continue;
                const FaceIndex g = s.face(s.opposite(h));
                if (g == SurfaceMesh::null_face()) {
                    sides[id] = Outside;
                } else if (piece[g.idx()] < 0) {
                    piece[g.idx()] = id;
                    stack.push_back(g);
                }
            }
        }
    }
    // Pieces across each loop edge.
    std::vector<std::vector<int>> across(sides.size());
    for (EdgeIndex e : s.edges()) {
        if (!near.onLoop[e])
            continue;
        const FaceIndex f = s.face(s.halfedge(e, 0)), g = s.face(s.halfedge(e, 1));
        if (f == SurfaceMesh::null_face() || g == SurfaceMesh::null_face())
            return std::nullopt;
        const int p = piece[f.idx()], q = piece[g.idx()];
        if (p == q)
            return std::nullopt;
        across[p].push_back(q);
        across[q].push_back(p);
    }
    auto spread = [&](int start) {
        std::vector<int> queue{start};
        while (!queue.empty()) {
            const int p = queue.back();
            queue.pop_back();
            for (int q : across[p]) {
                const Side opposite = sides[p] == Outside ? Inside : Outside;
                if (sides[q] == Unknown) {
                    sides[q] = opposite;
                    queue.push_back(q);
                } else if (sides[q] != opposite) {
                    return false;
                }
            }
        }
        return true;
    };
    for (int p = 0; p < static_cast<int>(sides.size()); ++p)
        if (sides[p] != Unknown && !spread(p))
            return std::nullopt;
    for (int p = 0; p < static_cast<int>(sides.size()); ++p) {
        if (sides[p] != Unknown)
            continue;
        // A vertex of the input off every loop lies strictly on one side.
        std::optional<Vec3> probe;
        for (FaceIndex f : s.faces()) {
            if (piece[f.idx()] != p)
                continue;
            for (auto h : CGAL::halfedges_around_face(s.halfedge(f), s)) {
                const VertexIndex v = s.target(h);
                bool onLoop = near.input[v] < 0;
                for (auto g : CGAL::halfedges_around_target(v, s))
                    onLoop = onLoop || near.onLoop[s.edge(g)];
                if (!onLoop) {
                    probe = mesh.vertices[near.input[v]];
                    break;
                }
            }
            if (probe)
                break;
        }
        if (!probe)
            return std::nullopt;
        sides[p] = sideOf(*probe, other);
        if (sides[p] == Unknown || !spread(p))
            return std::nullopt;
    }
    std::vector<Side> result(piece.size(), Unknown);
    for (FaceIndex f : s.faces())
        result[f.idx()] = sides[piece[f.idx()]];
    return result;
}

bool hasRepeatedPosition(const TriMesh& mesh) {
    std::unordered_set<PointKey, PointKeyHash> seen;
    seen.reserve(mesh.vertices.size());
    for (const Vec3& p : mesh.vertices)
        if (!seen.insert(keyOf(p)).second)
            return true;
    return false;
}

}  // namespace

std::optional<UnionSoup> unionNearOverlap(const TriMesh& first, const TriMesh& second) {
    const std::array<const TriMesh*, 2> inputs{&first, &second};
    // The whole union tells an input vertex by its position (first's before
    // second's, then the lowest index): two at one position in an input
    // could be told apart differently here.
    auto finite = [](const TriMesh& mesh) {
        return std::all_of(mesh.vertices.begin(), mesh.vertices.end(),
                           [](const Vec3& p) { return p.allFinite(); });
    };
    if (!finite(first) || !finite(second) || !isClosedOrientedManifold(first) ||
        !isClosedOrientedManifold(second) || hasRepeatedPosition(first) ||
        hasRepeatedPosition(second))
        return std::nullopt;
    const std::array<Eigen::AlignedBox3d, 2> boxes{boundingBox(first), boundingBox(second)};
    if (!boxes[0].intersects(boxes[1]))
        return std::nullopt;
    std::array<NearMesh, 2> near;
    for (int m = 0; m < 2; ++m)
        if (!buildNearMesh(*inputs[m], boxes[1 - m], near[m]))
            return std::nullopt;

    bool touching = false;
    CrossingsOnlyVisitor visitor;
    visitor.touching = &touching;
    try {
        PMP::corefine(near[0].surface, near[1].surface,
                      params::edge_is_constrained_map(near[0].onLoop)
                          .visitor(visitor)
                          .throw_on_self_intersection(true),
                      params::edge_is_constrained_map(near[1].onLoop));
    } catch (const PMP::Corefinement::Self_intersection_exception&) {
        throw Error(MessageId::MergeSelfIntersecting);
    }
    // No loop: one part inside the other or apart, which the whole union
    // refuses with its own message.
    const auto onLoop = near[0].onLoop;
    const auto edges = near[0].surface.edges();
    if (touching ||
        std::none_of(edges.begin(), edges.end(), [&](EdgeIndex e) { return onLoop[e]; }))
        return std::nullopt;
    std::array<std::vector<Side>, 2> sides;
    for (int m = 0; m < 2; ++m) {
        auto found = faceSides(near[m], *inputs[m], *inputs[1 - m]);
        if (!found)
            return std::nullopt;
        sides[m] = std::move(*found);
    }

    // Candidate vertices: both inputs' (second's after first's), then the
    // loops' new ones; a loop vertex is one candidate for both meshes. Only
    // those the kept faces use are output, below.
    UnionSoup candidates;
    const std::array<int, 2> offset{0, first.vertexCount()};
    for (int m = 0; m < 2; ++m)
        for (int v = 0; v < inputs[m]->vertexCount(); ++v) {
            candidates.positions.push_back(inputs[m]->vertices[v]);
            candidates.sources.push_back(VertexSource::vertex(m, v));
        }
    std::unordered_map<PointKey, int, PointKeyHash> loopVertex;
    std::array<std::vector<int>, 2> output;
    for (int m = 0; m < 2; ++m) {
        const SurfaceMesh& s = near[m].surface;
        output[m].assign(s.number_of_vertices() + s.number_of_removed_vertices(), -1);
        for (EdgeIndex e : s.edges()) {
            if (!near[m].onLoop[e])
                continue;
            for (int end = 0; end < 2; ++end) {
                const VertexIndex v = s.vertex(e, end);
                if (output[m][v.idx()] >= 0)
                    continue;
                const Vec3 p = toVec(s.point(v));
                const int input = near[m].input[v];
                auto [it, added] = loopVertex.try_emplace(keyOf(p), -1);
                if (added) {
                    if (input >= 0) {
                        it->second = offset[m] + input;
                    } else {
                        it->second = static_cast<int>(candidates.positions.size());
                        candidates.positions.push_back(p);
                        candidates.sources.push_back(VertexSource{});
                    }
                } else if (input >= 0 &&
                           candidates.sources[it->second].kind == VertexSource::Kind::New) {
                    candidates.sources[it->second] = VertexSource::vertex(m, input);
                }
                output[m][v.idx()] = it->second;
            }
        }
        for (VertexIndex v : s.vertices())
            if (output[m][v.idx()] < 0) {
                if (near[m].input[v] < 0)
                    return std::nullopt;  // a new vertex off every loop
                output[m][v.idx()] = offset[m] + near[m].input[v];
            }
    }
    std::vector<std::array<int, 3>> faces;
    for (int m = 0; m < 2; ++m) {
        const TriMesh& mesh = *inputs[m];
        for (std::size_t f = 0; f < mesh.faces.size(); ++f)
            if (!near[m].isNear[f])
                faces.push_back({offset[m] + mesh.faces[f][0], offset[m] + mesh.faces[f][1],
                                 offset[m] + mesh.faces[f][2]});
        const SurfaceMesh& s = near[m].surface;
        for (FaceIndex f : s.faces()) {
            if (sides[m][f.idx()] != Outside)
                continue;
            std::array<int, 3> face{};
            int corner = 0;
            for (VertexIndex v : CGAL::vertices_around_face(s.halfedge(f), s))
                face[corner++] = output[m][v.idx()];
            faces.push_back(face);
        }
    }
    std::vector<std::array<int, 2>> loop;
    for (EdgeIndex e : near[0].surface.edges())
        if (near[0].onLoop[e])
            loop.push_back({output[0][near[0].surface.vertex(e, 0).idx()],
                            output[0][near[0].surface.vertex(e, 1).idx()]});

    // Only the vertices the kept faces use.
    std::vector<int> compact(candidates.positions.size(), -1);
    for (const auto& face : faces)
        for (int v : face)
            compact[v] = 0;
    TriMesh result;
    VertexSources sources;
    for (std::size_t v = 0; v < compact.size(); ++v)
        if (compact[v] == 0) {
            compact[v] = result.vertexCount();
            result.vertices.push_back(candidates.positions[v]);
            sources.push_back(candidates.sources[v]);
        }
    for (auto& face : faces)
        for (int& v : face)
            v = compact[v];
    for (auto& edge : loop)
        for (int& v : edge)
            v = compact[v];
    result.faces = std::move(faces);

    // The union's volume lies between the larger input's and their sum; a
    // piece given the wrong side breaks this or the surface.
    const double volumeFirst = signedVolume(first);
    const double volumeSecond = signedVolume(second);
    const double volume = signedVolume(result);
    const double slack = 1e-9 * (std::abs(volumeFirst) + std::abs(volumeSecond));
    if (!(volume >= std::max(volumeFirst, volumeSecond) - slack &&
          volume <= volumeFirst + volumeSecond + slack) ||
        !isClosedOrientedManifold(result))
        return std::nullopt;
    return UnionSoup{std::move(result.vertices), std::move(sources), std::move(result.faces),
                     std::move(loop)};
}

}  // namespace rigmesh
