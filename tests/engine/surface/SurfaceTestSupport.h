// Helpers for the surface tests: the pipeline's results on the shared
// sketches, computed once per test binary, and small mesh geometry.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <map>
#include <string>
#include <vector>

#include "SketchToSurfaceTestSupport.h"
#include "base/Error.h"
#include "mesh/MeshChecks.h"
#include "pipeline/SketchToSurface.h"

namespace rigmesh::surfacetest {

// The pipeline's result on a shared sketch with default options, cached.
inline const SketchToSurfaceResult& sharedResult(const std::string& sketch) {
    static std::map<std::string, SketchToSurfaceResult> cache;
    auto found = cache.find(sketch);
    if (found == cache.end())
        found =
            cache.emplace(sketch, sketchToSurface(testsupport::sharedSketchPoints(sketch))).first;
    return found->second;
}

// Vertices around each body cross section (the whole mirrored ring). A
// body cut by a pruned bump is built in pieces and its rings are told by the
// rig cylinder's nearest section (pipeline/RigRegionOrigins.h): a section
// there may own two rings or none; those owning none are left out, and such
// a body's own rings are not seen here (a known gap of this figure).
inline std::vector<int> ringSizes(const SketchToSurfaceResult& result) {
    std::vector<int> sizes;
    for (std::size_t c = 0; c < result.cylinders.size(); ++c) {
        const auto& sections = result.cylinders[c].sections;
        std::vector<int> count(sections.size(), 0);
        for (const VertexOrigin& o : result.surface.origins)
            if (o.kind == RegionKind::Cylindrical && o.region == static_cast<int>(c) &&
                o.section >= 0)
                ++count[static_cast<std::size_t>(o.section)];
        for (std::size_t s = 0; s < sections.size(); ++s)
            if (!sections[s].inCap && count[s] > 0)
                sizes.push_back(count[s]);
    }
    return sizes;
}

// The full mesh report (self-intersections included) of a shared sketch, cached.
inline const MeshReport& sharedReport(const std::string& sketch) {
    static std::map<std::string, MeshReport> cache;
    auto found = cache.find(sketch);
    if (found == cache.end())
        found = cache.emplace(sketch, analyseMesh(sharedResult(sketch).surface.mesh, true)).first;
    return found->second;
}

inline Eigen::AlignedBox3d boundingBox(const TriMesh& mesh) {
    Eigen::AlignedBox3d box;
    for (const Vec3& v : mesh.vertices)
        box.extend(v);
    return box;
}

// What happened to one input that must either give a closed, manifold
// surface or be rejected with a rigmesh::Error.
enum class Outcome { ClosedManifold, Rejected, BrokenSurface, OtherException };

struct OutcomeReport {
    Outcome outcome;
    std::string detail;  // the error message or what is wrong with the surface
};

inline OutcomeReport runPipeline(const std::vector<Vec2>& stroke,
                                 const SketchToSurfaceOptions& options = {}) {
    try {
        const SketchToSurfaceResult result = sketchToSurface(stroke, options);
        const MeshReport report = analyseMesh(result.surface.mesh, false);
        if (report.isClosed() && report.isManifold())
            return {Outcome::ClosedManifold, ""};
        return {Outcome::BrokenSurface,
                "boundary edges " + std::to_string(report.boundaryEdges) + ", non-manifold edges " +
                    std::to_string(report.nonManifoldEdges) + ", non-manifold vertices " +
                    std::to_string(report.nonManifoldVertices)};
    } catch (const Error& error) {
        return {Outcome::Rejected, error.what()};
    } catch (const std::exception& error) {
        return {Outcome::OtherException, error.what()};
    } catch (...) {
        return {Outcome::OtherException, "a non-standard exception"};
    }
}

// The rule for any input: a closed, manifold surface or a rigmesh::Error
// with a message.
inline void expectSurfaceOrError(const std::vector<Vec2>& stroke) {
    const OutcomeReport result = runPipeline(stroke);
    EXPECT_TRUE(result.outcome == Outcome::ClosedManifold || result.outcome == Outcome::Rejected)
        << (result.outcome == Outcome::BrokenSurface ? "broken surface: " : "wrong exception: ")
        << result.detail;
    if (result.outcome == Outcome::Rejected) {
        EXPECT_FALSE(result.detail.empty());
    }
}

}  // namespace rigmesh::surfacetest
