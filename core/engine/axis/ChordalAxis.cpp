#include <stdexcept>

#include "axis/ChordalAxis.h"

#include "base/Error.h"

namespace rigmesh {
namespace {

PolygonEdge edgeOpposite(const std::array<int, 3>& triangle, int corner) {
    return {triangle[(corner + 1) % 3], triangle[(corner + 2) % 3]};
}

TriangleKind kindFromDegree(int degree) {
    switch (degree) {
        case 3:
            return TriangleKind::Junction;
        case 2:
            return TriangleKind::Sleeve;
        case 1:
            return TriangleKind::Terminal;
        default:
            return TriangleKind::Isolated;
    }
}

class AxisBuilder {
  public:
    AxisBuilder(ChordalAxis& axis, const ChordalAxisOptions& options)
        : axis_(axis), options_(options) {}

    int liveDegree(int t) const {
        int degree = 0;
        for (int k = 0; k < 3; ++k)
            degree += axis_.liveNeighbor(t, k) >= 0 ? 1 : 0;
        return degree;
    }

    int cornerToward(int from, int to) const {
        for (int k = 0; k < 3; ++k)
            if (axis_.cdt.neighbors[from][k] == to)
                return k;
        throw std::logic_error("internal error: triangles are not adjacent");
    }

    int otherLiveNeighbor(int sleeve, int previous) const {
        for (int k = 0; k < 3; ++k) {
            int n = axis_.liveNeighbor(sleeve, k);
            if (n >= 0 && n != previous)
                return n;
        }
        return -1;
    }

    // Walks inward from terminal `start`; prunes its branch if it is a bump.
    bool tryPruneFrom(int start) {
        std::vector<int> region{start};
        int previous = start;
        int current = -1;
        for (int k = 0; k < 3 && current < 0; ++k)
            current = axis_.liveNeighbor(start, k);
        while (current >= 0) {
            PolygonEdge chord =
                edgeOpposite(axis_.cdt.triangles[previous], cornerToward(previous, current));
            if (!axis_.outlineInsideChordCircle(region, chord, options_.pruneCircleFactor))
                return false;
            int degree = liveDegree(current);
            if (degree == 3) {
                for (int t : region)
                    axis_.pruned[t] = true;
                return true;
            }
            if (degree != 2)
                return false;  // reached the other end: one small blob
            region.push_back(current);
            int next = otherLiveNeighbor(current, previous);
            previous = current;
            current = next;
        }
        return false;
    }

    void prune() {
        bool changed = true;
        while (changed) {
            changed = false;
            for (int t = 0; t < static_cast<int>(axis_.cdt.triangles.size()); ++t)
                if (!axis_.pruned[t] && liveDegree(t) == 1 && tryPruneFrom(t))
                    changed = true;
        }
    }

    // Orients `edge` of a node triangle as (left, right) for travel out of it:
    // the triangle is counter-clockwise, so it lies left of a->b and travel
    // crosses to the right; looking along the travel, b is on the left.
    static PolygonEdge orientLeaving(const PolygonEdge& edge) { return {edge[1], edge[0]}; }

    // The next chord shares one end point with the previous one; that end
    // point stays on its side.
    static PolygonEdge orientFollowing(const PolygonEdge& edge, const PolygonEdge& previous) {
        if (edge[0] == previous[0] || edge[1] == previous[1])
            return edge;
        return {edge[1], edge[0]};
    }

    void collectBranches() {
        const int count = static_cast<int>(axis_.cdt.triangles.size());
        for (int node = 0; node < count; ++node) {
            if (axis_.pruned[node] || liveDegree(node) == 2)
                continue;
            for (int k = 0; k < 3; ++k) {
                int current = axis_.liveNeighbor(node, k);
                if (current < 0)
                    continue;
                AxisBranch branch;
                branch.startNode = node;
                branch.chords.push_back(orientLeaving(edgeOpposite(axis_.cdt.triangles[node], k)));
                int previous = node;
                while (liveDegree(current) == 2) {
                    branch.sleeves.push_back(current);
                    int next = otherLiveNeighbor(current, previous);
                    PolygonEdge edge =
                        edgeOpposite(axis_.cdt.triangles[current], cornerToward(current, next));
                    branch.chords.push_back(orientFollowing(edge, branch.chords.back()));
                    previous = current;
                    current = next;
                }
                branch.endNode = current;
                // The dual graph is a tree: each branch is found once from each end.
                if (branch.startNode < branch.endNode)
                    axis_.branches.push_back(std::move(branch));
            }
        }
    }

  private:
    ChordalAxis& axis_;
    const ChordalAxisOptions& options_;
};

}  // namespace

Vec2 ChordalAxis::centroid(int triangle) const {
    const auto& t = cdt.triangles[triangle];
    return (cdt.points[t[0]] + cdt.points[t[1]] + cdt.points[t[2]]) / 3.0;
}

Vec2 ChordalAxis::midpoint(const PolygonEdge& chord) const {
    return 0.5 * (cdt.points[chord[0]] + cdt.points[chord[1]]);
}

double ChordalAxis::length(const PolygonEdge& chord) const {
    return (cdt.points[chord[0]] - cdt.points[chord[1]]).norm();
}

bool ChordalAxis::outlineInsideChordCircle(const std::vector<int>& region, const PolygonEdge& chord,
                                           double factor) const {
    const Vec2 centre = midpoint(chord);
    const double radius = 0.5 * length(chord) * factor;
    for (int t : region)
        for (int v : cdt.triangles[t]) {
            if (v == chord[0] || v == chord[1])
                continue;
            if ((cdt.points[v] - centre).norm() > radius)
                return false;
        }
    return true;
}

int ChordalAxis::liveNeighbor(int triangle, int k) const {
    int n = cdt.neighbors[triangle][k];
    return (n >= 0 && !pruned[n]) ? n : -1;
}

ChordalAxis computeChordalAxis(PolygonTriangulation cdt, const ChordalAxisOptions& options) {
    ChordalAxis axis;
    axis.cdt = std::move(cdt);
    const int count = static_cast<int>(axis.cdt.triangles.size());
    axis.pruned.assign(count, false);
    AxisBuilder builder(axis, options);
    axis.kindBeforePruning.resize(count);
    for (int t = 0; t < count; ++t)
        axis.kindBeforePruning[t] = kindFromDegree(builder.liveDegree(t));

    builder.prune();
    axis.kind.resize(count);
    for (int t = 0; t < count; ++t)
        axis.kind[t] = kindFromDegree(builder.liveDegree(t));
    builder.collectBranches();
    if (axis.branches.empty())
        throw Error(MessageId::OutlineTooSimple);

    return axis;
}

std::vector<std::array<Vec2, 2>> chordalAxisSegments(const ChordalAxis& axis, bool afterPruning) {
    std::vector<std::array<Vec2, 2>> segments;
    for (int t = 0; t < static_cast<int>(axis.cdt.triangles.size()); ++t) {
        if (afterPruning && axis.pruned[t])
            continue;
        std::vector<Vec2> ends;
        for (int k = 0; k < 3; ++k) {
            int n = afterPruning ? axis.liveNeighbor(t, k) : axis.cdt.neighbors[t][k];
            if (n >= 0)
                ends.push_back(axis.midpoint(edgeOpposite(axis.cdt.triangles[t], k)));
        }
        if (ends.size() == 2) {
            segments.push_back({ends[0], ends[1]});
        } else {
            for (const Vec2& end : ends)
                segments.push_back({axis.centroid(t), end});
        }
    }
    return segments;
}

}  // namespace rigmesh
