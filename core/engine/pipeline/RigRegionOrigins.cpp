#include "pipeline/RigRegionOrigins.h"

#include <algorithm>
#include <limits>
#include <map>
#include <utility>

#include "sketch/PolygonGeometry.h"

namespace rigmesh {
namespace {

using ChordKey = std::pair<int, int>;

ChordKey keyOf(const PolygonEdge& chord) {
    return std::minmax(chord[0], chord[1]);
}

// Where a surface region lands among the rig's regions.
struct Target {
    RegionKind kind = RegionKind::Connecting;
    int region = -1;
    bool identical = false;  // same region: origins keep their section
};

// Moves `best` to the section of rig cylinder `c` nearest p (or one of its
// tips, with `tipsToo`) when it is nearer than `distance`, which follows.
void nearerSectionOf(const std::vector<CylinderSections>& rigCylinders, int c, const Vec2& p,
                     bool tipsToo, double& distance, VertexOrigin& best) {
    const CylinderSections& cylinder = rigCylinders[c];
    for (std::size_t s = 0; s < cylinder.sections.size(); ++s) {
        const double d =
            distanceToSegment(p, cylinder.sections[s].left, cylinder.sections[s].right);
        if (d < distance) {
            distance = d;
            best = {RegionKind::Cylindrical, c, static_cast<int>(s), cylinder.axisPosition[s],
                    false};
        }
    }
    if (!tipsToo)
        return;
    if (cylinder.startTip && (p - *cylinder.startTip).norm() < distance) {
        distance = (p - *cylinder.startTip).norm();
        best = {RegionKind::Cylindrical, c, -1, 0.0, false};
    }
    if (cylinder.endTip && (p - *cylinder.endTip).norm() < distance) {
        distance = (p - *cylinder.endTip).norm();
        best = {RegionKind::Cylindrical, c, -1, cylinder.endTipPosition, false};
    }
}

}  // namespace

bool sameRegions(const Decomposition& surface, const Decomposition& rig) {
    if (surface.cylinders.size() != rig.cylinders.size() ||
        surface.connecting.size() != rig.connecting.size())
        return false;
    for (std::size_t c = 0; c < surface.cylinders.size(); ++c)
        if (surface.cylinders[c].chords != rig.cylinders[c].chords)
            return false;
    return true;
}

void mapOriginsToRigRegions(SketchSurface& surface, const Decomposition& surfaceRegions,
                            const std::vector<CylinderSections>& surfaceCylinders,
                            const Decomposition& rigRegions,
                            const std::vector<CylinderSections>& rigCylinders) {
    // Each body chord of the rig belongs to one cylinder; each junction
    // triangle to one connecting region.
    std::map<ChordKey, int> rigCylinderOfChord;
    for (std::size_t c = 0; c < rigRegions.cylinders.size(); ++c)
        for (const PolygonEdge& chord : rigRegions.cylinders[c].chords)
            rigCylinderOfChord[keyOf(chord)] = static_cast<int>(c);
    std::map<int, int> rigRegionOfJunction;
    for (std::size_t r = 0; r < rigRegions.connecting.size(); ++r)
        for (int t : rigRegions.connecting[r].junctions)
            rigRegionOfJunction[t] = static_cast<int>(r);

    auto cylinderOfChords = [&](const std::vector<PolygonEdge>& chords) {
        for (const PolygonEdge& chord : chords)
            if (auto found = rigCylinderOfChord.find(keyOf(chord));
                found != rigCylinderOfChord.end())
                return found->second;
        return -1;
    };
    std::vector<Target> cylinderTarget(surfaceRegions.cylinders.size());
    for (std::size_t c = 0; c < surfaceRegions.cylinders.size(); ++c) {
        const CylinderRegion& piece = surfaceRegions.cylinders[c];
        const int rig = cylinderOfChords(piece.chords);
        cylinderTarget[c] = {RegionKind::Cylindrical, rig,
                             rig >= 0 && rigRegions.cylinders[rig].chords == piece.chords};
    }
    std::vector<Target> connectingTarget(surfaceRegions.connecting.size());
    for (std::size_t r = 0; r < surfaceRegions.connecting.size(); ++r) {
        const ConnectingRegion& region = surfaceRegions.connecting[r];
        for (int t : region.junctions)
            if (auto found = rigRegionOfJunction.find(t); found != rigRegionOfJunction.end())
                connectingTarget[r] = {RegionKind::Connecting, found->second, true};
        if (connectingTarget[r].region >= 0)
            continue;
        // A bump patch: part of the rig cylinder its ports came from.
        for (const auto& port : region.ports) {
            const int rig = cylinderTarget[port.cylinder].region;
            if (rig >= 0)
                connectingTarget[r] = {RegionKind::Cylindrical, rig, false};
        }
    }

    // A ring's vertices all go to the section found for its first one.
    std::map<std::pair<int, int>, VertexOrigin> ringOrigin;
    for (std::size_t v = 0; v < surface.origins.size(); ++v) {
        VertexOrigin& origin = surface.origins[v];
        const Target& target = origin.kind == RegionKind::Cylindrical
                                   ? cylinderTarget[origin.region]
                                   : connectingTarget[origin.region];
        if (target.region < 0) {
            // Nothing in the rig matches (not expected): leave it to the
            // visibility test, as a connecting vertex.
            origin = {RegionKind::Connecting, -1, -1, 0.0, origin.onOutline};
            continue;
        }
        if (target.identical) {
            origin.region = target.region;
            continue;
        }
        // The rig cylinder's cross section nearest the vertex (a ring's
        // vertices all go by their section's centre), or its tip.
        const bool onRing = origin.kind == RegionKind::Cylindrical && origin.section >= 0;
        const std::pair<int, int> ringKey{origin.region, origin.section};
        if (onRing) {
            if (auto found = ringOrigin.find(ringKey); found != ringOrigin.end()) {
                origin = {found->second.kind, found->second.region, found->second.section,
                          found->second.axisPosition, origin.onOutline};
                continue;
            }
        }
        const Vec2 p = onRing ? surfaceCylinders[origin.region].sections[origin.section].centre()
                              : Vec2(surface.mesh.vertices[v].head<2>());
        double distance = std::numeric_limits<double>::infinity();
        VertexOrigin nearest{RegionKind::Cylindrical, target.region, -1, 0.0, false};
        nearerSectionOf(rigCylinders, target.region, p, true, distance, nearest);
        nearest.onOutline = origin.onOutline;
        origin = nearest;
        if (onRing)
            ringOrigin[ringKey] = origin;
    }
}

void mapOriginsByNearestSection(SketchSurface& surface, const Decomposition& surfaceRegions,
                                const std::vector<CylinderSections>& surfaceCylinders,
                                const Decomposition& rigRegions,
                                const std::vector<CylinderSections>& rigCylinders) {
    // The rig section (or tip) nearest a point, over every rig cylinder.
    auto nearestSection = [&](const Vec2& p, bool tipsToo) {
        VertexOrigin best{RegionKind::Connecting, -1, -1, 0.0, false};
        double distance = std::numeric_limits<double>::infinity();
        for (std::size_t c = 0; c < rigCylinders.size(); ++c)
            nearerSectionOf(rigCylinders, static_cast<int>(c), p, tipsToo, distance, best);
        return best;
    };
    const auto& axis = rigRegions.axis;
    std::map<std::pair<int, int>, VertexOrigin> ringOrigin;
    for (std::size_t v = 0; v < surface.origins.size(); ++v) {
        VertexOrigin& origin = surface.origins[v];
        const bool onOutline = origin.onOutline;
        const Vec2 p = surface.mesh.vertices[v].head<2>();
        if (origin.kind == RegionKind::Cylindrical && origin.section >= 0) {
            const std::pair<int, int> key{origin.region, origin.section};
            auto found = ringOrigin.find(key);
            if (found == ringOrigin.end())
                found =
                    ringOrigin
                        .emplace(
                            key,
                            nearestSection(
                                surfaceCylinders[origin.region].sections[origin.section].centre(),
                                false))
                        .first;
            origin = found->second;
        } else if (origin.kind == RegionKind::Cylindrical || rigRegions.connecting.empty() ||
                   surfaceRegions.connecting[origin.region].junctions.empty()) {
            origin = nearestSection(p, true);
        } else {
            double distance = std::numeric_limits<double>::infinity();
            int region = -1;
            for (std::size_t r = 0; r < rigRegions.connecting.size(); ++r)
                for (int t : rigRegions.connecting[r].junctions)
                    if ((axis.centroid(t) - p).norm() < distance) {
                        distance = (axis.centroid(t) - p).norm();
                        region = static_cast<int>(r);
                    }
            origin = {RegionKind::Connecting, region, -1, 0.0, false};
        }
        origin.onOutline = onOutline;
    }
}

}  // namespace rigmesh
