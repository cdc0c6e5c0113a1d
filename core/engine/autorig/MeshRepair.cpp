#include "autorig/MeshRepair.h"

#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <set>
#include <unordered_map>

#include "base/Error.h"
#include "mesh/CgalSurfaceMesh.h"
#include "mesh/MeshChecks.h"
#include "mesh/MeshSelfIntersections.h"

namespace rigmesh {

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using cgal::FaceIndex;
using cgal::Point;
using cgal::SurfaceMesh;
using cgal::VertexIndex;
using Polygon = std::array<std::size_t, 3>;
using SourceMap = SurfaceMesh::Property_map<VertexIndex, int>;

// Raised inside the repair when the mesh cannot be made one clean piece.
struct Unrepairable {
    Message reason;
};

template <class... Args>
Unrepairable unrepairable(MessageId id, const Args&... args) {
    return {Message{id, {messageArgument(args)...}}};
}

struct Soup {
    std::vector<Point> points;
    std::vector<int> source;  // per point: its input vertex
    std::vector<Polygon> polygons;
};

// Coincident vertices become one (stitching split seams), then faces with a
// repeated corner and second copies of a face go, then unused vertices.
Soup weldedSoup(const TriMesh& input, std::vector<Message>& repairs) {
    std::unordered_map<cgal::PointKey, int, cgal::PointKeyHash> firstAt;
    std::vector<int> welded(input.vertices.size());
    int joined = 0;
    for (int v = 0; v < input.vertexCount(); ++v) {
        const auto [it, inserted] = firstAt.emplace(cgal::keyOf(input.vertices[v]), v);
        welded[v] = it->second;
        joined += inserted ? 0 : 1;
    }
    if (joined > 0)
        repairs.push_back({MessageId::AutoRigRepairWelded, {messageArgument(joined)}});

    std::vector<std::array<int, 3>> faces;
    std::set<std::array<int, 3>> seen;
    int repeatedCorner = 0, duplicates = 0;
    for (const auto& face : input.faces) {
        const std::array<int, 3> f{welded[face[0]], welded[face[1]], welded[face[2]]};
        if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2]) {
            ++repeatedCorner;
            continue;
        }
        std::array<int, 3> key = f;
        std::sort(key.begin(), key.end());
        if (!seen.insert(key).second) {
            ++duplicates;
            continue;
        }
        faces.push_back(f);
    }
    if (repeatedCorner > 0)
        repairs.push_back({MessageId::AutoRigRepairDegenerate, {messageArgument(repeatedCorner)}});
    if (duplicates > 0)
        repairs.push_back({MessageId::AutoRigRepairDuplicateFaces, {messageArgument(duplicates)}});

    Soup soup;
    std::vector<int> index(input.vertices.size(), -1);
    for (const auto& face : faces)
        for (int corner : face)
            if (index[corner] < 0) {
                index[corner] = static_cast<int>(soup.points.size());
                const Vec3& p = input.vertices[corner];
                soup.points.emplace_back(p.x(), p.y(), p.z());
                soup.source.push_back(corner);
            }
    const int unused = input.vertexCount() - joined - static_cast<int>(soup.points.size());
    if (unused > 0)
        repairs.push_back({MessageId::AutoRigRepairUnusedVertices, {messageArgument(unused)}});
    for (const auto& face : faces)
        soup.polygons.push_back({static_cast<std::size_t>(index[face[0]]),
                                 static_cast<std::size_t>(index[face[1]]),
                                 static_cast<std::size_t>(index[face[2]])});
    return soup;
}

// A vertex without a source (a copy CGAL made) takes the source of the
// vertex at its position.
void fillCopiedSources(const SurfaceMesh& mesh, SourceMap sources,
                       const std::unordered_map<cgal::PointKey, int, cgal::PointKeyHash>& byPoint) {
    for (VertexIndex v : mesh.vertices())
        if (sources[v] < 0) {
            const auto it = byPoint.find(cgal::keyOf(cgal::toVec(mesh.point(v))));
            if (it != byPoint.end())
                sources[v] = it->second;
        }
}

double boundingDiagonal(const SurfaceMesh& mesh) {
    Eigen::AlignedBox3d box;
    for (VertexIndex v : mesh.vertices())
        box.extend(cgal::toVec(mesh.point(v)));
    return box.isEmpty() ? 0.0 : box.diagonal().norm();
}

// Fills the holes whose border is short against the model; refuses the
// first large one.
void fillSmallHoles(SurfaceMesh& mesh, const MeshRepairOptions& options,
                    std::vector<Message>& repairs) {
    std::vector<SurfaceMesh::Halfedge_index> borders;
    PMP::extract_boundary_cycles(mesh, std::back_inserter(borders));
    if (borders.empty())
        return;
    const double diagonal = boundingDiagonal(mesh);
    double edgeSum = 0.0;
    for (auto e : mesh.edges())
        edgeSum += std::sqrt(
            CGAL::squared_distance(mesh.point(mesh.vertex(e, 0)), mesh.point(mesh.vertex(e, 1))));
    const double meanEdge =
        edgeSum / static_cast<double>(std::max<std::size_t>(1, mesh.number_of_edges()));
    const double limit =
        std::max(options.smallHoleEdges * meanEdge, options.smallHoleFraction * diagonal);
    for (auto h : borders) {
        double length = 0.0;
        int edges = 0;
        for (auto b : CGAL::halfedges_around_face(h, mesh)) {
            length += std::sqrt(
                CGAL::squared_distance(mesh.point(mesh.source(b)), mesh.point(mesh.target(b))));
            ++edges;
        }
        if (length > limit)
            throw unrepairable(MessageId::AutoRigOpenBorder, static_cast<int>(borders.size()),
                               edges);
    }
    int newVertices = 0;
    for (auto h : borders) {
        std::vector<FaceIndex> faces;
        std::vector<VertexIndex> vertices;
        PMP::triangulate_refine_and_fair_hole(mesh, h, std::back_inserter(faces),
                                              std::back_inserter(vertices));
        newVertices += static_cast<int>(vertices.size());
    }
    repairs.push_back(
        {MessageId::AutoRigRepairHoles,
         {messageArgument(static_cast<int>(borders.size())), messageArgument(newVertices)}});
}

// `mesh` without garbage: its vertex indices run 0 .. n-1.
RepairedMesh toRepaired(const SurfaceMesh& mesh, SourceMap sources) {
    RepairedMesh result;
    for (VertexIndex v : mesh.vertices()) {
        result.mesh.vertices.push_back(cgal::toVec(mesh.point(v)));
        result.sourceVertex.push_back(sources[v]);
    }
    for (FaceIndex f : mesh.faces()) {
        std::array<int, 3> face{};
        int corner = 0;
        for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
            face[corner++] = static_cast<int>(v.idx());
        result.mesh.faces.push_back(face);
    }
    return result;
}

RepairedMesh repaired(const TriMesh& input, const MeshRepairOptions& options) {
    std::vector<Message> repairs;
    Soup soup = weldedSoup(input, repairs);
    if (soup.polygons.size() < 4)
        throw unrepairable(MessageId::AutoRigTooFewFaces, static_cast<int>(soup.polygons.size()));
    std::unordered_map<cgal::PointKey, int, cgal::PointKeyHash> sourceAt;
    for (std::size_t p = 0; p < soup.points.size(); ++p)
        sourceAt.emplace(cgal::keyOf(cgal::toVec(soup.points[p])), soup.source[p]);

    // Orienting the soup copies the points where sheets touch at a vertex or
    // where more than two faces share an edge, so that it becomes a manifold.
    const std::size_t pointsBefore = soup.points.size();
    PMP::orient_polygon_soup(soup.points, soup.polygons);
    const int splitBySoup = static_cast<int>(soup.points.size() - pointsBefore);

    SurfaceMesh mesh;
    PMP::polygon_soup_to_polygon_mesh(soup.points, soup.polygons, mesh);
    SourceMap sources = mesh.add_property_map<VertexIndex, int>("v:source", -1).first;
    for (VertexIndex v : mesh.vertices())
        if (static_cast<std::size_t>(v) < soup.source.size())
            sources[v] = soup.source[v];
    const int splitByMesh = static_cast<int>(PMP::duplicate_non_manifold_vertices(mesh));
    fillCopiedSources(mesh, sources, sourceAt);
    if (splitBySoup + splitByMesh > 0)
        repairs.push_back(
            {MessageId::AutoRigRepairNonManifold, {messageArgument(splitBySoup + splitByMesh)}});

    // Faces without area (collinear corners): collapsed or flipped away.
    const int facesBefore = static_cast<int>(mesh.number_of_faces());
    PMP::remove_degenerate_faces(mesh);
    mesh.collect_garbage();
    const int degenerate = facesBefore - static_cast<int>(mesh.number_of_faces());
    if (degenerate > 0)
        repairs.push_back({MessageId::AutoRigRepairDegenerate, {messageArgument(degenerate)}});
    if (mesh.number_of_faces() < 4)
        throw unrepairable(MessageId::AutoRigTooFewFaces, static_cast<int>(mesh.number_of_faces()));

    // Pieces are counted before the holes are filled, so a piece is never
    // filled shut only to be refused.
    auto componentOf = mesh.add_property_map<FaceIndex, std::size_t>("f:component", 0).first;
    const std::size_t pieces = PMP::connected_components(mesh, componentOf);
    if (pieces > 1)
        throw unrepairable(MessageId::AutoRigSeveralPieces, static_cast<int>(pieces));

    fillSmallHoles(mesh, options, repairs);
    if (!CGAL::is_closed(mesh))
        throw unrepairable(MessageId::AutoRigNotManifold);
    if (!PMP::is_outward_oriented(mesh)) {
        PMP::reverse_face_orientations(mesh);
        repairs.push_back({MessageId::AutoRigRepairFlipped, {}});
    }
    mesh.collect_garbage();

    RepairedMesh result = toRepaired(mesh, sources);
    const MeshReport report = analyseMesh(result.mesh, true);
    if (!report.isManifold() || !report.isClosed())
        throw unrepairable(MessageId::AutoRigNotManifold);
    if (report.selfIntersectingFacePairs > 0)
        throw unrepairable(MessageId::AutoRigSelfIntersecting, report.selfIntersectingFacePairs);
    result.repairs = std::move(repairs);
    return result;
}

}  // namespace

bool fitForRigging(const TriMesh& mesh) {
    const MeshReport report = analyseMesh(mesh, true);
    if (!report.isClosed() || !report.isManifold() || !report.isOutwardOriented() ||
        report.components != 1 || report.degenerateFaces > 0 ||
        report.selfIntersectingFacePairs > 0)
        return false;
    std::vector<char> used(mesh.vertices.size(), 0);
    std::set<std::array<int, 3>> seen;
    for (auto face : mesh.faces) {
        for (int corner : face)
            used[corner] = 1;
        std::sort(face.begin(), face.end());
        if (!seen.insert(face).second)
            return false;
    }
    return std::all_of(used.begin(), used.end(), [](char u) { return u != 0; });
}

RepairAttempt repairForRigging(const TriMesh& input, const MeshRepairOptions& options) {
    try {
        return {repaired(input, options), {}};
    } catch (const Unrepairable& failure) {
        return {std::nullopt, failure.reason};
    } catch (const std::exception&) {
        // A CGAL precondition a broken mesh violates: the proxy takes it.
        return {std::nullopt, Message{MessageId::AutoRigNotManifold, {}}};
    }
}

}  // namespace rigmesh
