// Down-sampling a chordal axis into skeletal joints (paper section 2.3):
// plain Douglas-Peucker and the paper's Cylindrical Douglas-Peucker (CDP).
//
// Both are the same greedy divide and conquer: a range [i, j] of the axis
// v_0 .. v_{n-1} is accepted as one bone if every sample strictly inside has
// an error within the threshold; otherwise it is split at the sample of
// largest error (the earliest on ties). Both return the sorted indices of the
// kept samples, always including the first and the last.
//
// Thresholds are absolute lengths in the sketch plane; callers make them
// relative to the part's size (for instance a fraction of its mean chord
// length). Both are invariant under scaling the axis and threshold together.
#pragma once

#include <vector>

#include "base/Types.h"

namespace rigmesh {

// One sample of a (smoothed) chordal axis: the axis point and the two end
// points of its (smoothed) chord, all in the sketch plane.
struct AxisSample {
    Vec2 point;
    Vec2 chordA, chordB;
};

// Douglas & Peucker 1973. Error of v in [i, j]: e_DP = distance from v to the
// segment v_i v_j; split while max e_DP > threshold. Chords are ignored,
// which is why a straight axis with an abrupt change of thickness stays one
// bone (paper Fig. 4, top row).
std::vector<int> douglasPeucker(const std::vector<AxisSample>& axis, double threshold);

// The symmetric trapezoid ABCD a range [i, j] induces in CDP (paper Fig. 5).
// With u the unit direction of v_i v_j and n = u rotated by +90 degrees, the
// chords through v_i and v_j are projected onto n, giving half-widths
// h_i = |(chordA_i - chordB_i) . n| / 2 and h_j likewise; then
//   A = v_i + h_i n,  B = v_i - h_i n,  C = v_j - h_j n,  D = v_j + h_j n.
// AB and CD are the bases; AD is the side on the +n side of the axis and BC
// the side on the -n side. When v_i == v_j, u is taken perpendicular to the
// chord at v_i (or the x axis if that chord is degenerate too).
struct CdpTrapezoid {
    Vec2 a, b, c, d;
    Vec2 normal;  // n
};
CdpTrapezoid cdpTrapezoid(const AxisSample& first, const AxisSample& last);

// CDP error of a sample with chord end points E, F against a trapezoid:
//   e_CDP = e_1^2 + e_2^2,
// with e_1 the distance from the chord end point further along +n to the
// segment AD and e_2 the distance from the other end point to BC. Matching
// end points to sides by their order along n (rather than by which side of
// the axis each lies on) keeps the measure meaningful when a bent axis puts
// both end points on the same side.
double cdpError(const CdpTrapezoid& trapezoid, const AxisSample& sample);

// Cylindrical Douglas-Peucker (paper 2.3, Fig. 4 bottom row, Fig. 5): splits
// while max e_CDP > threshold^2. No separate axis-distance term is needed:
// moving the axis point off v_i v_j by d moves both chord end points, so with
// the widths matching e_CDP ~ 2 d^2 and a deviation d > threshold / sqrt(2)
// splits, as does a change of half-width by more than threshold / sqrt(2) on
// both sides (or by more than threshold on one side).
std::vector<int> cylindricalDouglasPeucker(const std::vector<AxisSample>& axis, double threshold);

// One sample of a curve skeleton in space (an imported mesh's):
// its point and the mean distance from it to the surface around it.
struct TubeSample {
    Vec3 point;
    double radius = 0.0;
};

// CDP's rule in space, where a sample has a radius instead of a chord. With
// d the distance from v_k to the segment v_i v_j and dr the difference
// between r_k and the radius interpolated linearly from r_i to r_j at v_k's
// projection, e_CDP = 2 (d^2 + dr^2): what the planar e_CDP gives for an
// axis moved by d or a width changed by dr on both sides. Splits while max
// e_CDP > threshold^2, so the same threshold means the same bones.
std::vector<int> cylindricalDouglasPeuckerInSpace(const std::vector<TubeSample>& tube,
                                                  double threshold);

}  // namespace rigmesh
