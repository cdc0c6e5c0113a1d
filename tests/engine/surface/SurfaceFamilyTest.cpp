// The surface figures on a generated family of creature outlines
// (tests/support/CreatureOutlines.h): legs close together, stubby limbs the
// skeleton prunes, fingers, tentacles, limbs meeting the body at any angle,
// drawn steadily, fast or slowly. On every outline: neighbouring face
// normals at most 20 degrees apart at the 99th percentile and 35 on every
// edge, a front view whose silhouette covers the cleaned outline (IoU >=
// 0.95) and strays from it by at most two outline spacings anywhere (so a
// short limb the rig prunes is rounded into the body, not shaved to a
// wall), no steep face stands more than two spacings inside the outline
// (SurfaceWall.h: a stub cut off or stepped down to a low patch leaves one
// though the silhouette may hold), and a short limb the skeleton keeps has
// a bone reaching into it.
//
// Every class is one test (CTest runs them in parallel), all 40 outlines
// of it. An outline missing a figure fails the test unless it is listed in
// SurfaceFamilyKnownDefects.h, a KNOWN DEFECT of the surface (folds at
// concave corners, a pruned stub shaved off), and then only if it got worse
// than its recorded figures; one that meets every figure again is printed,
// to be taken off the list. RIGMESH_FAMILY_RECORD=1 prints the list as it
// stands; RIGMESH_FAMILY_VERBOSE=1 the worst edges of each outline;
// RIGMESH_FAMILY_DUMP=DIR writes each outline's stroke as a sketch
// (DIR/CLASS_SEED.json) and its surface (DIR/CLASS_SEED.obj).
// RIGMESH_FAMILY_SEEDS=7,12 measures only those seeds of each class (for
// looking at a few outlines; the test then checks only those).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <tuple>

#include "CreatureOutlines.h"
#include "OutlineDeviation.h"
#include "SurfaceFamilyKnownDefects.h"
#include "SurfaceTestSupport.h"
#include "SurfaceWall.h"
#include "mesh/MeshWriter.h"
#include "mesh/SurfaceQuality.h"
#include "rig/SkeletonFromRegions.h"

namespace rigmesh {
namespace {

using testsupport::CreatureClass;
using testsupport::CreatureOutline;

constexpr double kP99Limit = 20.0;
constexpr double kMaxLimit = 35.0;
constexpr double kIoULimit = 0.95;
constexpr double kDeviationLimit = 2.0;  // outline spacings
constexpr int kFamilySize = 40;          // per class: 200 outlines in all

struct Figures {
    NormalAngles angles;
    double iou = 0;
    double shaved = 0, bulged = 0;  // outline spacings
    double wall = 0;                // outline spacings
    int cylinders = 0;
    int stubsWithBones = 0;
    std::string error;  // the pipeline's refusal, if any
};

// Does the rig keep the stub: a joint past the body's outline, nearer the
// stub's tip than its base is?
bool stubHasBone(const Skeleton& skeleton, const testsupport::Stub& stub) {
    const double reach = (stub.tip - stub.base).norm();
    return std::any_of(skeleton.joints().begin(), skeleton.joints().end(), [&](const Joint& j) {
        return (j.position.head<2>() - stub.tip).norm() < 0.8 * reach;
    });
}

void dump(const CreatureOutline& outline, const SketchToSurfaceResult* result,
          const std::string& name) {
    const char* directory = std::getenv("RIGMESH_FAMILY_DUMP");
    if (!directory)
        return;
    std::ofstream json(std::string(directory) + "/" + name + ".json");
    json.precision(10);
    json << "{\"name\":\"" << name << "\",\"points\":[";
    for (std::size_t i = 0; i < outline.stroke.size(); ++i)
        json << (i ? "," : "") << "[" << outline.stroke[i].x() << "," << outline.stroke[i].y()
             << "]";
    json << "]}\n";
    if (result) {
        writeMesh(result->surface.mesh, std::string(directory) + "/" + name + ".obj");
        std::ofstream origins(std::string(directory) + "/" + name + ".origins");
        for (const VertexOrigin& o : result->surface.origins)
            origins << (o.kind == RegionKind::Cylindrical ? "cyl " : "con ") << o.region << ' '
                    << o.section << ' ' << o.onOutline << '\n';
    }
}

std::string describe(const SketchToSurfaceResult& result, int v) {
    const VertexOrigin& o = result.surface.origins[v];
    const Vec3& p = result.surface.mesh.vertices[v];
    bool cap = o.kind == RegionKind::Cylindrical &&
               (o.section < 0 || result.cylinders[o.region].sections[o.section].inCap);
    char buffer[200];
    std::snprintf(buffer, sizeof buffer, "%s%d s%d%s%s (%.4g %.4g %.4g)",
                  o.kind == RegionKind::Cylindrical ? "cyl" : "con", o.region, o.section,
                  cap ? " cap" : "", o.onOutline ? " outline" : "", p.x(), p.y(), p.z());
    return buffer;
}

// The outline's turn (degrees, negative concave) summed over the polygon
// points within one spacing of p, and the distance to the nearest point.
std::pair<double, double> outlineTurnNear(const SketchToSurfaceResult& result, const Vec2& p) {
    const auto& pts = result.polygon.points;
    const int n = static_cast<int>(pts.size());
    double nearest = 1e300, turn = 0;
    int at = 0;
    for (int i = 0; i < n; ++i)
        if ((pts[i] - p).norm() < nearest) {
            nearest = (pts[i] - p).norm();
            at = i;
        }
    for (int k = -2; k <= 2; ++k) {
        const int i = ((at + k) % n + n) % n;
        turn += turnAngle(pts[i] - pts[(i - 1 + n) % n], pts[(i + 1) % n] - pts[i]);
    }
    return {turn * 180 / M_PI, nearest / result.polygon.spacing};
}

void describeWorstEdges(const SketchToSurfaceResult& result, int count) {
    const TriMesh& mesh = result.surface.mesh;
    std::map<std::pair<int, int>, std::vector<int>> edgeFaces;
    for (int f = 0; f < mesh.faceCount(); ++f)
        for (int k = 0; k < 3; ++k)
            edgeFaces[std::minmax(mesh.faces[f][k], mesh.faces[f][(k + 1) % 3])].push_back(f);
    auto normal = [&](int f) {
        const auto& t = mesh.faces[f];
        return Vec3((mesh.vertices[t[1]] - mesh.vertices[t[0]])
                        .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]])
                        .normalized());
    };
    std::vector<std::tuple<double, int, int>> edges;
    for (const auto& [key, faces] : edgeFaces)
        if (faces.size() == 2 && mesh.vertices[key.first].z() >= -1e-12 &&
            mesh.vertices[key.second].z() >= -1e-12)
            edges.emplace_back(
                std::acos(std::clamp(normal(faces[0]).dot(normal(faces[1])), -1.0, 1.0)) * 180 /
                    M_PI,
                key.first, key.second);
    std::sort(edges.rbegin(), edges.rend());
    for (int i = 0; i < count && i < static_cast<int>(edges.size()); ++i) {
        const auto [angle, a, b] = edges[i];
        if (angle < kMaxLimit)
            break;
        const Vec2 mid = 0.5 * (mesh.vertices[a] + mesh.vertices[b]).head<2>();
        const auto [turn, distance] = outlineTurnNear(result, mid);
        std::printf("   %5.1f outline turn %6.1f at %.2f spacings\n     a %s\n     b %s\n", angle,
                    turn, distance, describe(result, a).c_str(), describe(result, b).c_str());
    }
}

Figures measure(const CreatureOutline& outline, const std::string& name) {
    Figures f;
    SketchToSurfaceResult result;
    try {
        result = sketchToSurface(outline.stroke);
    } catch (const std::exception& error) {
        f.error = error.what();
        dump(outline, nullptr, name);
        return f;
    }
    dump(outline, &result, name);
    const TriMesh& mesh = result.surface.mesh;
    const double spacing = result.polygon.spacing;
    f.angles = normalAngles(mesh);
    f.iou = silhouetteIoU(mesh, result.polygon.points);
    const surfacetest::Deviation deviation =
        surfacetest::outlineDeviation(mesh, result.polygon.points, spacing);
    f.shaved = deviation.shaved / spacing;
    f.bulged = deviation.bulged / spacing;
    f.wall = surfacetest::deepestWall(mesh, result.polygon.points).depth / spacing;
    f.cylinders = static_cast<int>(result.cylinders.size());
    if (std::getenv("RIGMESH_FAMILY_VERBOSE"))
        describeWorstEdges(result, 6);
    if (!outline.stubs.empty()) {
        const PartSkeleton rig = buildSkeleton(result.decomposition, result.cylinders);
        for (const auto& stub : outline.stubs) {
            f.stubsWithBones += stubHasBone(rig.skeleton, stub) ? 1 : 0;
            if (std::getenv("RIGMESH_FAMILY_VERBOSE")) {
                std::printf("stub base %g %g tip %g %g length %g thickness %g\n", stub.base.x(),
                            stub.base.y(), stub.tip.x(), stub.tip.y(), stub.length, stub.thickness);
                for (const Joint& j : rig.skeleton.joints())
                    std::printf("  joint %g %g\n", j.position.x(), j.position.y());
            }
        }
    }
    return f;
}

// The figures an outline may reach: the limits, or for an outline listed
// in SurfaceFamilyKnownDefects.h its recorded (worse) figures.
struct Allowed {
    double p99 = kP99Limit, max = kMaxLimit, shaved = kDeviationLimit, wall = kDeviationLimit;
};

Allowed allowedFor(CreatureClass shapeClass, int seed, bool* known) {
    Allowed allowed;
    *known = false;
    for (const KnownDefect& d : kKnownDefects)
        if (d.shapeClass == shapeClass && d.seed == seed) {
            *known = true;
            allowed.p99 = std::max(allowed.p99, d.p99);
            allowed.max = std::max(allowed.max, d.max);
            allowed.shaved = std::max(allowed.shaved, d.shaved);
            allowed.wall = std::max(allowed.wall, d.wall);
        }
    return allowed;
}

std::string failures(const Figures& f, const Allowed& allowed) {
    if (!f.error.empty())
        return "refused: " + f.error;
    std::ostringstream out;
    out.precision(3);
    if (f.angles.p99 > allowed.p99)
        out << " p99 " << f.angles.p99;
    if (f.angles.max > allowed.max)
        out << " max " << f.angles.max;
    if (f.iou < kIoULimit)
        out << " IoU " << f.iou;
    if (f.shaved > allowed.shaved)
        out << " shaved " << f.shaved;
    if (f.bulged > kDeviationLimit)
        out << " bulged " << f.bulged;
    if (f.wall > allowed.wall)
        out << " wall " << f.wall;
    return out.str();
}

// Rounded up to a tenth, as the known-defect list records figures.
double recorded(double value) {
    return std::ceil(value * 10.0 - 1e-9) / 10.0;
}

// Whether RIGMESH_FAMILY_SEEDS (a comma-separated list) names the seed, or
// is unset.
bool seedSelected(int seed) {
    const char* seeds = std::getenv("RIGMESH_FAMILY_SEEDS");
    if (!seeds || !*seeds)
        return true;
    std::istringstream list(seeds);
    std::string item;
    while (std::getline(list, item, ','))
        if (!item.empty() && std::atoi(item.c_str()) == seed)
            return true;
    return false;
}

// Runs every outline of one class; prints each, the class's worst and the
// outlines missing a figure. Fails for an outline that misses a figure and
// is not a known defect, or a known defect that got worse than recorded.
void checkClass(CreatureClass shapeClass) {
    const std::string className = testsupport::creatureClassName(shapeClass);
    struct Worst {
        double value;
        int seed;
    };
    Worst p99{0, -1}, max{0, -1}, iou{1, -1}, shaved{0, -1}, bulged{0, -1}, wall{0, -1};
    int stubs = 0, stubsWithBones = 0, missing = 0, knownCount = 0;
    std::vector<std::string> failed, fixed;
    std::string record;
    for (int seed = 0; seed < kFamilySize; ++seed) {
        if (!seedSelected(seed))
            continue;
        const CreatureOutline outline = testsupport::creatureOutline(shapeClass, seed);
        const std::string name = className + "_" + std::to_string(seed);
        const Figures f = measure(outline, name);
        std::printf(
            "%-12s %-6s cyl %2d p99 %5.1f max %5.1f IoU %.4f shaved %4.2f bulged %4.2f wall %4.2f",
            name.c_str(), testsupport::strokeMannerName(outline.manner).c_str(), f.cylinders,
            f.angles.p99, f.angles.max, f.iou, f.shaved, f.bulged, f.wall);
        if (!outline.stubs.empty())
            std::printf(" stubs %zu with bones %d", outline.stubs.size(), f.stubsWithBones);
        std::printf("\n");
        stubs += static_cast<int>(outline.stubs.size());
        stubsWithBones += f.stubsWithBones;
        bool known = false;
        const Allowed allowed = allowedFor(shapeClass, seed, &known);
        knownCount += known ? 1 : 0;
        const bool meetsLimits = failures(f, Allowed{}).empty();
        if (!meetsLimits) {
            ++missing;
            char line[160];
            std::snprintf(line, sizeof line,
                          "    {CreatureClass::%s, %d, %.1f, %.1f, %.1f, %.1f},\n",
                          testsupport::creatureClassTypeName(shapeClass).c_str(), seed,
                          f.angles.p99 > kP99Limit ? recorded(f.angles.p99) : 0.0,
                          f.angles.max > kMaxLimit ? recorded(f.angles.max) : 0.0,
                          f.shaved > kDeviationLimit ? recorded(f.shaved) : 0.0,
                          f.wall > kDeviationLimit ? recorded(f.wall) : 0.0);
            record += line;
        }
        const std::string failure = failures(f, allowed);
        if (!failure.empty())
            failed.push_back(name + (known ? " (known defect, now worse):" : ":") + failure);
        else if (known && meetsLimits)
            fixed.push_back(name);
        if (!f.error.empty())
            continue;
        auto worse = [seed](Worst& w, double value, bool higher) {
            if (w.seed < 0 || (higher ? value > w.value : value < w.value))
                w = {value, seed};
        };
        worse(p99, f.angles.p99, true);
        worse(max, f.angles.max, true);
        worse(iou, f.iou, false);
        worse(shaved, f.shaved, true);
        worse(bulged, f.bulged, true);
        worse(wall, f.wall, true);
    }
    std::printf(
        "%s worst: p99 %.1f (seed %d) max %.1f (seed %d) IoU %.4f (seed %d) shaved %.2f "
        "(seed %d) bulged %.2f (seed %d) wall %.2f (seed %d); stubs with bones %d of %d; %d of %d "
        "miss a figure (%d listed as known defects)\n",
        className.c_str(), p99.value, p99.seed, max.value, max.seed, iou.value, iou.seed,
        shaved.value, shaved.seed, bulged.value, bulged.seed, wall.value, wall.seed, stubsWithBones,
        stubs, missing, kFamilySize, knownCount);
    if (std::getenv("RIGMESH_FAMILY_RECORD"))
        std::printf("known defects of %s, as recorded now:\n%s", className.c_str(), record.c_str());
    for (const std::string& name : fixed)
        std::printf("%s now meets every figure: take it off the known defects\n", name.c_str());
    std::string list;
    for (const std::string& f : failed)
        list += "\n  " + f;
    EXPECT_TRUE(failed.empty()) << failed.size() << " of " << kFamilySize << " " << className
                                << " outlines miss a figure:" << list;
}

std::string className(const testing::TestParamInfo<CreatureClass>& info) {
    return testsupport::creatureClassName(info.param);
}

class SurfaceFamily : public testing::TestWithParam<CreatureClass> {};

TEST_P(SurfaceFamily, EveryOutlineMeetsEveryFigureOrItsRecordedKnownDefect) {
    checkClass(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Classes, SurfaceFamily, testing::ValuesIn(testsupport::kCreatureClasses),
                         className);

}  // namespace
}  // namespace rigmesh
