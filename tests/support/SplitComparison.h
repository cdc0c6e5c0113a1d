// The band split against the whole split (cut/SurfaceSplit.h), bit for bit,
// and the cuts to compare them on: planes across a part at several places
// and tilts and bent strokes swept along z.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "cut/SurfaceSplit.h"

namespace rigmesh::testsupport {

struct NamedCut {
    std::string name;
    CutSurface surface;
};

// Planes with six normals at nine places along the box's diagonal, the
// planes test_cut cuts every shared sketch by, and bent strokes (a "<" and
// a ">" of nine points) across the shorter side at nine places.
inline std::vector<NamedCut> cutsAcross(const TriMesh& mesh) {
    Eigen::AlignedBox3d box;
    for (const Vec3& v : mesh.vertices)
        box.extend(v);
    std::vector<NamedCut> cuts;
    const std::vector<Vec3> normals{Vec3(1, 0.1, 0),    Vec3(1, 0.3, 0.2),  Vec3(0.1, 1, 0),
                                    Vec3(0.3, 1, -0.2), Vec3(0.05, 0.1, 1), Vec3(1, 1, 0.3)};
    for (std::size_t n = 0; n < normals.size(); ++n)
        for (int i = 1; i <= 9; ++i)
            cuts.push_back({"plane " + std::to_string(n) + " at " + std::to_string(i),
                            CutSurface::plane(box.min() + i / 10.0 * box.sizes(), normals[n])});
    const int axis = box.sizes().x() >= box.sizes().y() ? 0 : 1;
    for (double at : {0.3, 0.5, 0.7})
        cuts.push_back({"test_cut plane at " + std::to_string(at),
                        CutSurface::plane(box.min() + at * box.sizes(),
                                          Vec3::Unit(axis) + 0.1 * Vec3::Unit(1 - axis))});
    const bool wide = axis == 0;
    const double across = wide ? box.sizes().y() : box.sizes().x();
    for (int i = 1; i <= 9; ++i)
        for (double bendFactor : {0.25, -0.4}) {
            const double alongAt = (wide ? box.min().x() : box.min().y()) +
                                   i / 10.0 * (wide ? box.sizes().x() : box.sizes().y());
            const double bend = bendFactor * across;
            std::vector<Vec3> stroke;
            for (int k = 0; k <= 8; ++k) {
                const double s = -0.75 * across + 1.5 * across * k / 8.0;
                const double along = alongAt + bend * (1.0 - std::abs(s) / (0.75 * across));
                const Vec3 c = box.center();
                stroke.push_back(wide ? Vec3(along, c.y() + s, 0.0) : Vec3(c.x() + s, along, 0.0));
            }
            cuts.push_back(
                {"stroke at " + std::to_string(i) + " bend " + std::to_string(bendFactor),
                 CutSurface::swept(stroke, Vec3::UnitZ())});
        }
    return cuts;
}

struct SplitComparison {
    bool same = true;
    std::string difference;  // the first one
    SplitReport report;      // of the band split
};

// The band falls back to the whole split only when it would be most of the
// part (a plane along a small sketch) or the cut misses.
inline bool fallbackIsExpected(const SplitReport& report) {
    return report.band || report.fallback == "the band is most of the surface" ||
           report.fallback == "no face near the cut" ||
           report.fallback == "the plane misses the part's box";
}

inline bool sameBits(const Vec3& a, const Vec3& b) {
    return std::memcmp(a.data(), b.data(), 3 * sizeof(double)) == 0;
}

// Both splits of `mesh` by `surface`; a refusal (Error) must be the same too.
inline SplitComparison compareSplits(const TriMesh& mesh, const CutSurface& surface) {
    SplitComparison out;
    std::vector<MeshPiece> band, whole;
    std::string bandError, wholeError;
    try {
        band = splitBySurface(mesh, surface, SplitMethod::Band, &out.report);
    } catch (const std::exception& e) {
        bandError = e.what();
    }
    try {
        whole = splitBySurface(mesh, surface, SplitMethod::Whole);
    } catch (const std::exception& e) {
        wholeError = e.what();
    }
    auto differ = [&](const std::string& what) {
        if (out.same)
            out.difference = what;
        out.same = false;
    };
    if (bandError != wholeError)
        differ("errors: '" + bandError + "' / '" + wholeError + "'");
    if (band.size() != whole.size()) {
        differ("piece counts " + std::to_string(band.size()) + " / " +
               std::to_string(whole.size()));
        return out;
    }
    for (std::size_t k = 0; k < band.size(); ++k) {
        const MeshPiece& a = band[k];
        const MeshPiece& b = whole[k];
        const std::string piece = "piece " + std::to_string(k) + ": ";
        if (a.mesh.vertexCount() != b.mesh.vertexCount() ||
            a.mesh.faceCount() != b.mesh.faceCount()) {
            differ(piece + "sizes " + std::to_string(a.mesh.vertexCount()) + "/" +
                   std::to_string(a.mesh.faceCount()) + " against " +
                   std::to_string(b.mesh.vertexCount()) + "/" + std::to_string(b.mesh.faceCount()));
            continue;
        }
        for (int v = 0; v < a.mesh.vertexCount(); ++v)
            if (!sameBits(a.mesh.vertices[v], b.mesh.vertices[v])) {
                differ(piece + "vertex " + std::to_string(v));
                break;
            }
        if (a.mesh.faces != b.mesh.faces)
            differ(piece + "faces");
        if (a.holes != b.holes)
            differ(piece + "holes");
        if (a.side != b.side)
            differ(piece + "side");
        if (a.sources.size() != b.sources.size()) {
            differ(piece + "source counts");
            continue;
        }
        for (std::size_t v = 0; v < a.sources.size(); ++v) {
            const VertexSource& s = a.sources[v];
            const VertexSource& t = b.sources[v];
            // A vertex source's barycentric is not set (VertexSource::vertex).
            if (s.kind != t.kind || s.mesh != t.mesh || s.index != t.index ||
                (s.kind == VertexSource::Kind::Triangle &&
                 !sameBits(s.barycentric, t.barycentric))) {
                differ(piece + "source of vertex " + std::to_string(v));
                break;
            }
        }
    }
    return out;
}

// How many cuts were compared, and on how many the band held.
struct BandTally {
    int cuts = 0;
    int banded = 0;
};

// Every cut of cutsAcross(mesh): the band split gives the whole split's
// pieces bit for bit and falls back only for an expected reason (each
// failure traced with `label` and the cut's name).
inline BandTally expectBandGivesTheWholeSplitAcross(const TriMesh& mesh, const std::string& label) {
    BandTally tally;
    for (const NamedCut& cut : cutsAcross(mesh)) {
        SCOPED_TRACE(label + " " + cut.name);
        const SplitComparison result = compareSplits(mesh, cut.surface);
        EXPECT_TRUE(result.same) << result.difference;
        EXPECT_TRUE(fallbackIsExpected(result.report)) << result.report.fallback;
        ++tally.cuts;
        tally.banded += result.report.band ? 1 : 0;
    }
    return tally;
}

}  // namespace rigmesh::testsupport
