#include "geometry/ConstrainedTriangulation.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <deque>
#include <map>

#include "base/Error.h"

namespace rigmesh {
namespace {

struct VertexIndex {
    int value = -1;  // index into the caller's point list; -1 until assigned
};

struct FaceInfo {
    int nestingLevel = -1;
    int index = -1;
    bool inDomain() const { return nestingLevel % 2 == 1; }
};

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<VertexIndex, Kernel>;
using ConstrainedFaceBase = CGAL::Constrained_triangulation_face_base_2<Kernel>;
using FaceBase = CGAL::Triangulation_face_base_with_info_2<FaceInfo, Kernel, ConstrainedFaceBase>;
using DataStructure = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
// Crossing constraints mean a self-intersecting polygon: make CGAL throw.
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, DataStructure,
                                                       CGAL::No_constraint_intersection_tag>;
using Point = Kernel::Point_2;

constexpr int kNoIndex = -1;

// Flood fill from the infinite face: a face is inside the polygon when an odd
// number of constraints separates it from infinity (CGAL's "mark domains").
void markDomains(Cdt& cdt) {
    for (auto f : cdt.all_face_handles())
        f->info().nestingLevel = -1;
    std::deque<std::pair<Cdt::Face_handle, int>> queue{{cdt.infinite_face(), 0}};
    std::deque<std::pair<Cdt::Face_handle, int>> nextLevel;
    while (!queue.empty()) {
        while (!queue.empty()) {
            auto [face, level] = queue.front();
            queue.pop_front();
            if (face->info().nestingLevel != -1)
                continue;
            face->info().nestingLevel = level;
            for (int i = 0; i < 3; ++i) {
                auto neighbor = face->neighbor(i);
                if (neighbor->info().nestingLevel != -1)
                    continue;
                if (cdt.is_constrained({face, i}))
                    nextLevel.emplace_back(neighbor, level + 1);
                else
                    queue.emplace_back(neighbor, level);
            }
        }
        std::swap(queue, nextLevel);
    }
}

Cdt::Vertex_handle insertIndexed(Cdt& cdt, const Vec2& p, int index) {
    auto vertex = cdt.insert(Point(p.x(), p.y()));
    if (vertex->info().value != kNoIndex && vertex->info().value != index)
        throw Error(MessageId::OutlineTouchesItself, std::to_string(p.x()), std::to_string(p.y()));
    vertex->info().value = index;
    return vertex;
}

// Inserts the closed loop as constraints; throws rigmesh::Error on crossings.
std::vector<Cdt::Vertex_handle> insertLoop(Cdt& cdt, const std::vector<Vec2>& loop) {
    std::vector<Cdt::Vertex_handle> handles;
    handles.reserve(loop.size());
    for (std::size_t i = 0; i < loop.size(); ++i)
        handles.push_back(insertIndexed(cdt, loop[i], static_cast<int>(i)));
    try {
        for (std::size_t i = 0; i < handles.size(); ++i)
            cdt.insert_constraint(handles[i], handles[(i + 1) % handles.size()]);
    } catch (const Cdt::Intersection_of_constraints_exception&) {
        throw Error(MessageId::OutlineCrossesItself);
    }
    return handles;
}

}  // namespace

PolygonTriangulation triangulatePolygon(const std::vector<Vec2>& polygon) {
    if (polygon.size() < 3)
        throw Error(MessageId::OutlineTooFewPoints);
    Cdt cdt;
    insertLoop(cdt, polygon);
    if (cdt.number_of_vertices() != polygon.size())
        throw Error(MessageId::OutlineRepeatedPoints);
    markDomains(cdt);

    PolygonTriangulation result;
    result.points = polygon;
    int count = 0;
    for (auto face : cdt.finite_face_handles())
        if (face->info().inDomain())
            face->info().index = count++;
    result.triangles.reserve(count);
    result.neighbors.reserve(count);
    for (auto face : cdt.finite_face_handles()) {
        if (!face->info().inDomain())
            continue;
        std::array<int, 3> corners{}, across{};
        for (int k = 0; k < 3; ++k) {
            corners[k] = face->vertex(k)->info().value;
            auto neighbor = face->neighbor(k);
            bool interior = !cdt.is_constrained({face, k}) && !cdt.is_infinite(neighbor) &&
                            neighbor->info().inDomain();
            across[k] = interior ? neighbor->info().index : -1;
        }
        result.triangles.push_back(corners);
        result.neighbors.push_back(across);
    }
    if (result.triangles.empty())
        throw Error(MessageId::OutlineNoArea);

    return result;
}

PatchTriangulation triangulatePatch(const std::vector<Vec2>& boundary,
                                    const std::vector<Vec2>& interiorPoints,
                                    const std::vector<bool>& isRimPoint) {
    if (boundary.size() < 3)
        throw Error(MessageId::PatchBoundaryTooShort);
    Cdt cdt;
    insertLoop(cdt, boundary);
    markDomains(cdt);

    PatchTriangulation result;
    result.points = boundary;
    // Keep the interior points that fall inside the domain, then insert them.
    // Each search starts where the previous one ended: the lattice comes row
    // by row, so the walks stay short (from an arbitrary face each would
    // cross about sqrt(n) faces, n^1.5 in all).
    std::vector<Vec2> inside;
    Cdt::Face_handle hint;
    for (const Vec2& p : interiorPoints) {
        hint = cdt.locate(Point(p.x(), p.y()), hint);
        if (!cdt.is_infinite(hint) && hint->info().inDomain())
            inside.push_back(p);
    }
    Cdt::Face_handle insertHint;
    auto insertNew = [&](const Vec2& p) {
        auto vertex = cdt.insert(Point(p.x(), p.y()), insertHint);
        insertHint = vertex->face();
        if (vertex->info().value != kNoIndex)
            return;  // coincides with an existing point
        vertex->info().value = static_cast<int>(result.points.size());
        result.points.push_back(p);
    };
    for (const Vec2& p : inside)
        insertNew(p);
    markDomains(cdt);

    // Split interior edges that join two rim points: mirrored, such an edge
    // would be shared by four faces (paper 2.2 builds both halves this way).
    auto isRim = [&](int index) {
        return index < static_cast<int>(isRimPoint.size()) && isRimPoint[index];
    };
    for (int pass = 0; pass < 8; ++pass) {
        std::vector<Vec2> midpoints;
        for (auto edge : cdt.finite_edges()) {
            auto face = edge.first;
            int i = edge.second;
            auto mirror = face->neighbor(i);
            if (cdt.is_constrained(edge))
                continue;
            if (!face->info().inDomain() && (cdt.is_infinite(mirror) || !mirror->info().inDomain()))
                continue;
            int a = face->vertex(Cdt::cw(i))->info().value;
            int b = face->vertex(Cdt::ccw(i))->info().value;
            if (isRim(a) && isRim(b))
                midpoints.push_back(0.5 * (result.points[a] + result.points[b]));
        }
        if (midpoints.empty())
            break;
        for (const Vec2& p : midpoints)
            insertNew(p);
        markDomains(cdt);
    }

    for (auto face : cdt.finite_face_handles()) {
        if (!face->info().inDomain())
            continue;
        result.triangles.push_back({face->vertex(0)->info().value, face->vertex(1)->info().value,
                                    face->vertex(2)->info().value});
    }
    return result;
}

}  // namespace rigmesh
