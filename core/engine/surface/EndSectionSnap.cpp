#include "surface/EndSectionSnap.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sketch/PolygonGeometry.h"

namespace rigmesh {
namespace {

// How many sections in from an end chord the outline still pulls. Sections
// are about one local edge length apart (a quarter of the radius on thin
// parts), so 8 reach about two radii. 3, 5, 8 and 12 were measured: the
// random outlines' worst fold is 29-33 degrees with each, and the IoU
// improves with the reach; 8 gave the shared sketches' lowest maximum.
constexpr int kSnapReach = 8;

// The nearest point to `p` on the closed outline's edges within `window`
// arc length of the outline point `anchor`, walking one way only
// (`direction` +1 counter-clockwise, -1 clockwise): along the body's side,
// never round the cap or the connecting region beyond the end chord.
Vec2 nearestAlongSide(const std::vector<Vec2>& outline, int anchor, int direction, const Vec2& p,
                      double window) {
    const int size = static_cast<int>(outline.size());
    Vec2 best = outline[anchor];
    double bestDistance = (p - best).norm();
    double walked = 0.0;
    for (int k = 0; k < size && walked <= window; ++k) {
        const Vec2& a = outline[((anchor + direction * k) % size + size) % size];
        const Vec2& b = outline[((anchor + direction * (k + 1)) % size + size) % size];
        const Vec2 q = closestPointOnSegment(p, a, b);
        if ((q - p).norm() < bestDistance) {
            bestDistance = (q - p).norm();
            best = q;
        }
        walked += (b - a).norm();
    }
    return best;
}

// Snaps the sections `end + inward`, `end + 2 inward`, ... of one cylinder,
// stopping short of `inwardLimit` sections. A section that would cross or
// crowd a neighbour as finally placed keeps its smoothed end points.
void snapFromEnd(std::vector<CrossSection>& sections, int end, int inward, int inwardLimit,
                 const std::vector<Vec2>& outline) {
    const CrossSection& fixed = sections[end];
    if (fixed.leftPolygonIndex < 0 || fixed.rightPolygonIndex < 0)
        return;
    // Into the body, the left side runs clockwise from a start chord and
    // counter-clockwise from an end chord (the caps run counter-clockwise
    // from the start chord's left end point and to the end chord's left one).
    const int leftDirection = -inward, rightDirection = inward;
    std::vector<int> moved;  // section indices, from the end inwards
    std::vector<CrossSection> smoothed;
    for (int j = 1; j < kSnapReach && j < inwardLimit; ++j) {
        const int s = end + j * inward;
        if (sections[s].inCap)
            break;
        CrossSection& section = sections[s];
        moved.push_back(s);
        smoothed.push_back(section);
        const double weight = 1.0 - static_cast<double>(j) / kSnapReach;
        // Search the outline as far along as the section is from the end, twice over.
        const double window = 2.0 * std::max((section.left - fixed.left).norm(),
                                             (section.right - fixed.right).norm()) +
                              section.spacing;
        const Vec2 left =
            nearestAlongSide(outline, fixed.leftPolygonIndex, leftDirection, section.left, window);
        const Vec2 right = nearestAlongSide(outline, fixed.rightPolygonIndex, rightDirection,
                                            section.right, window);
        section.left += weight * (left - section.left);
        section.right += weight * (right - section.right);
    }
    // Undo snaps that clash with a neighbour until none does.
    const int count = static_cast<int>(sections.size());
    for (bool changed = true; changed;) {
        changed = false;
        for (std::size_t k = 0; k < moved.size(); ++k) {
            const int s = moved[k];
            if (sections[s].left == smoothed[k].left && sections[s].right == smoothed[k].right)
                continue;
            const int next = s + inward;
            if (sectionsClash(sections[s], sections[s - inward]) ||
                (next >= 0 && next < count && sectionsClash(sections[s], sections[next]))) {
                sections[s] = smoothed[k];
                changed = true;
            }
        }
    }
}

}  // namespace

void snapSectionsNearEndsToOutline(std::vector<CylinderSections>& cylinders,
                                   const Decomposition& regions) {
    const std::vector<Vec2>& outline = regions.axis.cdt.points;
    for (CylinderSections& cylinder : cylinders) {
        std::vector<CrossSection>& sections = cylinder.sections;
        int first = 0, last = static_cast<int>(sections.size()) - 1;
        while (first <= last && sections[first].inCap)
            ++first;
        while (last >= first && sections[last].inCap)
            --last;
        if (last - first < 2)
            continue;
        const int half = (last - first) / 2;
        snapFromEnd(sections, first, 1, half + 1, outline);
        snapFromEnd(sections, last, -1, last - first - half, outline);
    }
}

}  // namespace rigmesh
