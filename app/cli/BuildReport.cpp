#include "BuildReport.h"

#include "mesh/SurfaceQuality.h"

#include <cstdio>

namespace rigmesh::cli {

nlohmann::json buildStatistics(const std::string& name, const SketchToPartResult& rigged,
                               const MeshReport& report, double meshChecksMilliseconds) {
    const SketchToSurfaceResult& result = rigged.surface;
    const StageTimings& ms = result.milliseconds;
    nlohmann::json stats;
    stats["sketch"] = name;
    stats["vertices"] = result.surface.mesh.vertexCount();
    stats["faces"] = result.surface.mesh.faceCount();
    stats["outline_points"] = result.polygon.points.size();
    stats["target_edge_length"] = result.targetEdgeLength;
    stats["cylindrical_regions"] = result.decomposition.cylinders.size();
    stats["connecting_regions"] = result.decomposition.connecting.size();
    stats["joints"] = rigged.part.skeleton.jointCount();
    stats["bones"] = rigged.part.skeleton.boneCount();
    stats["failed_bones"] = rigged.part.weights.failedBones.size();
    stats["ms_total"] = rigged.totalMilliseconds + meshChecksMilliseconds;
    stats["ms_stages"] = {{"clean", ms.clean},
                          {"triangulate", ms.triangulate},
                          {"chordal_axis", ms.chordalAxis},
                          {"decompose", ms.decompose},
                          {"cross_sections", ms.crossSections},
                          {"surface", ms.surface},
                          {"smoothing", ms.smoothing},
                          {"surface_checks", ms.checks},
                          {"skeleton", rigged.skeletonMilliseconds},
                          {"weights", rigged.weightsMilliseconds},
                          {"mesh_checks", meshChecksMilliseconds}};
    // The surface figures (mesh/SurfaceQuality.h): creases and the front silhouette against the
    // outline.
    const NormalAngles angles = normalAngles(result.surface.mesh);
    stats["surface_quality"] = {
        {"normal_angle_p50_degrees", angles.p50},
        {"normal_angle_p99_degrees", angles.p99},
        {"normal_angle_max_degrees", angles.max},
        {"silhouette_iou", silhouetteIoU(result.surface.mesh, result.polygon.points)}};
    stats["mesh"] = {{"checks_passed", report.passesChecks()},
                     {"closed", report.isClosed()},
                     {"manifold", report.isManifold()},
                     {"outward", report.isOutwardOriented()},
                     {"components", report.components},
                     {"genus", report.genus},
                     {"self_intersecting_face_pairs", report.selfIntersectingFacePairs},
                     {"degenerate_faces", report.degenerateFaces},
                     {"min_angle_degrees", report.minAngleDegrees},
                     {"volume", report.volume},
                     {"area", report.area}};
    return stats;
}

std::string buildSummary(const nlohmann::json& s) {
    char text[1024];
    const auto& mesh = s["mesh"];
    std::snprintf(
        text, sizeof text,
        "%s: %d vertices, %d faces, %d cylindrical + %d connecting regions, %d joints, %d bones\n"
        "  surface: %s, %s, genus %d, %d self-intersecting face pairs, %d degenerate faces, "
        "min angle %.1f deg\n"
        "  mesh checks: %s\n"
        "  time: %.2f ms total\n",
        s["sketch"].get<std::string>().c_str(), s["vertices"].get<int>(), s["faces"].get<int>(),
        s["cylindrical_regions"].get<int>(), s["connecting_regions"].get<int>(),
        s["joints"].get<int>(), s["bones"].get<int>(),
        mesh["closed"].get<bool>() ? "closed" : "OPEN",
        mesh["manifold"].get<bool>() ? "manifold" : "NON-MANIFOLD", mesh["genus"].get<int>(),
        mesh["self_intersecting_face_pairs"].get<int>(), mesh["degenerate_faces"].get<int>(),
        mesh["min_angle_degrees"].get<double>(),
        mesh["checks_passed"].get<bool>() ? "passed" : "FAILED", s["ms_total"].get<double>());
    return text;
}

}  // namespace rigmesh::cli
