#include "surface/SketchSurface.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <unordered_set>

#include <Eigen/Geometry>
#include <stdexcept>

#include "base/Error.h"
#include "geometry/ConstrainedTriangulation.h"
#include "surface/FoldRelaxation.h"
#include "surface/LeastSquaresMesh.h"
#include "surface/PatchLattice.h"
#include "surface/PatchRims.h"
#include "surface/SectionGaps.h"

namespace rigmesh {
namespace {

// The upper half of the surface under construction.
class HalfSurfaceBuilder {
  public:
    HalfSurfaceBuilder(const Decomposition& decomposition, const SurfaceOptions& options)
        : decomposition_(decomposition),
          options_(options),
          polygonVertex_(decomposition.axis.cdt.points.size(), -1) {}

    void addCylinder(int index, const CylinderSections& cylinder) {
        std::vector<std::vector<int>> rings;
        auto origin = [&](int section, double position) {
            return VertexOrigin{RegionKind::Cylindrical, index, section, position, false};
        };
        if (cylinder.startTip)
            rings.push_back({outlineVertex(cylinder.startTipPolygonIndex, *cylinder.startTip,
                                           origin(-1, 0.0))});
        for (std::size_t s = 0; s < cylinder.sections.size(); ++s)
            rings.push_back(addRing(cylinder.sections[s],
                                    origin(static_cast<int>(s), cylinder.axisPosition[s])));
        if (cylinder.endTip)
            rings.push_back({outlineVertex(cylinder.endTipPolygonIndex, *cylinder.endTip,
                                           origin(-1, cylinder.endTipPosition))});
        for (std::size_t r = 1; r < rings.size(); ++r)
            stitch(rings[r - 1], rings[r]);

        const CylinderRegion& region = decomposition_.cylinders[index];
        int first = cylinder.startTip ? 1 : 0;
        int last = static_cast<int>(rings.size()) - (cylinder.endTip ? 2 : 1);
        if (region.startConnecting >= 0) {
            portRings_[chordKey(cylinder.sections.front())] = rings[first];
            portSpacing_[region.startConnecting] =
                std::min(portSpacing(region.startConnecting), cylinder.sections.front().spacing);
        }
        if (region.endConnecting >= 0) {
            portRings_[chordKey(cylinder.sections.back())] = rings[last];
            portSpacing_[region.endConnecting] =
                std::min(portSpacing(region.endConnecting), cylinder.sections.back().spacing);
        }
    }

    void addConnectingRegion(int index) {
        const ConnectingRegion& region = decomposition_.connecting[index];
        const auto& cdt = decomposition_.axis.cdt;
        const int pointCount = static_cast<int>(cdt.points.size());
        std::unordered_set<int> inside(region.triangles.begin(), region.triangles.end());

        // Boundary edges of the region, oriented as in their counter-clockwise triangles.
        std::map<int, int> next;
        for (int t : region.triangles)
            for (int k = 0; k < 3; ++k) {
                int neighbour = cdt.neighbors[t][k];
                if (neighbour >= 0 && inside.count(neighbour))
                    continue;
                next[cdt.triangles[t][(k + 1) % 3]] = cdt.triangles[t][(k + 2) % 3];
            }
        if (next.empty())
            throw std::logic_error("internal error: a connecting region without boundary");

        const VertexOrigin origin{RegionKind::Connecting, index, -1, 0.0, false};
        // The patch is as fine as the finest cylinder meeting it (resolution
        // follows thickness): a coarse patch against a fine port ring would
        // crease along the seam.
        const double spacing = portSpacing(index);
        std::vector<int> loop;
        std::vector<Vec2> loop2d;
        std::vector<bool> rim;
        const int start = next.begin()->first;
        int a = start;
        do {
            int b = next.at(a);
            loop.push_back(outlineVertex(a, cdt.points[a], origin));
            rim.push_back(true);
            if (b == (a + 1) % pointCount) {
                // An outline edge of this region only: split to the patch's spacing.
                const Vec2 &p = cdt.points[a], &q = cdt.points[b];
                const int pieces = static_cast<int>(std::ceil((q - p).norm() / spacing - 0.25));
                for (int k = 1; k < pieces; ++k) {
                    loop.push_back(outlineVertex(-1, p + (q - p) * (double(k) / pieces), origin));
                    rim.push_back(true);
                }
            } else {
                // A port chord: walk the adjacent cylinder's end semicircle.
                const std::vector<int>& ring = portRings_.at(std::minmax(a, b));
                bool forward = ring.front() == polygonVertex_[a];
                for (std::size_t j = 1; j + 1 < ring.size(); ++j) {
                    loop.push_back(forward ? ring[j] : ring[ring.size() - 1 - j]);
                    rim.push_back(false);
                }
            }
            a = b;
            if (loop.size() > 4 * static_cast<std::size_t>(pointCount) + 4 * positions_.size())
                throw std::logic_error(
                    "internal error: a connecting region's boundary does not close");
        } while (a != start);
        for (int v : loop)
            loop2d.push_back(positions_[v].head<2>());

        PatchTriangulation patch = triangulatePatch(loop2d, latticeInside(loop2d, spacing), rim);
        std::vector<int> vertexOf(patch.points.size());
        for (std::size_t i = 0; i < patch.points.size(); ++i)
            vertexOf[i] =
                i < loop.size()
                    ? loop[i]
                    : addVertex(Vec3(patch.points[i].x(), patch.points[i].y(), spacing), origin);
        for (const auto& t : patch.triangles)
            faces_.push_back({vertexOf[t[0]], vertexOf[t[1]], vertexOf[t[2]]});
    }

    // Mirrors the upper half through the sketch plane into a closed surface.
    SketchSurface mirrored() const {
        SketchSurface surface;
        const int n = static_cast<int>(positions_.size());
        surface.mesh.vertices = positions_;
        surface.origins = origins_;
        surface.mirror.resize(n);
        for (int v = 0; v < n; ++v) {
            if (origins_[v].onOutline) {
                surface.mirror[v] = v;
                surface.mesh.vertices[v].z() = 0.0;
                continue;
            }
            surface.mirror[v] = static_cast<int>(surface.mesh.vertices.size());
            surface.mesh.vertices.push_back(
                Vec3(positions_[v].x(), positions_[v].y(), -positions_[v].z()));
            surface.origins.push_back(origins_[v]);
        }
        surface.mirror.resize(surface.mesh.vertices.size());
        for (int v = 0; v < n; ++v)
            surface.mirror[surface.mirror[v]] = v;
        surface.mesh.faces = faces_;
        for (const auto& f : faces_)
            surface.mesh.faces.push_back(
                {surface.mirror[f[0]], surface.mirror[f[2]], surface.mirror[f[1]]});
        return surface;
    }

  private:
    // The finest local edge length of the cylinders meeting a connecting
    // region, at most the target one.
    double portSpacing(int region) const {
        auto found = portSpacing_.find(region);
        return found == portSpacing_.end() || !(found->second > 0)
                   ? options_.targetEdgeLength
                   : std::min(found->second, options_.targetEdgeLength);
    }

    static std::pair<int, int> chordKey(const CrossSection& section) {
        return std::minmax(section.leftPolygonIndex, section.rightPolygonIndex);
    }

    int addVertex(const Vec3& position, const VertexOrigin& origin) {
        positions_.push_back(position);
        origins_.push_back(origin);
        return static_cast<int>(positions_.size()) - 1;
    }

    // Outline vertices are shared by polygon index between regions.
    int outlineVertex(int polygonIndex, const Vec2& p, VertexOrigin origin) {
        origin.onOutline = true;
        if (polygonIndex < 0)
            return addVertex(Vec3(p.x(), p.y(), 0.0), origin);
        int& vertex = polygonVertex_[polygonIndex];
        if (vertex < 0)
            vertex = addVertex(Vec3(p.x(), p.y(), 0.0), origin);
        return vertex;
    }

    // A semicircle over the chord, sampled uniformly in arc length (paper
    // 2.2): theta = 0 at the left end point, pi at the right one.
    std::vector<int> addRing(const CrossSection& section, const VertexOrigin& origin) {
        const double radius = section.radius();
        const double spacing = section.spacing > 0
                                   ? std::min(section.spacing, options_.targetEdgeLength)
                                   : options_.targetEdgeLength;
        // Cap slices shrink towards the tip; below six segments the last
        // rings make a pyramid of the tip (a crease of 45 degrees or more).
        constexpr int kMinimumCapSegments = 10;
        // A body section is a ring of at least 12, even where a
        // hair-thin limb's radius falls below the floor of the local edge
        // length (1/16 of the target), as just before a thin tip.
        constexpr int kMinimumBodySegments = 6;
        const int minimum = section.inCap ? kMinimumCapSegments : kMinimumBodySegments;
        const int segments =
            std::max(minimum, static_cast<int>(std::lround(std::numbers::pi * radius / spacing)));
        const Vec2 centre = section.centre();
        const Vec2 direction =
            radius > 0 ? Vec2((section.right - section.left) / (2 * radius)) : Vec2(1, 0);
        std::vector<int> ring{outlineVertex(section.leftPolygonIndex, section.left, origin)};
        for (int j = 1; j < segments; ++j) {
            double theta = std::numbers::pi * j / segments;
            Vec2 p = centre - radius * std::cos(theta) * direction;
            ring.push_back(addVertex(Vec3(p.x(), p.y(), radius * std::sin(theta)), origin));
        }
        ring.push_back(outlineVertex(section.rightPolygonIndex, section.right, origin));
        return ring;
    }

    // Triangle strip between consecutive semicircles with possibly different
    // sample counts: advance on whichever ring lags behind in angle. With the
    // left end point at theta = 0, these triangles face outward.
    void stitch(const std::vector<int>& a, const std::vector<int>& b) {
        const int na = static_cast<int>(a.size()) - 1, nb = static_cast<int>(b.size()) - 1;
        int i = 0, j = 0;
        while (i < na || j < nb) {
            bool advanceA = i == na ? false : j == nb ? true : (i + 1) * nb <= (j + 1) * na;
            if (advanceA) {
                addStripFace({a[i], a[i + 1], b[j]});
                ++i;
            } else {
                addStripFace({a[i], b[j + 1], b[j]});
                ++j;
            }
        }
    }

    // Neighbouring rings may share an outline vertex (a cap tip on an end
    // point of the last section, as on a circle): the strip triangle there
    // collapses to an edge and the next one already covers the gap.
    void addStripFace(const std::array<int, 3>& face) {
        if (face[0] != face[1] && face[1] != face[2] && face[2] != face[0])
            faces_.push_back(face);
    }

    const Decomposition& decomposition_;
    const SurfaceOptions& options_;
    std::vector<int> polygonVertex_;
    std::vector<Vec3> positions_;
    std::vector<VertexOrigin> origins_;
    std::vector<std::array<int, 3>> faces_;
    std::map<std::pair<int, int>, std::vector<int>> portRings_;
    std::map<int, double> portSpacing_;
};

// Anchor weights for Least-Squares Meshes (paper 2.2): zero inside
// connecting regions (their outline vertices are held), growing with the distance along the axis
// from the nearest connecting region in cylindrical ones.
std::vector<double> anchorWeights(const SketchSurface& surface, const Decomposition& decomposition,
                                  const std::vector<CylinderSections>& cylinders,
                                  const SurfaceOptions& options) {
    std::vector<double> weights(surface.mesh.vertices.size(), 0.0);
    std::vector<std::vector<SectionGap>> gaps;
    for (const CylinderSections& c : cylinders)
        gaps.push_back(sectionGaps(c, options.targetEdgeLength));
    for (std::size_t v = 0; v < weights.size(); ++v) {
        const VertexOrigin& origin = surface.origins[v];
        if (origin.kind != RegionKind::Cylindrical) {
            // The outline of a connecting region is the sketch itself: held,
            // so the silhouette does not shrink at junctions.
            if (origin.onOutline)
                weights[v] = options.maxAnchorWeight;
            continue;
        }
        const CylinderRegion& region = decomposition.cylinders[origin.region];
        const CylinderSections& sections = cylinders[origin.region];
        double distance = std::numeric_limits<double>::infinity();
        if (region.startConnecting >= 0)
            distance = std::min(distance, origin.axisPosition - sections.axisPosition.front());
        if (region.endConnecting >= 0)
            distance = std::min(distance, sections.axisPosition.back() - origin.axisPosition);
        double diameter = 0.0;
        for (const auto& s : sections.sections)
            diameter += 2.0 * s.radius();
        diameter /= static_cast<double>(sections.sections.size());
        double falloff = std::max(options.anchorFalloff * diameter, 1e-12);
        weights[v] = options.maxAnchorWeight * std::clamp(distance / falloff, 0.0, 1.0);
        // A cap's slices twist and crowd near its tip (they join the k-th
        // points of its two sides): held softly, LSM rounds the tip.
        const bool inCap = origin.section < 0 || sections.sections[origin.section].inCap;
        if (inCap && !origin.onOutline)
            weights[v] = std::min(weights[v], options.capAnchorWeight);
        // Across a gap left by dropped cap slices the strip is a step:
        // free at the two sections bounding it, rising over the gap's
        // length (SectionGaps.h). Its outline vertices stay held.
        if (!origin.onOutline)
            for (const SectionGap& gap : gaps[origin.region]) {
                const double away =
                    std::max(0.0, std::abs(origin.axisPosition - gap.axisPosition) - gap.halfWidth);
                weights[v] = std::min(
                    weights[v], options.maxAnchorWeight * std::clamp(away / gap.length, 0.0, 1.0));
            }
    }
    return weights;
}

// Restores exact mirror symmetry after the (symmetric) solve.
void symmetrize(SketchSurface& surface) {
    auto& p = surface.mesh.vertices;
    for (std::size_t v = 0; v < p.size(); ++v) {
        int m = surface.mirror[v];
        if (m == static_cast<int>(v)) {
            p[v].z() = 0.0;
        } else if (m > static_cast<int>(v)) {
            Vec3 upper = 0.5 * (p[v] + Vec3(p[m].x(), p[m].y(), -p[m].z()));
            p[v] = upper;
            p[m] = Vec3(upper.x(), upper.y(), -upper.z());
        }
    }
}

}  // namespace

SketchSurface buildSurface(const Decomposition& decomposition,
                           const std::vector<CylinderSections>& cylinders,
                           const SurfaceOptions& options) {
    if (!(options.targetEdgeLength > 0))
        throw Error(MessageId::EdgeLengthMustBePositive);
    HalfSurfaceBuilder builder(decomposition, options);
    for (std::size_t c = 0; c < cylinders.size(); ++c)
        builder.addCylinder(static_cast<int>(c), cylinders[c]);
    for (std::size_t r = 0; r < decomposition.connecting.size(); ++r)
        builder.addConnectingRegion(static_cast<int>(r));
    SketchSurface surface = builder.mirrored();
    if (options.smooth)
        smoothSurface(surface, decomposition, cylinders, options);
    return surface;
}

void smoothSurface(SketchSurface& surface, const Decomposition& decomposition,
                   const std::vector<CylinderSections>& cylinders, const SurfaceOptions& options) {
    constexpr double kOutlineShift = 0.5;  // target edge lengths
    std::vector<double> weights = anchorWeights(surface, decomposition, cylinders, options);
    const std::vector<double> rims = inflatePatchRims(
        surface, decomposition, cylinders, options.capAnchorWeight, options.maxAnchorWeight);
    for (std::size_t v = 0; v < weights.size(); ++v)
        weights[v] = std::max(weights[v], rims[v]);
    // The surface and its weights are mirror-symmetric: LSM solves on half
    // the unknowns (LeastSquaresMesh.h); symmetrize restores the symmetry
    // where the mesh is not exactly its own image and the full system ran.
    surface.mesh.vertices =
        leastSquaresMesh(surface.mesh, weights, options.maxAnchorWeight, surface.mirror);
    symmetrize(surface);
    // LSM bounds no angle between neighbouring faces: the folds it leaves
    // where the surface turns sharply in little room are spread over their
    // neighbourhood (FoldRelaxation.h); one left at an outline vertex, by
    // moving the outline there within half an edge length in the plane.
    FoldRelaxationOptions relaxation;
    relaxation.outlineShift = kOutlineShift * options.targetEdgeLength;
    relaxFolds(surface, relaxation);
}

}  // namespace rigmesh
