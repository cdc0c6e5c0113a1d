// Where a shared sketch's surface creases: the worst edges by the
// angle between their two face normals, with where their vertices came from
// (VertexOrigin). Prints only when RIGMESH_CREASE_REPORT is set (to the
// number of edges to list per sketch); RIGMESH_CREASE_PLY=DIR also writes
// DIR/SKETCH.ply with every face coloured by its largest neighbour angle
// (white 0, red at 35 degrees or more). A tool for the surface work, not a
// guard: the figures are guarded in SurfaceFigures (SurfaceFiguresTest).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <string>

#include "SurfaceTestSupport.h"

namespace rigmesh {
namespace {

std::string describe(const VertexOrigin& o, const Vec3& p) {
    char buffer[160];
    std::snprintf(buffer, sizeof buffer, "%s%d s%d t%.3f%s (%.3f %.3f %.3f)",
                  o.kind == RegionKind::Cylindrical ? "cyl" : "con", o.region, o.section,
                  o.axisPosition, o.onOutline ? " outline" : "", p.x(), p.y(), p.z());
    return buffer;
}

class CreaseReport : public testing::TestWithParam<std::string> {};

TEST_P(CreaseReport, WorstEdges) {
    const char* count = std::getenv("RIGMESH_CREASE_REPORT");
    if (!count)
        GTEST_SKIP() << "set RIGMESH_CREASE_REPORT=N to list the N worst edges";
    const SketchToSurfaceResult& result = surfacetest::sharedResult(GetParam());
    const TriMesh& mesh = result.surface.mesh;
    const auto& origins = result.surface.origins;
    std::vector<Vec3> normals;
    for (const auto& f : mesh.faces) {
        Vec3 n = (mesh.vertices[f[1]] - mesh.vertices[f[0]])
                     .cross(mesh.vertices[f[2]] - mesh.vertices[f[0]]);
        normals.push_back(n.norm() > 0 ? Vec3(n.normalized()) : Vec3::Zero());
    }
    std::map<std::pair<int, int>, std::vector<int>> edgeFaces;
    for (int f = 0; f < mesh.faceCount(); ++f)
        for (int k = 0; k < 3; ++k)
            edgeFaces[std::minmax(mesh.faces[f][k], mesh.faces[f][(k + 1) % 3])].push_back(f);
    struct Edge {
        double angle;
        int a, b, fa, fb;
    };
    std::vector<Edge> edges;
    std::vector<double> faceWorst(mesh.faces.size(), 0.0);
    for (const auto& [key, faces] : edgeFaces) {
        if (faces.size() != 2)
            continue;
        double angle = std::acos(std::clamp(normals[faces[0]].dot(normals[faces[1]]), -1.0, 1.0)) *
                       180.0 / M_PI;
        edges.push_back({angle, key.first, key.second, faces[0], faces[1]});
        faceWorst[faces[0]] = std::max(faceWorst[faces[0]], angle);
        faceWorst[faces[1]] = std::max(faceWorst[faces[1]], angle);
    }
    std::sort(edges.begin(), edges.end(),
              [](const Edge& x, const Edge& y) { return x.angle > y.angle; });
    auto opposite = [&](int f, int a, int b) {
        for (int v : mesh.faces[f])
            if (v != a && v != b)
                return v;
        return -1;
    };
    std::printf("== %s: %d vertices, edge length %.4f\n", GetParam().c_str(), mesh.vertexCount(),
                result.targetEdgeLength);
    // Where the creased edges are: at a tip (a vertex of a cap slice or a
    // tip), at a junction seam (connecting and cylindrical vertices), in a
    // patch (connecting only) or along a body (cylindrical only).
    auto inCap = [&](int v) {
        const VertexOrigin& o = origins[v];
        return o.kind == RegionKind::Cylindrical &&
               (o.section < 0 || result.cylinders[o.region].sections[o.section].inCap);
    };
    auto place = [&](const Edge& e) {
        const std::array<int, 4> vs{e.a, e.b, opposite(e.fa, e.a, e.b), opposite(e.fb, e.a, e.b)};
        int connecting = 0;
        for (int v : vs) {
            if (inCap(v))
                return 0;
            connecting += origins[v].kind == RegionKind::Connecting;
        }
        return connecting == 4 ? 2 : connecting > 0 ? 1 : 3;
    };
    const char* places[] = {"tip", "seam", "patch", "body"};
    for (double limit : {20.0, 35.0}) {
        std::array<int, 4> counts{};
        for (const Edge& e : edges)
            if (e.angle > limit)
                ++counts[place(e)];
        std::printf("   edges over %.0f deg:", limit);
        for (int k = 0; k < 4; ++k)
            std::printf(" %s %d", places[k], counts[k]);
        std::printf(" (of %zu)\n", edges.size());
    }
    const int n = std::min<int>(std::atoi(count), static_cast<int>(edges.size()));
    for (int i = 0; i < n; ++i) {
        const Edge& e = edges[i];
        if (mesh.vertices[e.a].z() < -1e-12 || mesh.vertices[e.b].z() < -1e-12)
            continue;  // the mirror image of an upper edge
        int c = opposite(e.fa, e.a, e.b), d = opposite(e.fb, e.a, e.b);
        std::printf("%6.1f  a %s\n        b %s\n        c %s\n        d %s\n", e.angle,
                    describe(origins[e.a], mesh.vertices[e.a]).c_str(),
                    describe(origins[e.b], mesh.vertices[e.b]).c_str(),
                    describe(origins[c], mesh.vertices[c]).c_str(),
                    describe(origins[d], mesh.vertices[d]).c_str());
    }
    if (const char* dir = std::getenv("RIGMESH_CREASE_PLY")) {
        std::ofstream out(std::string(dir) + "/" + GetParam() + ".ply");
        out << "ply\nformat ascii 1.0\nelement vertex " << mesh.vertexCount()
            << "\nproperty float x\nproperty float y\nproperty float z\nelement face "
            << mesh.faceCount()
            << "\nproperty list uchar int vertex_indices\nproperty uchar red\nproperty uchar "
               "green\nproperty uchar blue\nend_header\n";
        for (const Vec3& v : mesh.vertices)
            out << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
        for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
            const int shade = 255 - static_cast<int>(255 * std::min(1.0, faceWorst[f] / 35.0));
            out << "3 " << mesh.faces[f][0] << ' ' << mesh.faces[f][1] << ' ' << mesh.faces[f][2]
                << " 255 " << shade << ' ' << shade << '\n';
        }
    }
}

INSTANTIATE_TEST_SUITE_P(SharedSketches, CreaseReport,
                         testing::ValuesIn(testsupport::sharedSketchNames(false)),
                         testsupport::sketchTestName);

}  // namespace
}  // namespace rigmesh
