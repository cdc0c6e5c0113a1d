// Cross sections of a generalized cylinder (paper 2.2).
//
// The cylinder's chords are smoothed (Laplacian smoothing of the axis and of
// the chord directions, paper 2.1), then resampled so that adjacent cross
// sections are about one target edge length apart on their widest side
// without crossing each other. Caps continue the cylinder beyond its last
// chord: the outline around the tip is sliced perpendicular to the axis and
// the slices shrink to a single tip point.
#pragma once

#include <optional>
#include <vector>

#include "axis/Decomposition.h"

namespace rigmesh {

// A chord in the sketch plane, diameter of a circular cross section
// perpendicular to the plane. `left` and `right` are seen along the cylinder.
struct CrossSection {
    Vec2 left, right;
    int leftPolygonIndex = -1;   // outline index when `left` is an outline vertex to share
    int rightPolygonIndex = -1;  // likewise for `right`
    bool inCap = false;          // a slice of a cap rather than of the body
    // The local target edge length: the document's one, or less on a thin
    // part (CrossSectionOptions::radiusFraction); its semicircle and the
    // spacing to its neighbours follow it. 0 = the caller's edge length.
    double spacing = 0.0;
    // Where along the cylinder's smoothed chords (CylinderSections::axisChords)
    // a body section was taken, as a fractional index; -1 for a cap slice.
    double chordParameter = -1.0;

    Vec2 centre() const { return 0.5 * (left + right); }
    double radius() const { return 0.5 * (right - left).norm(); }
};

struct CylinderSections {
    std::vector<CrossSection> sections;  // from start to end, caps included
    std::optional<Vec2> startTip;        // the tip point before the first section
    std::optional<Vec2> endTip;          // the tip point after the last section
    int startTipPolygonIndex = -1;
    int endTipPolygonIndex = -1;
    // Arc length along the axis (section centres) from the start tip, or from
    // the first section when there is none; one value per section.
    std::vector<double> axisPosition;
    double startTipPosition = 0.0;
    double endTipPosition = 0.0;
    // The body's smoothed chords before resampling (paper 2.1): one per chord
    // of the chordal axis, so they depend on the outline alone, not on the
    // edge length. The skeleton (2.3) simplifies these, so a part gets the
    // same joints at any resolution; the first and last are the body's end
    // sections.
    std::vector<CrossSection> axisChords;
};

struct CrossSectionOptions {
    int axisSmoothingIterations = 8;  // Laplacian steps on the axis and chord directions
    double smoothingStep = 0.5;       // lambda of each step
    // Resolution follows thickness: the local edge length is at
    // most this fraction of the local radius, so a semicircle has at least
    // pi / radiusFraction segments (13 at 0.25: 26 vertices around a thin
    // part, neighbouring faces about 14 degrees apart; at 0.35 they were 20
    // degrees apart) while parts wider than
    // targetEdgeLength / radiusFraction keep the target edge length.
    double radiusFraction = 0.25;
    // Floor of the local edge length, as a fraction of the target one, so a
    // hair-thin neck cannot ask for an unbounded number of vertices.
    double minimumSpacingFraction = 1.0 / 16.0;
};

CylinderSections buildCrossSections(const Decomposition& decomposition, int cylinder,
                                    double targetEdgeLength,
                                    const CrossSectionOptions& options = {});

// True when the 2D segments ab and cd cross or touch.
bool segmentsIntersect(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d);

// True when two sections cross, or their end points on either side lie
// closer than 0.3 of the smaller spacing (around an outline corner one side
// barely moves): the strip between them would fold or be slivers.
bool sectionsClash(const CrossSection& a, const CrossSection& b);

}  // namespace rigmesh
