#include "cut/PlaneSplit.h"

#include <CGAL/Polygon_mesh_processing/clip.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>

#include <unordered_map>

#include "mesh/CgalSurfaceMesh.h"

namespace rigmesh {

using namespace cgal;
namespace PMP = CGAL::Polygon_mesh_processing;

std::vector<MeshPiece> splitByPlane(const TriMesh& mesh, const Vec3& point, const Vec3& normal) {
    SurfaceMesh surface = toSurfaceMesh(mesh, "the part");
    const Vec3 n = normal.normalized();
    PMP::split(surface, Kernel::Plane_3(n.x(), n.y(), n.z(), -n.dot(point)));
    std::vector<SurfaceMesh> components;
    PMP::split_connected_components(surface, components);

    std::unordered_map<PointKey, int, PointKeyHash> inputVertex;
    for (int v = mesh.vertexCount() - 1; v >= 0; --v)
        inputVertex[keyOf(mesh.vertices[v])] = v;
    const SourceTriangles sourceTriangles({&mesh});

    std::vector<MeshPiece> pieces;
    for (const SurfaceMesh& component : components) {
        MeshPiece piece;
        std::vector<int> index(
            component.number_of_vertices() + component.number_of_removed_vertices(), -1);
        double farthest = 0.0;
        for (VertexIndex v : component.vertices()) {
            const Vec3 p = toVec(component.point(v));
            index[v.idx()] = piece.mesh.vertexCount();
            piece.mesh.vertices.push_back(p);
            auto found = inputVertex.find(keyOf(p));
            piece.sources.push_back(found != inputVertex.end()
                                        ? VertexSource::vertex(0, found->second)
                                        : sourceTriangles.sourceOf(p));
            const double d = n.dot(p - point);
            if (std::abs(d) > std::abs(farthest))
                farthest = d;
        }
        piece.side = farthest >= 0.0 ? 1 : -1;
        for (FaceIndex f : component.faces()) {
            std::array<int, 3> face{};
            int corner = 0;
            for (VertexIndex v : CGAL::vertices_around_face(component.halfedge(f), component))
                face[corner++] = index[v.idx()];
            piece.mesh.faces.push_back(face);
        }
        // Border halfedges run against the faces; a loop followed by next()
        // on the border is the order a filling patch must use.
        std::vector<char> seen(
            component.number_of_halfedges() + component.number_of_removed_halfedges(), 0);
        for (auto h : component.halfedges()) {
            if (!component.is_border(h) || seen[h.idx()])
                continue;
            std::vector<int> loop;
            auto g = h;
            do {
                seen[g.idx()] = 1;
                loop.push_back(index[component.source(g).idx()]);
                g = component.next(g);
            } while (g != h);
            piece.holes.push_back(std::move(loop));
        }
        pieces.push_back(std::move(piece));
    }
    return pieces;
}

}  // namespace rigmesh
