#include "cut/SurfaceSplit.h"

#include <CGAL/Polygon_mesh_processing/clip.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>

#include <optional>
#include <unordered_map>

#include "mesh/CgalSurfaceMesh.h"
#include "mesh/MeshChecks.h"

namespace rigmesh {

using namespace cgal;
namespace PMP = CGAL::Polygon_mesh_processing;

namespace {

// The points where the plane crosses the input's edges, each as a point on
// one of the edge's faces: a new vertex of the split is one of them (CGAL
// constructs it in its own arithmetic, so the nearest one is taken). A few
// hundred points, searched linearly: cheaper than a search tree over every
// triangle.
class EdgeCrossings {
  public:
    EdgeCrossings(const TriMesh& mesh, const CutSurface& surface) {
        std::vector<double> side(mesh.vertices.size());
        for (std::size_t v = 0; v < side.size(); ++v)
            side[v] = surface.side(mesh.vertices[v]);
        for (int f = 0; f < mesh.faceCount(); ++f) {
            const auto& face = mesh.faces[f];
            for (int c = 0; c < 3; ++c) {
                const int a = face[c], b = face[(c + 1) % 3];
                if (a > b ||
                    !((side[a] < 0.0 && side[b] > 0.0) || (side[a] > 0.0 && side[b] < 0.0)))
                    continue;  // each edge once (from its face with a < b)
                const double t = side[a] / (side[a] - side[b]);
                Vec3 barycentric = Vec3::Zero();
                barycentric[c] = 1.0 - t;
                barycentric[(c + 1) % 3] = t;
                crossings_.push_back({mesh.vertices[a] + t * (mesh.vertices[b] - mesh.vertices[a]),
                                      VertexSource::triangle(0, f, barycentric)});
            }
        }
    }

    // The crossing nearest to `p`; nullopt if there is none.
    std::optional<VertexSource> sourceOf(const Vec3& p) const {
        const Crossing* best = nullptr;
        double bestDistance = 0.0;
        for (const Crossing& c : crossings_) {
            const double d = (c.point - p).squaredNorm();
            if (!best || d < bestDistance) {
                best = &c;
                bestDistance = d;
            }
        }
        if (!best)
            return std::nullopt;
        return best->source;
    }

  private:
    struct Crossing {
        Vec3 point;
        VertexSource source;
    };
    std::vector<Crossing> crossings_;
};

// The side of the cut surface a piece lies on, judged by the vertices next
// to its holes: a swept surface ends where the stroke was drawn, and beyond
// its ends side() extends the end segments, so only near the cut is the
// side the piece's own (a vertex far away, on a limb the extension would
// cross, may read the other way).
int sideNearHoles(const MeshPiece& piece, const CutSurface& cut) {
    std::vector<char> onHole(piece.mesh.vertices.size(), 0);
    for (const std::vector<int>& loop : piece.holes)
        for (int v : loop)
            onHole[v] = 1;
    double sum = 0.0, farthest = 0.0;
    for (const auto& face : piece.mesh.faces) {
        const bool touches = onHole[face[0]] || onHole[face[1]] || onHole[face[2]];
        for (int v : face) {
            const double d = cut.side(piece.mesh.vertices[v]);
            if (touches && !onHole[v])
                sum += d;
            if (std::abs(d) > std::abs(farthest))
                farthest = d;
        }
    }
    if (sum == 0.0)
        sum = farthest;  // no vertex off the holes beside them: a sliver
    return sum >= 0.0 ? 1 : -1;
}

}  // namespace

std::vector<MeshPiece> splitBySurface(const TriMesh& mesh, const CutSurface& cut) {
    SurfaceMesh surface =
        toSurfaceMesh(mesh, MessageId::PartSurfaceNotManifold, MessageId::PartSurfaceHasHole);
    if (cut.isPlane()) {
        const Vec3& n = cut.planeNormal();
        PMP::split(surface, Kernel::Plane_3(n.x(), n.y(), n.z(), -n.dot(cut.planePoint())));
    } else {
        SurfaceMesh splitter =
            toSurfaceMesh(cut.strip(boundingBox(mesh)), MessageId::CutSurfaceNotManifold);
        PMP::split(surface, splitter);
    }
    std::vector<SurfaceMesh> components;
    PMP::split_connected_components(surface, components);

    std::unordered_map<PointKey, int, PointKeyHash> inputVertex;
    for (int v = mesh.vertexCount() - 1; v >= 0; --v)
        inputVertex[keyOf(mesh.vertices[v])] = v;
    const EdgeCrossings crossings(mesh, cut);

    std::vector<MeshPiece> pieces;
    for (const SurfaceMesh& component : components) {
        MeshPiece piece;
        std::vector<int> index(
            component.number_of_vertices() + component.number_of_removed_vertices(), -1);
        for (VertexIndex v : component.vertices()) {
            const Vec3 p = toVec(component.point(v));
            index[v.idx()] = piece.mesh.vertexCount();
            piece.mesh.vertices.push_back(p);
            auto found = inputVertex.find(keyOf(p));
            if (found != inputVertex.end()) {
                piece.sources.push_back(VertexSource::vertex(0, found->second));
            } else if (auto crossing = crossings.sourceOf(p)) {
                piece.sources.push_back(*crossing);
            } else {
                piece.sources.push_back(SourceTriangles({&mesh}).sourceOf(p));
            }
        }
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
        piece.side = sideNearHoles(piece, cut);
        pieces.push_back(std::move(piece));
    }
    return pieces;
}

}  // namespace rigmesh
