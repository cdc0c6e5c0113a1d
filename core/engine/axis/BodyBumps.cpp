#include "axis/BodyBumps.h"

#include <algorithm>
#include <cmath>

namespace rigmesh {

PrunedBump prunedBumpOf(const ChordalAxis& axis, int sleeve) {
    PrunedBump bump;
    double& height = bump.height;
    const auto& corners = axis.cdt.triangles[sleeve];
    for (int k = 0; k < 3; ++k) {
        const int start = axis.cdt.neighbors[sleeve][k];
        if (start < 0 || !axis.pruned[start])
            continue;
        // The chord the bump hangs on is the sleeve's edge opposite corner k.
        const Vec2 a = axis.cdt.points[corners[(k + 1) % 3]];
        const Vec2 b = axis.cdt.points[corners[(k + 2) % 3]];
        const Vec2 along = (b - a).normalized();
        bump.base = std::max(bump.base, (b - a).norm());
        // The pruned triangles form a subtree of the dual tree below the chord.
        std::vector<int> stack{start};
        std::vector<int> previous{sleeve};
        while (!stack.empty()) {
            const int t = stack.back();
            const int from = previous.back();
            stack.pop_back();
            previous.pop_back();
            for (int v : axis.cdt.triangles[t]) {
                const Vec2 d = axis.cdt.points[v] - a;
                height = std::max(height, std::abs(d.x() * along.y() - d.y() * along.x()));
            }
            for (int n : axis.cdt.neighbors[t])
                if (n >= 0 && n != from && axis.pruned[n]) {
                    stack.push_back(n);
                    previous.push_back(t);
                }
        }
    }
    return bump;
}

BranchPieces splitAtSleeves(const AxisBranch& branch, const std::vector<int>& bumpSleeves) {
    BranchPieces result;
    // Sleeve s lies between chords s and s + 1.
    auto piece = [&](int startNode, int endNode, int firstChord, int lastChord, bool run) {
        AxisBranch p;
        p.startNode = startNode;
        p.endNode = endNode;
        p.chords.assign(branch.chords.begin() + firstChord, branch.chords.begin() + lastChord + 1);
        p.sleeves.assign(branch.sleeves.begin() + firstChord, branch.sleeves.begin() + lastChord);
        result.pieces.push_back(std::move(p));
        result.isRun.push_back(run);
    };
    int startNode = branch.startNode;
    int firstChord = 0;
    for (std::size_t i = 0; i < bumpSleeves.size();) {
        std::size_t j = i;
        while (j + 1 < bumpSleeves.size() && bumpSleeves[j + 1] == bumpSleeves[j] + 1)
            ++j;
        const int first = bumpSleeves[i], last = bumpSleeves[j];
        piece(startNode, branch.sleeves[first], firstChord, first, false);
        if (last > first)
            piece(branch.sleeves[first], branch.sleeves[last], first + 1, last, true);
        startNode = branch.sleeves[last];
        firstChord = last + 1;
        i = j + 1;
    }
    piece(startNode, branch.endNode, firstChord, static_cast<int>(branch.chords.size()) - 1, false);
    return result;
}

}  // namespace rigmesh
