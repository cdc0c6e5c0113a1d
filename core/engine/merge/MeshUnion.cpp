#include "merge/MeshUnion.h"

#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cstring>
#include <deque>
#include <tuple>
#include <unordered_map>

#include "base/Error.h"
#include "mesh/CgalSurfaceMesh.h"

namespace rigmesh {

namespace {

using namespace cgal;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace params = CGAL::parameters;

// Faces with a corner within `rings` edges of a constrained (loop) edge.
std::vector<FaceIndex> facesNearLoop(const SurfaceMesh& mesh,
                                     const SurfaceMesh::Property_map<EdgeIndex, bool>& onLoop,
                                     int rings) {
    std::vector<int> depth(mesh.number_of_vertices(), -1);
    std::deque<VertexIndex> queue;
    for (EdgeIndex e : mesh.edges())
        if (onLoop[e])
            for (int end = 0; end < 2; ++end) {
                const VertexIndex v = mesh.vertex(e, end);
                if (depth[v.idx()] < 0) {
                    depth[v.idx()] = 0;
                    queue.push_back(v);
                }
            }
    while (!queue.empty()) {
        const VertexIndex v = queue.front();
        queue.pop_front();
        if (depth[v.idx()] >= rings)
            continue;
        for (VertexIndex w : CGAL::vertices_around_target(mesh.halfedge(v), mesh))
            if (depth[w.idx()] < 0) {
                depth[w.idx()] = depth[v.idx()] + 1;
                queue.push_back(w);
            }
    }
    std::vector<FaceIndex> faces;
    for (FaceIndex f : mesh.faces())
        for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
            if (depth[v.idx()] >= 0) {
                faces.push_back(f);
                break;
            }
    return faces;
}

// The mesh in an order that depends only on its geometry and sources, not
// on CGAL's internal order (its box intersection sorts by address): input
// vertices by (mesh, index), new ones by position; faces by their corners,
// each starting at its smallest. Recipe replays and undo then give the same
// bytes.
template <typename SourceOf>
MeshUnionResult canonicalResult(const SurfaceMesh& mesh,
                                const SurfaceMesh::Property_map<EdgeIndex, bool>& loopEdges,
                                SourceOf&& sourceOf) {
    struct Entry {
        VertexIndex vertex;
        Vec3 position;
        VertexSource source;
    };
    std::vector<Entry> entries;
    for (VertexIndex v : mesh.vertices()) {
        const Vec3 p = toVec(mesh.point(v));
        entries.push_back({v, p, sourceOf(p)});
    }
    auto rank = [](const Entry& e) {
        const bool copy = e.source.kind == VertexSource::Kind::Vertex;
        return std::make_tuple(copy ? 0 : 1, copy ? e.source.mesh : 0, copy ? e.source.index : 0,
                               e.position.x(), e.position.y(), e.position.z());
    };
    std::sort(entries.begin(), entries.end(),
              [&](const Entry& a, const Entry& b) { return rank(a) < rank(b); });
    std::vector<int> index(mesh.number_of_vertices() + mesh.number_of_removed_vertices(), -1);
    MeshUnionResult result;
    for (const Entry& e : entries) {
        index[e.vertex.idx()] = result.mesh.vertexCount();
        result.mesh.vertices.push_back(e.position);
        result.sources.push_back(e.source);
    }
    for (FaceIndex f : mesh.faces()) {
        std::array<int, 3> face{};
        int corner = 0;
        for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
            face[corner++] = index[v.idx()];
        std::rotate(face.begin(), std::min_element(face.begin(), face.end()), face.end());
        result.mesh.faces.push_back(face);
    }
    std::sort(result.mesh.faces.begin(), result.mesh.faces.end());
    result.onLoop.assign(result.mesh.vertices.size(), 0);
    for (EdgeIndex e : mesh.edges())
        if (loopEdges[e]) {
            const int p = index[mesh.vertex(e, 0).idx()];
            const int q = index[mesh.vertex(e, 1).idx()];
            result.loop.push_back({std::min(p, q), std::max(p, q)});
            result.onLoop[p] = result.onLoop[q] = 1;
        }
    std::sort(result.loop.begin(), result.loop.end());
    return result;
}

}  // namespace

MeshUnionResult unionMeshes(const TriMesh& first, const TriMesh& second, double seamEdgeLength) {
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
    const SourceTriangles sourceTriangles({&first, &second});
    auto sourceOf = [&](const Vec3& p) {
        auto found = inputVertices.find(keyOf(p));
        return found != inputVertices.end() ? found->second : sourceTriangles.sourceOf(p);
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
    if (!(seamEdgeLength > 0.0))
        return result;

    // Remesh the cut faces (paper 3.2.1 glues the meshes by splitting edges;
    // we also even them out) with the loop as a constraint, on the canonical
    // mesh so the result does not depend on CGAL's internal order.
    SurfaceMesh seam;
    for (const Vec3& v : result.mesh.vertices)
        seam.add_vertex(Point(v.x(), v.y(), v.z()));
    for (const auto& [a0, b0, c0] : result.mesh.faces)
        seam.add_face(VertexIndex(a0), VertexIndex(b0), VertexIndex(c0));
    auto seamLoop = seam.add_property_map<EdgeIndex, bool>("e:loop", false).first;
    for (const auto& [p0, q0] : result.loop)
        seamLoop[seam.edge(seam.halfedge(VertexIndex(p0), VertexIndex(q0)))] = true;
    const std::vector<FaceIndex> band = facesNearLoop(seam, seamLoop, 2);
    PMP::isotropic_remeshing(
        band, seamEdgeLength, seam,
        params::number_of_iterations(3).edge_is_constrained_map(seamLoop).protect_constraints(
            false));
    seam.collect_garbage();
    std::unordered_map<PointKey, VertexSource, PointKeyHash> unionVertices;
    for (int v = 0; v < result.mesh.vertexCount(); ++v)
        unionVertices[keyOf(result.mesh.vertices[v])] = result.sources[v];
    int remeshed = 0;
    MeshUnionResult remeshedResult = canonicalResult(seam, seamLoop, [&](const Vec3& p) {
        auto found = unionVertices.find(keyOf(p));
        if (found != unionVertices.end())
            return found->second;
        ++remeshed;
        return sourceTriangles.sourceOf(p);
    });
    remeshedResult.remeshedVertices = remeshed;
    return remeshedResult;
}

}  // namespace rigmesh
