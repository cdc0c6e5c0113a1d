#include "autorig/CurveSkeleton.h"

// Before any CGAL header: the flow's containers allocate through the
// arena, so its pointer-ordered sets run in the same order every time
// (autorig/DeterministicArena.h). Only this file instantiates them.
#include "autorig/DeterministicArena.h"
#define CGAL_ALLOCATOR(T) rigmesh::ArenaAllocator<T>

#include <CGAL/Mean_curvature_flow_skeletonization.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <algorithm>
#include <cmath>

#include "base/Error.h"
#include "mesh/CgalSurfaceMesh.h"

namespace rigmesh {

namespace {

using Skeletonization = CGAL::Mean_curvature_flow_skeletonization<cgal::SurfaceMesh>;
namespace PMP = CGAL::Polygon_mesh_processing;

// The flow never frees into the arena, and remeshing makes elements as it
// goes: measured 1.0-1.7 kB per input vertex on the shared sketches; ten
// times that and a gigabyte more, as address space only.
std::size_t arenaBytes(const TriMesh& mesh) {
    return (std::size_t{1} << 30) + static_cast<std::size_t>(mesh.vertexCount()) * 20'000;
}

}  // namespace

CurveSkeleton extractCurveSkeleton(const TriMesh& mesh, const RigProgress& progress) {
    const cgal::SurfaceMesh surface =
        cgal::toSurfaceMesh(mesh, MessageId::MeshSurfaceNotManifold, MessageId::MeshSurfaceHasHole);
    reportRigProgress(progress, 0.0);
    // Address space only; what the flow touches is committed as it goes.
    DeterministicArena arena(arenaBytes(mesh));
    const DeterministicArena::Scope scope(arena);
    Skeletonization flow(surface);
    // contract_until_convergence() with a progress report and a way out at
    // every step: stop when one step changes the area by less than the
    // flow's fraction of the original area, or after its step limit.
    const double originalArea = PMP::area(surface);
    double lastArea = 0.0;
    for (std::size_t step = 0; step < flow.max_iterations(); ++step) {
        flow.contract_geometry();
        flow.remesh();
        flow.detect_degeneracies();
        const double area = PMP::area(flow.meso_skeleton());
        // The area shrinks towards zero as the surface becomes a curve.
        reportRigProgress(progress, std::clamp(1.0 - area / originalArea, 0.0, 0.99));
        if (std::abs(lastArea - area) / originalArea < flow.area_variation_factor())
            break;
        lastArea = area;
    }
    Skeletonization::Skeleton graph;
    flow.convert_to_skeleton(graph);
    if (boost::num_vertices(graph) < 2)
        throw Error(MessageId::AutoRigFlowContracted);

    CurveSkeleton result;
    for (auto v : CGAL::make_range(boost::vertices(graph))) {
        const auto& point = graph[v].point;
        result.nodes.emplace_back(point.x(), point.y(), point.z());
        std::vector<int> vertices;
        for (auto input : graph[v].vertices)
            vertices.push_back(static_cast<int>(input));
        result.nodeVertices.push_back(std::move(vertices));
    }
    for (auto e : CGAL::make_range(boost::edges(graph)))
        result.edges.push_back(
            {static_cast<int>(boost::source(e, graph)), static_cast<int>(boost::target(e, graph))});
    reportRigProgress(progress, 1.0);
    return result;
}

}  // namespace rigmesh
