#include "cut/SurfaceSplit.h"

#include <CGAL/Polygon_mesh_processing/clip.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>

#include <algorithm>
#include <cstring>
#include <optional>

#include "cut/CutBand.h"
#include "cut/SurfaceSplitCgal.h"
#include "mesh/CgalClosedSurface.h"
#include "mesh/MeshChecks.h"

namespace rigmesh {

using namespace cgal;
namespace PMP = CGAL::Polygon_mesh_processing;

namespace {

// The corners of the faces marked in `faces` (nothing when none are marked
// at all: the whole surface).
std::vector<char> cornersOf(const TriMesh& mesh, const std::vector<char>& faces) {
    if (faces.empty())
        return {};
    std::vector<char> corner(mesh.vertices.size(), 0);
    for (int f = 0; f < mesh.faceCount(); ++f)
        if (faces[f])
            for (int v : mesh.faces[f])
                corner[v] = 1;
    return corner;
}

// The points where the plane crosses the input's edges, each as a point on
// one of the edge's faces: a new vertex of the split is one of them (CGAL
// constructs it in its own arithmetic, so the nearest one is taken). A few
// hundred points, searched linearly: cheaper than a search tree over every
// triangle. `bandFaces`, when not empty, marks the only faces whose edges the
// split may have crossed (the band's, cut/CutBand.h), and `bandCorners`
// their corners: the cut surface's side (a search along a swept stroke) is
// then taken there only.
class EdgeCrossings {
  public:
    EdgeCrossings(const TriMesh& mesh, const CutSurface& surface,
                  const std::vector<char>& bandFaces, const std::vector<char>& bandCorners) {
        const auto considered = [&](int f) { return bandFaces.empty() || bandFaces[f]; };
        std::vector<double> side(mesh.vertices.size(), 0.0);
        for (std::size_t v = 0; v < side.size(); ++v)
            if (bandCorners.empty() || bandCorners[v])
                side[v] = surface.side(mesh.vertices[v]);
        for (int f = 0; f < mesh.faceCount(); ++f) {
            if (!considered(f))
                continue;
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

// The input's vertices by exact position (the lowest index for each): an
// unchanged vertex of a piece is the input vertex at its position. Open
// addressing over the bits of the position: a node-based map's allocation
// per vertex was a fifteenth of a cut (perf on bench_merge).
// `kept`, when not empty, marks the only vertices looked up.
class InputPositions {
  public:
    explicit InputPositions(const std::vector<Vec3>& points, const std::vector<char>& kept = {})
        : points_(points) {
        const std::size_t count =
            kept.empty() ? points.size()
                         : static_cast<std::size_t>(std::count(kept.begin(), kept.end(), 1));
        std::size_t size = 16;
        while (size < 2 * count)
            size <<= 1;
        slots_.assign(size, -1);
        mask_ = size - 1;
        for (int v = 0; v < static_cast<int>(points.size()); ++v) {
            if (!kept.empty() && !kept[v])
                continue;
            std::size_t i = PointKeyHash{}(keyOf(points[v])) & mask_;
            while (slots_[i] >= 0 && !sameBits(points[slots_[i]], points[v]))
                i = (i + 1) & mask_;
            if (slots_[i] < 0)
                slots_[i] = v;
        }
    }

    // The input vertex at exactly `p`; -1 if there is none.
    int find(const Vec3& p) const {
        for (std::size_t i = PointKeyHash{}(keyOf(p)) & mask_; slots_[i] >= 0; i = (i + 1) & mask_)
            if (sameBits(points_[slots_[i]], p))
                return slots_[i];
        return -1;
    }

    static bool sameBits(const Vec3& a, const Vec3& b) {
        return std::memcmp(a.data(), b.data(), 3 * sizeof(double)) == 0;
    }

  private:
    const std::vector<Vec3>& points_;
    std::vector<int> slots_;
    std::size_t mask_ = 0;
};

// Which input vertex a piece's point is, if any. Without the band: the input
// vertex at its exact position (the lowest index). With the band's read-off
// (each point's vertex on the whole surface, whose vertex i is input vertex
// i, mesh/CgalClosedSurface.h): a vertex the split kept is itself (not the
// lowest index at its position, where two input vertices share one); a new
// one is an input vertex only where CGAL copied a vertex lying on the cut
// (split_along_edges, CGAL 5.5 Polygon_mesh_processing/clip.h) or rounded
// an intersection onto a corner, both corners of band faces, the only
// vertices looked up then.
class InputVertexFinder {
  public:
    // `bandCorners`: the band's corners (cornersOf), empty without the band.
    InputVertexFinder(const TriMesh& mesh, const std::vector<char>& bandCorners)
        : mesh_(mesh), positions_(mesh.vertices, bandCorners), band_(!bandCorners.empty()) {}

    // `wholeVertex`: the point's vertex on the whole surface, or -1.
    int find(const Vec3& p, int wholeVertex) const {
        if (band_ && wholeVertex >= 0 && wholeVertex < mesh_.vertexCount() &&
            InputPositions::sameBits(mesh_.vertices[wholeVertex], p))
            return wholeVertex;
        return positions_.find(p);
    }

  private:
    const TriMesh& mesh_;
    InputPositions positions_;
    bool band_;
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
    double sum = 0.0;
    for (const auto& face : piece.mesh.faces) {
        if (!onHole[face[0]] && !onHole[face[1]] && !onHole[face[2]])
            continue;
        for (int v : face)
            if (!onHole[v])
                sum += cut.side(piece.mesh.vertices[v]);
    }
    if (sum == 0.0) {
        // No vertex off the holes beside them (a sliver): the farthest
        // vertex's side.
        double farthest = 0.0;
        for (const auto& face : piece.mesh.faces)
            for (int v : face) {
                const double d = cut.side(piece.mesh.vertices[v]);
                if (std::abs(d) > std::abs(farthest))
                    farthest = d;
            }
        sum = farthest;
    }
    return sum >= 0.0 ? 1 : -1;
}

// What CGAL's PMP::split(tm, plane) corefines tm with (CGAL 5.5,
// Polygon_mesh_processing/clip.h): the plane clipped to tm's box, enlarged
// by 1 (or 1% of its size) each way; for a swept cut, the strip. nullopt:
// the plane misses the box (PMP::split leaves tm as it is).
std::optional<SurfaceMesh> splitterOf(const TriMesh& mesh, const SurfaceMesh& surface,
                                      const CutSurface& cut) {
    if (!cut.isPlane())
        return toSurfaceMesh(cut.strip(boundingBox(mesh)), MessageId::CutSurfaceNotManifold);
    const Vec3& n = cut.planeNormal();
    const Kernel::Plane_3 plane(n.x(), n.y(), n.z(), -n.dot(cut.planePoint()));
    CGAL::Bbox_3 box = PMP::bbox(surface);
    const double xd = std::max(1., 0.01 * (box.xmax() - box.xmin()));
    const double yd = std::max(1., 0.01 * (box.ymax() - box.ymin()));
    const double zd = std::max(1., 0.01 * (box.zmax() - box.zmin()));
    box = CGAL::Bbox_3(box.xmin() - xd, box.ymin() - yd, box.zmin() - zd, box.xmax() + xd,
                       box.ymax() + yd, box.zmax() + zd);
    SurfaceMesh splitter;
    if (PMP::internal::clip_to_bbox(plane, box, splitter, CGAL::parameters::default_values()) !=
        CGAL::ON_ORIENTED_BOUNDARY)
        return std::nullopt;
    return splitter;
}

// The whole surface split by CGAL (nothing to split without a splitter: the
// plane misses the box), its pieces copied out by split_connected_components.
std::vector<SplitComponent> splitWhole(SurfaceMesh& surface, std::optional<SurfaceMesh>& splitter) {
    if (splitter)
        splitAlong(surface, *splitter);
    std::vector<SurfaceMesh> meshes;
    PMP::split_connected_components(surface, meshes);

    std::vector<SplitComponent> components;
    for (const SurfaceMesh& component : meshes) {
        SplitComponent out;
        std::vector<int> index(
            component.number_of_vertices() + component.number_of_removed_vertices(), -1);
        for (VertexIndex v : component.vertices()) {
            index[v.idx()] = static_cast<int>(out.points.size());
            out.points.push_back(toVec(component.point(v)));
        }
        for (FaceIndex f : component.faces()) {
            std::array<int, 3> face{};
            int corner = 0;
            for (VertexIndex v : CGAL::vertices_around_face(component.halfedge(f), component))
                face[corner++] = index[v.idx()];
            out.faces.push_back(face);
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
            out.holes.push_back(std::move(loop));
        }
        components.push_back(std::move(out));
    }
    return components;
}

}  // namespace

std::vector<MeshPiece> splitBySurface(const TriMesh& mesh, const CutSurface& cut,
                                      SplitMethod method, SplitReport* report) {
    // Built directly when the input is a closed manifold (the same surface as
    // add_face's, mesh/CgalClosedSurface.h); otherwise add_face names what
    // it is not.
    std::optional<SurfaceMesh> closed = closedSurfaceMesh(mesh);
    return splitBySurface(mesh,
                          closed ? std::move(*closed)
                                 : toSurfaceMesh(mesh, MessageId::PartSurfaceNotManifold,
                                                 MessageId::PartSurfaceHasHole),
                          cut, method, report);
}

std::vector<MeshPiece> splitBySurface(const TriMesh& mesh, SurfaceMesh surface,
                                      const CutSurface& cut, SplitMethod method,
                                      SplitReport* report) {
    SplitReport local;
    local.faces = mesh.faceCount();
    std::vector<SplitComponent> components;
    std::vector<char> bandFaces;  // empty: the whole surface was split
    // Left as it is by the band's split (splitAlong), so the whole split can
    // use it too.
    std::optional<SurfaceMesh> splitter = splitterOf(mesh, surface, cut);
    if (method == SplitMethod::Band) {
        if (splitter) {
            BandOutcome band = splitInBand(surface, *splitter);
            local.bandFaces = band.bandFaces;
            if (band.components) {
                components = std::move(*band.components);
                bandFaces = std::move(band.inBand);
                local.band = true;
            } else {
                local.fallback = band.whyNot;
            }
        } else {
            local.fallback = "the plane misses the part's box";
        }
    }
    if (!local.band)
        components = splitWhole(surface, splitter);
    if (report)
        *report = local;

    const std::vector<char> bandCorners = cornersOf(mesh, bandFaces);
    const InputVertexFinder inputVertex(mesh, bandCorners);
    const EdgeCrossings crossings(mesh, cut, bandFaces, bandCorners);

    std::vector<MeshPiece> pieces;
    for (SplitComponent& component : components) {
        MeshPiece piece;
        piece.mesh.vertices = std::move(component.points);
        for (std::size_t i = 0; i < piece.mesh.vertices.size(); ++i) {
            const Vec3& p = piece.mesh.vertices[i];
            const int wholeVertex =
                i < component.wholeVertex.size() ? component.wholeVertex[i] : -1;
            if (const int found = inputVertex.find(p, wholeVertex); found >= 0) {
                piece.sources.push_back(VertexSource::vertex(0, found));
            } else if (auto crossing = crossings.sourceOf(p)) {
                piece.sources.push_back(*crossing);
            } else {
                piece.sources.push_back(SourceTriangles({&mesh}).sourceOf(p));
            }
        }
        piece.mesh.faces = std::move(component.faces);
        piece.holes = std::move(component.holes);
        piece.side = sideNearHoles(piece, cut);
        pieces.push_back(std::move(piece));
    }
    return pieces;
}

}  // namespace rigmesh
