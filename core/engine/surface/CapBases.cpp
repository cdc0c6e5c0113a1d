#include "surface/CapBases.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "sketch/PolygonGeometry.h"

namespace rigmesh {
namespace {

// A cap base more askew than this (degrees) leaves a ring tilted against
// both the body's sections and the cap's slices: a crease of 40 degrees
// across a thin limb. The zigzag of a triangulation's chords is
// about +-10 degrees, so about half of all limbs end on a skew chord.
constexpr double kAskewDegrees = 8.0;
// An outline turn (degrees) at a cap base's end point above which the
// corner stays a crease: only the cap's own path is rounded.
constexpr double kCornerDegrees = 40.0;
// At most this many chords move from the body to a cap.
constexpr int kMaxMovedChords = 3;
// The axis direction at a chord runs to the centre of the chord this many further on.
constexpr int kAxisReach = 6;
// A chord further in must be this much (degrees per chord) less askew to be chosen.
constexpr double kPreferEndDegrees = 1.0;

double degrees(double radians) {
    return radians * 180.0 / std::numbers::pi;
}

class CapBaseChooser {
  public:
    CapBaseChooser(const Decomposition& decomposition, const CylinderRegion& cylinder)
        : points_(decomposition.axis.cdt.points),
          cylinder_(cylinder),
          size_(static_cast<int>(points_.size())) {}

    // The chord the cap at `end` (0 or the last index) should start from;
    // `inward` (+1 or -1) points into the body.
    int base(int end, int inward) const {
        int chosen = end;
        while (cornerTurn(chosen) > kCornerDegrees && std::abs(chosen - end) < kMaxMovedChords)
            chosen += inward;
        if (chosen != end || skew(end, inward) <= kAskewDegrees)
            return chosen;
        double best = skew(end, inward);
        for (int k = 1; k <= kMaxMovedChords; ++k) {
            const double cost = skew(end + k * inward, inward) + kPreferEndDegrees * k;
            if (cost < best) {
                best = cost;
                chosen = end + k * inward;
            }
        }
        return chosen;
    }

    // Polygon indices from `from` to `to`, counter-clockwise, both included.
    std::vector<int> run(int from, int to) const {
        std::vector<int> indices;
        for (int i = from; i != to; i = (i + 1) % size_)
            indices.push_back(i);
        indices.push_back(to);
        return indices;
    }

  private:
    Vec2 centre(int chord) const {
        const auto& c = cylinder_.chords[chord];
        return 0.5 * (points_[c[0]] + points_[c[1]]);
    }

    // The chord's angle (degrees) to the perpendicular of the axis through
    // its centre and the centre of the chord kAxisReach further in.
    double skew(int chord, int inward) const {
        const auto& c = cylinder_.chords[chord];
        const Vec2 direction = (points_[c[1]] - points_[c[0]]).normalized();
        const Vec2 along = (centre(chord + kAxisReach * inward) - centre(chord)).normalized();
        return degrees(std::asin(std::min(1.0, std::abs(direction.dot(along)))));
    }

    // The larger outline turn (degrees) at the chord's two end points.
    double cornerTurn(int chord) const {
        double most = 0.0;
        for (int v : cylinder_.chords[chord]) {
            const Vec2 in = points_[v] - points_[(v - 1 + size_) % size_];
            const Vec2 out = points_[(v + 1) % size_] - points_[v];
            most = std::max(most, std::abs(turnAngle(in, out)));
        }
        return degrees(most);
    }

    const std::vector<Vec2>& points_;
    const CylinderRegion& cylinder_;
    int size_;
};

// `cap` runs counter-clockwise from one end point of the old base chord to
// the other; the new cap runs from `fromPoint` to `toPoint`, the new base's
// end points, through it.
std::vector<int> widenedCap(const CapBaseChooser& chooser, const std::vector<int>& cap,
                            int fromPoint, int toPoint) {
    std::vector<int> widened = chooser.run(fromPoint, cap.front());
    widened.pop_back();
    widened.insert(widened.end(), cap.begin(), cap.end());
    const std::vector<int> tail = chooser.run(cap.back(), toPoint);
    widened.insert(widened.end(), tail.begin() + 1, tail.end());
    return widened;
}

}  // namespace

CylinderRegion withCapBases(const Decomposition& decomposition, int cylinderIndex) {
    const CylinderRegion& cylinder = decomposition.cylinders[cylinderIndex];
    const int count = static_cast<int>(cylinder.chords.size());
    if (count <= 2 * (kAxisReach + kMaxMovedChords))
        return cylinder;
    const CapBaseChooser chooser(decomposition, cylinder);
    const int first = cylinder.startCap.empty() ? 0 : chooser.base(0, 1);
    const int last = cylinder.endCap.empty() ? count - 1 : chooser.base(count - 1, -1);
    if (first == 0 && last == count - 1)
        return cylinder;
    CylinderRegion result = cylinder;
    result.chords.assign(cylinder.chords.begin() + first, cylinder.chords.begin() + last + 1);
    // startCap runs from the front chord's left end point to its right one,
    // endCap from the back chord's right end point to its left one.
    if (first > 0)
        result.startCap = widenedCap(chooser, cylinder.startCap, result.chords.front()[0],
                                     result.chords.front()[1]);
    if (last < count - 1)
        result.endCap =
            widenedCap(chooser, cylinder.endCap, result.chords.back()[1], result.chords.back()[0]);
    return result;
}

}  // namespace rigmesh
