#include "axis/Decomposition.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include "axis/BodyBumps.h"
#include "base/Error.h"

namespace rigmesh {
namespace {

class UnionFind {
  public:
    explicit UnionFind(int size) : parent_(size) { std::iota(parent_.begin(), parent_.end(), 0); }
    int find(int x) { return parent_[x] == x ? x : parent_[x] = find(parent_[x]); }
    void unite(int a, int b) { parent_[find(a)] = find(b); }

  private:
    std::vector<int> parent_;
};

// Length of the branch's axis, from node centre through the chord midpoints.
double branchAxisLength(const ChordalAxis& axis, const AxisBranch& branch) {
    double length = (axis.centroid(branch.startNode) - axis.midpoint(branch.chords.front())).norm();
    for (std::size_t i = 1; i < branch.chords.size(); ++i)
        length += (axis.midpoint(branch.chords[i]) - axis.midpoint(branch.chords[i - 1])).norm();
    return length + (axis.midpoint(branch.chords.back()) - axis.centroid(branch.endNode)).norm();
}

double meanChordLength(const ChordalAxis& axis, const AxisBranch& branch) {
    double sum = 0.0;
    for (const auto& chord : branch.chords)
        sum += axis.length(chord);
    return sum / static_cast<double>(branch.chords.size());
}

// Counter-clockwise outline path from polygon index `from` to `to`.
std::vector<int> outlinePath(int from, int to, int size) {
    std::vector<int> path{from};
    for (int i = from; i != to;) {
        i = (i + 1) % size;
        path.push_back(i);
    }
    return path;
}

bool isJunction(const ChordalAxis& axis, int triangle) {
    return axis.kind[triangle] == TriangleKind::Junction;
}

int sharedEndpoint(const PolygonEdge& a, const PolygonEdge& b) {
    if (a[0] == b[0] || a[0] == b[1])
        return a[0];
    if (a[1] == b[0] || a[1] == b[1])
        return a[1];
    return -1;
}

// Near a junction, and at a blunt end, the CDT often fans out from one
// concave outline vertex (an armpit, a crotch, the corner of a flat end):
// consecutive chords share that vertex and turn around it, so cross sections
// there would crowd on one side and the axis would bend into the corner.
// Returns how many leading chords of `chords` (from the junction or tip side)
// end inside such fans, at most `limit`: up to two fans of at least four
// chords each, each starting within a few chords of the previous one.
int fanLength(const std::vector<PolygonEdge>& chords, int limit) {
    constexpr int kLookAhead = 8;   // chords a fan may start after the current end
    constexpr int kMinimumRun = 3;  // chords after the first sharing the pivot
    const int count = static_cast<int>(chords.size());
    int absorbed = 0;
    for (int fan = 0; fan < 2; ++fan) {
        int found = -1;
        for (int start = absorbed; start <= absorbed + kLookAhead && start + 1 < count; ++start) {
            int pivot = sharedEndpoint(chords[start], chords[start + 1]);
            int end = start + 1;
            while (end + 1 < count && (chords[end + 1][0] == pivot || chords[end + 1][1] == pivot))
                ++end;
            if (end - start >= kMinimumRun && end <= limit) {
                found = end;
                break;
            }
        }
        if (found < 0)
            break;
        absorbed = found;
    }
    return absorbed;
}

// A sleeve triangle with a pruned neighbour: a junction whose third branch
// was only a bump of the outline (2.1's pruning).
bool carriesPrunedBump(const ChordalAxis& axis, int sleeve) {
    for (int n : axis.cdt.neighbors[sleeve])
        if (n >= 0 && axis.pruned[n])
            return true;
    return false;
}

// Grows the cap at a terminal end: returns how many chords it swallows, at
// most `limit`; `sleeves` and `chords` run from the tip inward. The cap takes
// what Teddy's circle test allows (the region so far lies within the circle
// of the next chord) and also fans of chords around one corner of a blunt
// end, whose axis would otherwise bend into that corner; the two alternate
// until neither applies.
int capLength(const ChordalAxis& axis, int terminal, const std::vector<int>& sleeves,
              const std::vector<PolygonEdge>& chords, int limit, double factor) {
    std::vector<int> region{terminal};
    int swallowed = 0;
    for (bool fanned = true; fanned;) {
        while (swallowed < limit) {
            std::vector<int> grown = region;
            grown.push_back(sleeves[swallowed]);
            if (!axis.outlineInsideChordCircle(grown, chords[swallowed + 1], factor))
                break;
            region = std::move(grown);
            ++swallowed;
        }
        std::vector<PolygonEdge> rest(chords.begin() + swallowed, chords.end());
        int fan = fanLength(rest, limit - swallowed);
        for (int i = 0; i < fan; ++i)
            region.push_back(sleeves[swallowed + i]);
        swallowed += fan;
        // A pruned bump hanging off the next sleeve (a former junction next
        // to the tip, as where a bridged gap leaves a corner beside a round
        // end) belongs to the cap: past it, its outline would be in no region
        // and the surface would miss it.
        int bumps = 0;
        while (swallowed + bumps < limit && carriesPrunedBump(axis, sleeves[swallowed + bumps]))
            region.push_back(sleeves[swallowed + bumps++]);
        swallowed += bumps;
        fanned = fan > 0 || bumps > 0;  // after a fan the circle test may pass again
    }
    return swallowed;
}

// Moves the fan sleeves next to junctions from the branch into the
// connecting regions, keeping at least half of the branch's chords.
void absorbJunctionFans(AxisBranch& branch, std::vector<int>& regionOfTriangle,
                        std::vector<ConnectingRegion>& connecting, bool startAtJunction,
                        bool endAtJunction) {
    const int limit = static_cast<int>(branch.chords.size()) / 4;
    if (startAtJunction) {
        int count = fanLength(branch.chords, limit);
        int region = regionOfTriangle[branch.startNode];
        for (int i = 0; i < count; ++i) {
            regionOfTriangle[branch.sleeves[i]] = region;
            connecting[region].triangles.push_back(branch.sleeves[i]);
        }
        branch.sleeves.erase(branch.sleeves.begin(), branch.sleeves.begin() + count);
        branch.chords.erase(branch.chords.begin(), branch.chords.begin() + count);
    }
    if (endAtJunction) {
        std::vector<PolygonEdge> reversed(branch.chords.rbegin(), branch.chords.rend());
        int count = fanLength(reversed, limit);
        int region = regionOfTriangle[branch.endNode];
        for (int i = 0; i < count; ++i) {
            int sleeve = branch.sleeves[branch.sleeves.size() - 1 - i];
            regionOfTriangle[sleeve] = region;
            connecting[region].triangles.push_back(sleeve);
        }
        branch.sleeves.resize(branch.sleeves.size() - count);
        branch.chords.resize(branch.chords.size() - count);
    }
}

// The chords a branch's ends give away: to a cap at a terminal (as step 5
// grows it) or to a junction's fans (as step 3 absorbs them). What is left
// is the branch's body, sleeves [first, second).
std::array<int, 2> bodySleeves(const ChordalAxis& axis, const AxisBranch& branch,
                               const std::vector<bool>& node, const DecompositionOptions& options) {
    const int chordCount = static_cast<int>(branch.chords.size());
    const bool startIsCap = !node[branch.startNode];
    const bool endIsCap = !node[branch.endNode];
    int fromStart = 0, fromEnd = 0;
    if (startIsCap) {
        const int limit = endIsCap ? (chordCount - 1) / 2 : chordCount - 1;
        fromStart = capLength(axis, branch.startNode, branch.sleeves, branch.chords, limit,
                              options.capCircleFactor);
    } else {
        fromStart = fanLength(branch.chords, chordCount / 4);
    }
    std::vector<int> sleeves(branch.sleeves.rbegin(), branch.sleeves.rend());
    std::vector<PolygonEdge> reversed(branch.chords.rbegin(), branch.chords.rend());
    if (endIsCap)
        fromEnd = capLength(axis, branch.endNode, sleeves, reversed, chordCount - 1 - fromStart,
                            options.capCircleFactor);
    else
        fromEnd = fanLength(reversed, chordCount / 4);
    return {fromStart, static_cast<int>(branch.sleeves.size()) - fromEnd};
}

// The sleeves [lo, hi] of `branch` whose patch carries the pruned bump off
// sleeve s: the sleeve's two chords meet at one point across the body, so
// on a bump narrower than half the body (a short limb the chordal axis
// prunes) its patch alone was a sliver between two body pieces and came
// out as a horn with a fold around it, or, left to the body's sections, the
// bump was cut off in a wall. The run takes in the body sleeves on either
// side, one at a time, until its end chords stand `wanted` apart on the
// bump's side, as a wide bump's do, staying within the body [first, end).
std::array<int, 2> bumpRun(const ChordalAxis& axis, const AxisBranch& branch, int s, int first,
                           int end, double wanted) {
    // The chords' shared end is the apex across the body; the bump is on
    // the other side (PolygonEdge is (left, right) along the branch).
    const int side = branch.chords[s][0] == branch.chords[s + 1][0] ? 1 : 0;
    int lo = s, hi = s;
    auto span = [&] {
        return (axis.cdt.points[branch.chords[lo][side]] -
                axis.cdt.points[branch.chords[hi + 1][side]])
            .norm();
    };
    while (span() < wanted) {
        const bool before = lo > first, after = hi + 1 < end;
        if (!before && !after)
            break;
        if (before)
            --lo;
        if (after && span() < wanted)
            ++hi;
    }
    return {lo, hi};
}

// Splits branches where a body sleeve carries a pruned bump high enough to
// see (BodyBumps.h): the sleeve becomes a node, so it and its bump form a
// connecting region. Runs of such sleeves are `forcedMerge` pieces, as are
// pieces of fewer than three chords between two nodes (no room for a body).
std::vector<AxisBranch> splitAtBodyBumps(const ChordalAxis& axis, std::vector<bool>& node,
                                         std::vector<bool>& forcedMerge,
                                         const DecompositionOptions& options) {
    std::vector<AxisBranch> branches;
    if (!std::isfinite(options.bumpHeightFactor)) {
        forcedMerge.assign(axis.branches.size(), false);
        return axis.branches;
    }
    // The outline's own spacing: most of its edges (thin parts are refined
    // to shorter ones, sketch/ThinPartRefinement.h), so the 90th percentile.
    const int pointCount = static_cast<int>(axis.cdt.points.size());
    std::vector<double> edges;
    for (int i = 0; i < pointCount; ++i)
        edges.push_back((axis.cdt.points[(i + 1) % pointCount] - axis.cdt.points[i]).norm());
    const auto percentile = edges.begin() + static_cast<long>(0.9 * (edges.size() - 1));
    std::nth_element(edges.begin(), percentile, edges.end());
    const double minimumHeight = options.bumpHeightFactor * *percentile;
    for (const AxisBranch& branch : axis.branches) {
        const auto [first, end] = bodySleeves(axis, branch, node, options);
        std::vector<std::array<int, 2>> runs;
        for (int s = first; s < end; ++s) {
            const PrunedBump bump = prunedBumpOf(axis, branch.sleeves[s]);
            if (bump.height < minimumHeight)
                continue;
            const double body =
                0.5 * (axis.length(branch.chords[s]) + axis.length(branch.chords[s + 1]));
            runs.push_back(bumpRun(axis, branch, s, first, end, 0.5 * body));
        }
        // A narrow bump's run that leaves no body piece between it and
        // another bump's (they meet, or the piece between is short-yet-wide
        // and merges, step 1) makes one patch of both: a row of short legs
        // became one patch along the whole body, folded at every leg. Such
        // bumps stay with the body's sections.
        auto noBodyBetween = [&](const std::array<int, 2>& a, const std::array<int, 2>& b) {
            if (b[0] <= a[1] + 1)
                return true;
            AxisBranch between;
            between.startNode = branch.sleeves[a[1]];
            between.endNode = branch.sleeves[b[0]];
            between.chords.assign(branch.chords.begin() + a[1] + 1,
                                  branch.chords.begin() + b[0] + 1);
            return between.chords.size() < 3 ||
                   branchAxisLength(axis, between) <
                       options.mergeLengthFactor * meanChordLength(axis, between);
        };
        std::vector<bool> inRun(branch.sleeves.size(), false);
        for (std::size_t r = 0; r < runs.size(); ++r) {
            const auto [lo, hi] = runs[r];
            const bool grown = hi > lo;
            const bool crowded = std::any_of(runs.begin(), runs.end(), [&](const auto& other) {
                if (&other == &runs[r])
                    return false;
                if (other[1] >= lo && other[0] <= hi)  // they overlap
                    return true;
                return other[0] > hi ? noBodyBetween(runs[r], other)
                                     : noBodyBetween(other, runs[r]);
            });
            if (grown && crowded)
                continue;
            std::fill(inRun.begin() + lo, inRun.begin() + hi + 1, true);
        }
        std::vector<int> bumps;
        for (int s = first; s < end; ++s)
            if (inRun[s])
                bumps.push_back(s);
        if (bumps.empty()) {
            branches.push_back(branch);
            forcedMerge.push_back(false);
            continue;
        }
        // The ends of each run of bump sleeves are nodes; the sleeves between
        // them reach the region through the run's merged piece.
        for (std::size_t i = 0; i < bumps.size(); ++i) {
            const bool runStart = i == 0 || bumps[i - 1] != bumps[i] - 1;
            const bool runEnd = i + 1 == bumps.size() || bumps[i + 1] != bumps[i] + 1;
            if (runStart || runEnd)
                node[branch.sleeves[bumps[i]]] = true;
        }
        BranchPieces split = splitAtSleeves(branch, bumps);
        for (std::size_t p = 0; p < split.pieces.size(); ++p) {
            const AxisBranch& piece = split.pieces[p];
            forcedMerge.push_back(split.isRun[p] || (node[piece.startNode] && node[piece.endNode] &&
                                                     piece.chords.size() < 3));
            branches.push_back(piece);
        }
    }
    return branches;
}

}  // namespace

Decomposition decompose(ChordalAxis axis, const DecompositionOptions& options) {
    Decomposition result;
    const int triangleCount = static_cast<int>(axis.cdt.triangles.size());
    const int pointCount = static_cast<int>(axis.cdt.points.size());

    // 0. Nodes of the decomposition: junctions, and sleeves carrying a bump.
    std::vector<bool> node(triangleCount, false);
    for (int t = 0; t < triangleCount; ++t)
        node[t] = !axis.pruned[t] && isJunction(axis, t);
    std::vector<bool> forcedMerge;
    axis.branches = splitAtBodyBumps(axis, node, forcedMerge, options);

    // 1. Merge short-yet-wide branches between junctions (Fig. 2 c -> d).
    UnionFind groups(triangleCount);
    std::vector<bool> merged(axis.branches.size(), false);
    for (std::size_t b = 0; b < axis.branches.size(); ++b) {
        const AxisBranch& branch = axis.branches[b];
        if (!node[branch.startNode] || !node[branch.endNode])
            continue;
        if (forcedMerge[b] || branchAxisLength(axis, branch) <
                                  options.mergeLengthFactor * meanChordLength(axis, branch)) {
            merged[b] = true;
            groups.unite(branch.startNode, branch.endNode);
        }
    }

    // 2. One connecting region per group of junctions.
    std::vector<int> regionOfTriangle(triangleCount, -1);
    for (int t = 0; t < triangleCount; ++t) {
        if (!node[t])
            continue;
        int root = groups.find(t);
        if (regionOfTriangle[root] < 0) {
            regionOfTriangle[root] = static_cast<int>(result.connecting.size());
            result.connecting.emplace_back();
        }
        regionOfTriangle[t] = regionOfTriangle[root];
        result.connecting[regionOfTriangle[t]].junctions.push_back(t);
        result.connecting[regionOfTriangle[t]].triangles.push_back(t);
    }
    for (std::size_t b = 0; b < axis.branches.size(); ++b) {
        if (!merged[b])
            continue;
        int region = regionOfTriangle[axis.branches[b].startNode];
        result.connecting[region].junctionLinks.push_back(
            {axis.branches[b].startNode, axis.branches[b].endNode});
        for (int sleeve : axis.branches[b].sleeves) {
            regionOfTriangle[sleeve] = region;
            result.connecting[region].triangles.push_back(sleeve);
        }
    }
    // 3. Fans next to junctions join the connecting regions.
    std::vector<AxisBranch> cylinderBranches;
    for (std::size_t b = 0; b < axis.branches.size(); ++b) {
        if (merged[b])
            continue;
        AxisBranch branch = axis.branches[b];
        absorbJunctionFans(branch, regionOfTriangle, result.connecting, node[branch.startNode],
                           node[branch.endNode]);
        cylinderBranches.push_back(std::move(branch));
    }
    // 4. Pruned bumps hanging off a connecting region belong to it: its patch
    // then follows the outline around them.
    for (auto& region : result.connecting) {
        std::vector<int> stack = region.triangles;
        int id = regionOfTriangle[region.junctions.front()];
        while (!stack.empty()) {
            int t = stack.back();
            stack.pop_back();
            for (int n : axis.cdt.neighbors[t]) {
                if (n < 0 || !axis.pruned[n] || regionOfTriangle[n] >= 0)
                    continue;
                regionOfTriangle[n] = id;
                region.triangles.push_back(n);
                stack.push_back(n);
            }
        }
    }

    // 5. Every other branch is a cylindrical region, with caps at terminals.
    for (const AxisBranch& branch : cylinderBranches) {
        CylinderRegion cylinder;
        std::vector<PolygonEdge> chords = branch.chords;
        const int chordCount = static_cast<int>(chords.size());
        const bool startIsCap = !node[branch.startNode];
        const bool endIsCap = !node[branch.endNode];

        int fromStart = 0;
        if (startIsCap) {
            int limit = endIsCap ? (chordCount - 1) / 2 : chordCount - 1;
            fromStart = capLength(axis, branch.startNode, branch.sleeves, chords, limit,
                                  options.capCircleFactor);
        }
        int fromEnd = 0;
        if (endIsCap) {
            std::vector<int> sleeves(branch.sleeves.rbegin(), branch.sleeves.rend());
            std::vector<PolygonEdge> reversed(chords.rbegin(), chords.rend());
            fromEnd = capLength(axis, branch.endNode, sleeves, reversed, chordCount - 1 - fromStart,
                                options.capCircleFactor);
        }
        cylinder.chords.assign(chords.begin() + fromStart, chords.end() - fromEnd);
        if (startIsCap) {
            const PolygonEdge& base = cylinder.chords.front();
            cylinder.startCap = outlinePath(base[0], base[1], pointCount);
        } else {
            cylinder.startConnecting = regionOfTriangle[branch.startNode];
            cylinder.startJunction = branch.startNode;
        }
        if (endIsCap) {
            const PolygonEdge& base = cylinder.chords.back();
            cylinder.endCap = outlinePath(base[1], base[0], pointCount);
        } else {
            cylinder.endConnecting = regionOfTriangle[branch.endNode];
            cylinder.endJunction = branch.endNode;
        }
        int index = static_cast<int>(result.cylinders.size());
        if (cylinder.startConnecting >= 0)
            result.connecting[cylinder.startConnecting].ports.push_back({index, true});
        if (cylinder.endConnecting >= 0)
            result.connecting[cylinder.endConnecting].ports.push_back({index, false});
        result.cylinders.push_back(std::move(cylinder));
    }
    if (result.cylinders.empty())
        throw Error(MessageId::OutlineNotElongated);
    result.axis = std::move(axis);
    return result;
}

}  // namespace rigmesh
