#include "mesh/MirroredHeightField.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <array>
#include <optional>

#include "mesh/MeshMirror.h"

namespace rigmesh {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point2 = Kernel::Point_2;

enum class Side { Upper, Lower, Neither };

Side sideOf(const TriMesh& mesh, const std::array<int, 3>& face) {
    bool above = false, below = false;
    for (int v : face) {
        const double z = mesh.vertices[v].z();
        above = above || z > 0;
        below = below || z < 0;
    }
    if (above == below)  // both sides, or flat in the plane
        return Side::Neither;
    return above ? Side::Upper : Side::Lower;
}

// The directed edges of the upper faces, packed by their first vertex.
struct DirectedEdges {
    std::vector<int> start, target;
    bool contains(int from, int to) const {
        return std::find(target.begin() + start[from], target.begin() + start[from + 1], to) !=
               target.begin() + start[from + 1];
    }
};

DirectedEdges directedEdges(const TriMesh& mesh, const std::vector<int>& faces) {
    const int n = mesh.vertexCount();
    DirectedEdges edges;
    edges.start.assign(static_cast<std::size_t>(n) + 1, 0);
    for (int i : faces)
        for (int v : mesh.faces[i])
            ++edges.start[v + 1];
    for (int v = 0; v < n; ++v)
        edges.start[v + 1] += edges.start[v];
    edges.target.resize(edges.start[n]);
    std::vector<int> next(edges.start.begin(), edges.start.end() - 1);
    for (int i : faces) {
        const auto& f = mesh.faces[i];
        for (int k = 0; k < 3; ++k)
            edges.target[next[f[k]]++] = f[(k + 1) % 3];
    }
    return edges;
}

// The boundary of the upper faces as one cycle of vertices, or nothing when
// a directed edge is in two of them or the boundary is not one cycle.
std::optional<std::vector<int>> boundaryCycle(const TriMesh& mesh, const DirectedEdges& edges) {
    const int n = mesh.vertexCount();
    std::vector<int> successor(n, -1);
    int boundaryEdges = 0, first = -1;
    for (int v = 0; v < n; ++v)
        for (int k = edges.start[v]; k < edges.start[v + 1]; ++k) {
            const int w = edges.target[k];
            if (std::find(edges.target.begin() + k + 1, edges.target.begin() + edges.start[v + 1],
                          w) != edges.target.begin() + edges.start[v + 1])
                return std::nullopt;  // the edge v -> w in two faces
            if (edges.contains(w, v))
                continue;
            if (successor[v] >= 0)
                return std::nullopt;  // the boundary passes v twice
            successor[v] = w;
            ++boundaryEdges;
            first = v;
        }
    if (boundaryEdges < 3)
        return std::nullopt;
    std::vector<int> cycle;
    cycle.reserve(boundaryEdges);
    int v = first;
    do {
        cycle.push_back(v);
        v = successor[v];
    } while (v >= 0 && v != first && static_cast<int>(cycle.size()) <= boundaryEdges);
    if (v != first || static_cast<int>(cycle.size()) != boundaryEdges)
        return std::nullopt;
    return cycle;
}

// Folds on more than one upper face in this many are left to the pairwise
// test: each upper face's box is compared with every fold's.
constexpr std::size_t kMostFoldedPerFace = 64;

}  // namespace

std::optional<std::vector<int>> mirroredHeightFieldSuspects(const TriMesh& mesh,
                                                            const std::vector<int>& mirror) {
    const std::optional<std::vector<int>> images = mirrorFaceImages(mesh, mirror);
    if (!images)  // also when a face is listed twice (mesh/MeshMirror.h)
        return std::nullopt;
    const int n = mesh.vertexCount();
    for (int v = 0; v < n; ++v)
        if (mesh.vertices[v].z() == 0 && mirror[v] != v)
            return std::nullopt;
    std::vector<int> upper;
    upper.reserve(mesh.faces.size() / 2 + 1);
    for (int i = 0; i < mesh.faceCount(); ++i) {
        const Side side = sideOf(mesh, mesh.faces[i]);
        if (side == Side::Neither)
            return std::nullopt;
        if (side == Side::Upper)
            upper.push_back(i);  // a lower face is the image of one (mirrorFaceImages)
    }
    if (upper.empty())
        return std::nullopt;
    const std::optional<std::vector<int>> cycle = boundaryCycle(mesh, directedEdges(mesh, upper));
    if (!cycle)
        return std::nullopt;
    std::vector<Point2> projected;
    projected.reserve(n);
    for (const Vec3& p : mesh.vertices)
        projected.emplace_back(p.x(), p.y());
    std::vector<Point2> outline;
    outline.reserve(cycle->size());
    for (int v : *cycle)
        outline.push_back(projected[v]);
    // CGAL's sweep with exact predicates: sides meet only where consecutive
    // ones share a corner (a repeated corner or a side turning back along
    // the last one is a crossing).
    if (!CGAL::is_simple_2(outline.begin(), outline.end(), Kernel()))
        return std::nullopt;
    // The faces turning as the outline does cover its inside once over;
    // the others (the folds) are the suspects, with every upper face whose
    // box in the plane meets one of theirs.
    const CGAL::Orientation turn = CGAL::orientation_2(outline.begin(), outline.end(), Kernel());
    std::vector<int> folded;
    for (int i : upper) {
        const auto& f = mesh.faces[i];
        if (CGAL::orientation(projected[f[0]], projected[f[1]], projected[f[2]]) != turn)
            folded.push_back(i);
    }
    std::vector<int> suspects;
    if (folded.empty())
        return suspects;
    if (folded.size() * kMostFoldedPerFace > upper.size())
        return std::nullopt;  // no help: leave it to the pairwise test
    const auto boxOf = [&](int face) {
        const auto& f = mesh.faces[face];
        return projected[f[0]].bbox() + projected[f[1]].bbox() + projected[f[2]].bbox();
    };
    std::vector<CGAL::Bbox_2> foldBoxes;
    for (int i : folded)
        foldBoxes.push_back(boxOf(i));
    for (int i : upper) {
        const CGAL::Bbox_2 box = boxOf(i);
        if (std::any_of(foldBoxes.begin(), foldBoxes.end(),
                        [&](const CGAL::Bbox_2& fold) { return CGAL::do_overlap(box, fold); })) {
            suspects.push_back(i);
            suspects.push_back((*images)[i]);
        }
    }
    std::sort(suspects.begin(), suspects.end());
    return suspects;
}

bool isMirroredHeightField(const TriMesh& mesh, const std::vector<int>& mirror) {
    const std::optional<std::vector<int>> suspects = mirroredHeightFieldSuspects(mesh, mirror);
    return suspects && suspects->empty();
}

}  // namespace rigmesh
