#include "merge/MeshUnion.h"

#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cstring>
#include <numeric>
#include <optional>
#include <tuple>
#include <unordered_map>

#include "base/Error.h"
#include "merge/NearOverlapUnion.h"
#include "mesh/CgalSurfaceMesh.h"
#include "mesh/MeshChecks.h"

namespace rigmesh {

namespace {

using namespace cgal;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace params = CGAL::parameters;

// Each vertex's distance in edges from the loop, up to `rings` (-1 beyond):
// breadth first, one ring per sweep over the faces.
std::vector<int> ringsFromLoop(const TriMesh& mesh, const std::vector<std::array<int, 2>>& loop,
                               int rings) {
    std::vector<int> depth(mesh.vertices.size(), -1);
    for (const auto& [p, q] : loop)
        depth[p] = depth[q] = 0;
    for (int ring = 1; ring <= rings; ++ring)
        for (const auto& face : mesh.faces) {
            const bool touches = depth[face[0]] == ring - 1 || depth[face[1]] == ring - 1 ||
                                 depth[face[2]] == ring - 1;
            if (touches)
                for (int v : face)
                    if (depth[v] < 0)
                        depth[v] = ring;
        }
    return depth;
}

bool hasCornerWithin(const std::array<int, 3>& face, const std::vector<int>& depth, int rings) {
    return std::any_of(face.begin(), face.end(),
                       [&](int v) { return depth[v] >= 0 && depth[v] <= rings; });
}

// cgal::SourceTriangles over only the triangles whose boxes meet `region`
// (each input's faces in their order), reporting the inputs' face indices.
class NearbyTriangles {
  public:
    NearbyTriangles(const std::array<const TriMesh*, 2>& inputs, const Eigen::AlignedBox3d& region)
        : nearby_(select(inputs, region, faces_)), triangles_({&nearby_[0], &nearby_[1]}) {}

    VertexSource sourceOf(const Vec3& p) const {
        VertexSource source = triangles_.sourceOf(p);
        source.index = faces_[source.mesh][source.index];
        return source;
    }

  private:
    static std::array<TriMesh, 2> select(const std::array<const TriMesh*, 2>& inputs,
                                         const Eigen::AlignedBox3d& region,
                                         std::array<std::vector<int>, 2>& faces) {
        std::array<TriMesh, 2> nearby;
        for (int m = 0; m < 2; ++m) {
            const TriMesh& mesh = *inputs[m];
            nearby[m].vertices = mesh.vertices;
            for (int f = 0; f < mesh.faceCount(); ++f) {
                const auto& [a, b, c] = mesh.faces[f];
                Eigen::AlignedBox3d box(mesh.vertices[a]);
                box.extend(mesh.vertices[b]);
                box.extend(mesh.vertices[c]);
                if (region.intersects(box)) {
                    nearby[m].faces.push_back(mesh.faces[f]);
                    faces[m].push_back(f);
                }
            }
        }
        return nearby;
    }

    std::array<std::vector<int>, 2> faces_;  // nearby face -> input face
    std::array<TriMesh, 2> nearby_;
    SourceTriangles triangles_;
};

// The mesh in an order that depends only on its geometry and sources, not
// on CGAL's internal order (its box intersection sorts by address): input
// vertices by (mesh, index), new ones by position; faces by their corners,
// each starting at its smallest. Recipe replays and undo then give the same
// bytes. Faces and loop edges index `positions`.
MeshUnionResult canonicalOrder(const std::vector<Vec3>& positions, const VertexSources& sources,
                               const std::vector<std::array<int, 3>>& faces,
                               const std::vector<std::array<int, 2>>& loop) {
    auto rank = [&](int v) {
        const VertexSource& source = sources[v];
        const Vec3& p = positions[v];
        const bool copy = source.kind == VertexSource::Kind::Vertex;
        return std::make_tuple(copy ? 0 : 1, copy ? source.mesh : 0, copy ? source.index : 0, p.x(),
                               p.y(), p.z());
    };
    std::vector<int> order(positions.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return rank(a) < rank(b); });
    std::vector<int> index(positions.size(), -1);
    MeshUnionResult result;
    result.mesh.vertices.reserve(positions.size());
    result.sources.reserve(positions.size());
    for (int v : order) {
        index[v] = result.mesh.vertexCount();
        result.mesh.vertices.push_back(positions[v]);
        result.sources.push_back(sources[v]);
    }
    result.mesh.faces.reserve(faces.size());
    for (const auto& corners : faces) {
        std::array<int, 3> face{index[corners[0]], index[corners[1]], index[corners[2]]};
        std::rotate(face.begin(), std::min_element(face.begin(), face.end()), face.end());
        result.mesh.faces.push_back(face);
    }
    std::sort(result.mesh.faces.begin(), result.mesh.faces.end());
    result.onLoop.assign(result.mesh.vertices.size(), 0);
    for (const auto& [a, b] : loop) {
        const int p = index[a], q = index[b];
        result.loop.push_back({std::min(p, q), std::max(p, q)});
        result.onLoop[p] = result.onLoop[q] = 1;
    }
    std::sort(result.loop.begin(), result.loop.end());
    return result;
}

// canonicalOrder of a CGAL mesh whose vertices' sources `sourceOf` tells by
// position.
template <typename SourceOf>
MeshUnionResult canonicalResult(const SurfaceMesh& mesh,
                                const SurfaceMesh::Property_map<EdgeIndex, bool>& loopEdges,
                                SourceOf&& sourceOf) {
    std::vector<int> compact(mesh.number_of_vertices() + mesh.number_of_removed_vertices(), -1);
    std::vector<Vec3> positions;
    VertexSources sources;
    for (VertexIndex v : mesh.vertices()) {
        compact[v.idx()] = static_cast<int>(positions.size());
        positions.push_back(toVec(mesh.point(v)));
        sources.push_back(sourceOf(positions.back()));
    }
    std::vector<std::array<int, 3>> faces;
    for (FaceIndex f : mesh.faces()) {
        std::array<int, 3> face{};
        int corner = 0;
        for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
            face[corner++] = compact[v.idx()];
        faces.push_back(face);
    }
    std::vector<std::array<int, 2>> loop;
    for (EdgeIndex e : mesh.edges())
        if (loopEdges[e])
            loop.push_back({compact[mesh.vertex(e, 0).idx()], compact[mesh.vertex(e, 1).idx()]});
    return canonicalOrder(positions, sources, faces, loop);
}

// CGAL's union of the whole surfaces; throws the merge's messages when they
// do not cross or the result is not a manifold.
MeshUnionResult wholeUnion(const TriMesh& first, const TriMesh& second) {
    SurfaceMesh a =
        toSurfaceMesh(first, MessageId::TargetSurfaceNotManifold, MessageId::TargetSurfaceHasHole);
    SurfaceMesh b = toSurfaceMesh(second, MessageId::DraggedSurfaceNotManifold,
                                  MessageId::DraggedSurfaceHasHole);
    SurfaceMesh out;
    auto loopEdges = out.add_property_map<EdgeIndex, bool>("e:loop", false).first;
    bool ok = false;
    try {
        ok = PMP::corefine_and_compute_union(a, b, out, params::throw_on_self_intersection(true),
                                             params::throw_on_self_intersection(true),
                                             params::edge_is_constrained_map(loopEdges));
    } catch (const PMP::Corefinement::Self_intersection_exception&) {
        throw Error(MessageId::MergeSelfIntersecting);
    }
    if (!ok)
        throw Error(MessageId::MergeNotManifold);

    // Where every vertex came from: an unchanged input vertex (bitwise), or
    // a new point on the loop (a point on either input surface).
    std::unordered_map<PointKey, VertexSource, PointKeyHash> inputVertices;
    for (int v = second.vertexCount() - 1; v >= 0; --v)
        inputVertices[keyOf(second.vertices[v])] = VertexSource::vertex(1, v);
    for (int v = first.vertexCount() - 1; v >= 0; --v)
        inputVertices[keyOf(first.vertices[v])] = VertexSource::vertex(0, v);
    // New vertices are ordered by position alone: their triangles are found
    // below, once the region they lie in is known.
    auto sourceOf = [&](const Vec3& p) {
        auto found = inputVertices.find(keyOf(p));
        return found != inputVertices.end() ? found->second : VertexSource{};
    };
    MeshUnionResult result = canonicalResult(out, loopEdges, sourceOf);
    std::array<int, 2> keptFrom{0, 0};
    for (const VertexSource& source : result.sources)
        if (source.kind == VertexSource::Kind::Vertex)
            ++keptFrom[source.mesh];
    if (result.loop.empty()) {
        if (keptFrom[0] > 0 && keptFrom[1] > 0)
            throw Error(MessageId::MergePartsApart);
        throw Error(MessageId::MergePartInside);
    }
    return result;
}

}  // namespace

MeshUnionResult unionMeshes(const TriMesh& first, const TriMesh& second, double seamEdgeLength,
                            UnionScope scope) {
    std::optional<UnionSoup> soup;
    if (scope == UnionScope::NearOverlap)
        soup = unionNearOverlap(first, second);
    MeshUnionResult result =
        soup ? canonicalOrder(soup->positions, soup->sources, soup->faces, soup->loop)
             : wholeUnion(first, second);
    // The closest input triangle of each new vertex: a loop vertex lies on
    // both inputs, a remeshed one on the submesh below (CGAL projects it
    // there), up to rounding; so only triangles whose boxes meet that
    // region's (grown by far more than rounding) can be closest, and the
    // search tree is built over those alone (over both whole parts it was a
    // sixth of a merge).
    auto sourcesWithin = [&](const std::vector<int>& vertices) {
        Eigen::AlignedBox3d region;
        for (int v : vertices)
            region.extend(result.mesh.vertices[v]);
        const Eigen::AlignedBox3d whole = boundingBox(first).merged(boundingBox(second));
        const double margin = 1e-9 * whole.diagonal().norm();
        region.min().array() -= margin;
        region.max().array() += margin;
        return NearbyTriangles({&first, &second}, region);
    };
    auto fillNewSources = [&](const NearbyTriangles& triangles) {
        for (int v = 0; v < result.mesh.vertexCount(); ++v)
            if (result.sources[v].kind == VertexSource::Kind::New)
                result.sources[v] = triangles.sourceOf(result.mesh.vertices[v]);
    };
    if (!(seamEdgeLength > 0.0)) {
        std::vector<int> onLoop;
        for (int v = 0; v < result.mesh.vertexCount(); ++v)
            if (result.onLoop[v])
                onLoop.push_back(v);
        fillNewSources(sourcesWithin(onLoop));
        return result;
    }

    // Remesh the cut faces (paper 3.2.1 glues the meshes by splitting edges;
    // we also even them out) with the loop as a constraint, on the canonical
    // mesh so the result does not depend on CGAL's internal order. CGAL is
    // given only the faces within four rings of the loop, in the canonical
    // order: the band (two rings) plus every face around each band vertex
    // and one ring more, so each step of the remeshing (valences, collapse
    // links, normals, the order of equal-length edges) reads what it reads
    // in the whole mesh, and the result is the same; its tangential
    // relaxation computes the normal of every vertex of the mesh it is given
    // (CGAL 5.5), which on the whole part was most of the remeshing.
    constexpr int kBandRings = 2;
    constexpr int kSubmeshRings = kBandRings + 2;
    const TriMesh& whole = result.mesh;
    const std::vector<int> depth = ringsFromLoop(whole, result.loop, kSubmeshRings);
    std::vector<char> inSubmesh(whole.faces.size(), 0);
    std::vector<int> subVertex(whole.vertices.size(), -1);
    for (std::size_t f = 0; f < whole.faces.size(); ++f)
        if (hasCornerWithin(whole.faces[f], depth, kSubmeshRings)) {
            inSubmesh[f] = 1;
            for (int v : whole.faces[f])
                subVertex[v] = 0;
        }
    SurfaceMesh seam;
    std::vector<int> wholeVertex;  // per submesh vertex
    for (int v = 0; v < whole.vertexCount(); ++v)
        if (subVertex[v] == 0) {
            subVertex[v] = static_cast<int>(wholeVertex.size());
            wholeVertex.push_back(v);
            const Vec3& p = whole.vertices[v];
            seam.add_vertex(Point(p.x(), p.y(), p.z()));
        }
    const NearbyTriangles sourceTriangles = sourcesWithin(wholeVertex);
    fillNewSources(sourceTriangles);
    std::vector<FaceIndex> band;
    for (std::size_t f = 0; f < whole.faces.size(); ++f) {
        if (!inSubmesh[f])
            continue;
        const auto& [a0, b0, c0] = whole.faces[f];
        const FaceIndex face = seam.add_face(VertexIndex(subVertex[a0]), VertexIndex(subVertex[b0]),
                                             VertexIndex(subVertex[c0]));
        if (face == SurfaceMesh::null_face())
            throw Error(MessageId::MergeNotManifold);
        if (hasCornerWithin(whole.faces[f], depth, kBandRings))
            band.push_back(face);
    }
    auto seamLoop = seam.add_property_map<EdgeIndex, bool>("e:loop", false).first;
    for (const auto& [p0, q0] : result.loop)
        seamLoop[seam.edge(seam.halfedge(VertexIndex(subVertex[p0]), VertexIndex(subVertex[q0])))] =
            true;
    PMP::isotropic_remeshing(
        band, seamEdgeLength, seam,
        params::number_of_iterations(3).edge_is_constrained_map(seamLoop).protect_constraints(
            false));

    // The whole mesh again: the faces outside the submesh and their vertices
    // as they were, the submesh's as remeshed.
    std::unordered_map<PointKey, VertexSource, PointKeyHash> unionVertices;
    for (int v : wholeVertex)
        unionVertices[keyOf(whole.vertices[v])] = result.sources[v];
    std::vector<Vec3> positions;
    VertexSources sources;
    std::vector<int> outsideIndex(whole.vertices.size(), -1);
    for (int v = 0; v < whole.vertexCount(); ++v)
        if (subVertex[v] < 0) {
            outsideIndex[v] = static_cast<int>(positions.size());
            positions.push_back(whole.vertices[v]);
            sources.push_back(result.sources[v]);
        }
    std::vector<int> seamIndex(seam.number_of_vertices() + seam.number_of_removed_vertices(), -1);
    int remeshed = 0;
    for (VertexIndex v : seam.vertices()) {
        seamIndex[v.idx()] = static_cast<int>(positions.size());
        positions.push_back(toVec(seam.point(v)));
        auto found = unionVertices.find(keyOf(positions.back()));
        if (found != unionVertices.end()) {
            sources.push_back(found->second);
        } else {
            ++remeshed;
            sources.push_back(sourceTriangles.sourceOf(positions.back()));
        }
    }
    std::vector<std::array<int, 3>> faces;
    faces.reserve(whole.faces.size() + seam.number_of_faces());
    // A face outside may share a corner with the submesh's border, which the
    // remeshing neither moves nor removes (it lies outside the band).
    auto outputIndex = [&](int v) {
        return subVertex[v] >= 0 ? seamIndex[subVertex[v]] : outsideIndex[v];
    };
    for (std::size_t f = 0; f < whole.faces.size(); ++f)
        if (!inSubmesh[f]) {
            const auto& [a0, b0, c0] = whole.faces[f];
            faces.push_back({outputIndex(a0), outputIndex(b0), outputIndex(c0)});
        }
    for (FaceIndex f : seam.faces()) {
        std::array<int, 3> face{};
        int corner = 0;
        for (VertexIndex v : CGAL::vertices_around_face(seam.halfedge(f), seam))
            face[corner++] = seamIndex[v.idx()];
        faces.push_back(face);
    }
    std::vector<std::array<int, 2>> loop;
    for (EdgeIndex e : seam.edges())
        if (seamLoop[e])
            loop.push_back(
                {seamIndex[seam.vertex(e, 0).idx()], seamIndex[seam.vertex(e, 1).idx()]});
    MeshUnionResult remeshedResult = canonicalOrder(positions, sources, faces, loop);
    remeshedResult.remeshedVertices = remeshed;
    return remeshedResult;
}

}  // namespace rigmesh
