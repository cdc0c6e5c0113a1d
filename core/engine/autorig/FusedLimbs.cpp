#include "autorig/FusedLimbs.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <optional>
#include <set>
#include <unordered_map>

#include "autorig/LimbOutlines.h"
#include "rig/BoneSegment.h"

namespace rigmesh {

namespace {

// Planes across a leaf chain, evenly along it.
constexpr int kStations = 24;
// The chain is two limbs from the highest station whose plane cuts the
// mesh in two outlines, when this share of the stations from there to the
// tip do so too (limbs may touch here and there: a knee, the feet) and at
// least kFewestSplitStations.
constexpr double kSplitShare = 0.6;
constexpr int kFewestSplitStations = 4;
// Two limbs fused along most of their length part within the first
// quarter of the chain (legs from the hips). A chain that parts lower down
// may be one limb the proxy joined to the end of another (a shin to the
// other shin, whose thigh has a chain of its own, cut at the knee where the
// curve skeleton's loop thigh, shins, thigh was cut: SkeletonFromCurve's
// spanningTree): the other limb's part continues that chain's leaf when
// one ends near where it parts. Else both limbs leave the parting joint,
// as from a high split: legs fused from the crotch down have no junction
// of their own, and their chain runs from the chest (mrfixit of
// assimp-testmodels, its legs 1.4% of the diagonal apart).
constexpr int kHighestTop = kStations / 4;
// Both limbs reach the tip: two outlines among this many stations nearest it.
constexpr int kTipStations = 3;
// A limb's outline is followed from station to station while its length
// changes by less than this factor.
constexpr double kLengthChange = 1.6;
// A limb's end gets its tip in its middle when it has at least this many
// of the mesh's points.
constexpr int kFewestEndPoints = 4;

JointId otherEnd(const Skeleton& skeleton, BoneId bone, JointId from) {
    const Bone& b = skeleton.bone(bone);
    return b.head == from ? b.tail : b.head;
}

// The joints from a junction (first) to the leaf `leaf` (last); empty when
// the whole skeleton is one chain.
std::vector<JointId> leafChain(const Skeleton& skeleton, JointId leaf) {
    std::vector<JointId> chain{leaf};
    JointId previous = kNoJoint;
    JointId here = leaf;
    while (true) {
        JointId next = kNoJoint;
        for (BoneId bone : skeleton.bonesAt(here))
            if (otherEnd(skeleton, bone, here) != previous)
                next = otherEnd(skeleton, bone, here);
        if (next == kNoJoint)
            return {};
        chain.push_back(next);
        if (skeleton.degree(next) != 2)
            break;
        previous = here;
        here = next;
    }
    std::reverse(chain.begin(), chain.end());
    return chain;
}

// A polyline by arc length.
struct Polyline {
    std::vector<Vec3> points;
    std::vector<double> arcs;

    double length() const { return arcs.back(); }
    Vec3 at(double arc) const {
        arc = std::clamp(arc, 0.0, length());
        for (std::size_t i = 1; i < points.size(); ++i)
            if (arc <= arcs[i] || i + 1 == points.size()) {
                const double span = arcs[i] - arcs[i - 1];
                const double t = span > 0.0 ? (arc - arcs[i - 1]) / span : 0.0;
                return points[i - 1] + std::clamp(t, 0.0, 1.0) * (points[i] - points[i - 1]);
            }
        return points.back();
    }
};

// Piecewise linear in arc length between known values, held at the ends.
Vec3 interpolate(const std::vector<double>& arcs, const std::vector<Vec3>& values, double arc) {
    if (arc <= arcs.front())
        return values.front();
    for (std::size_t i = 1; i < arcs.size(); ++i)
        if (arc <= arcs[i]) {
            const double t = (arc - arcs[i - 1]) / (arcs[i] - arcs[i - 1]);
            return values[i - 1] + t * (values[i] - values[i - 1]);
        }
    return values.back();
}

struct Split {
    bool low = false;                          // parts below kHighestTop
    double arc = 0.0;                          // where the limbs part
    std::vector<double> arcs;                  // of the split stations, increasing
    std::array<std::vector<Vec3>, 2> offsets;  // each limb's middle from the chain
};

// Whether limb `k` of `split` already has a chain of its own: at more than
// half of the split's stations its middle lies nearer a bone off `chain` than half
// the two limbs' distance apart. Splitting would give it a second one (the
// thighs around the stub of a chain the tree cut at the knee, on a coarser
// wrap, where the other thigh's chain runs down to its foot).
bool limbHasItsOwnChain(const Skeleton& skeleton, const std::vector<JointId>& chain,
                        const Polyline& line, const Split& split, int k) {
    int taken = 0;
    for (std::size_t s = 0; s < split.arcs.size(); ++s) {
        const Vec3 at = line.at(split.arcs[s]);
        const std::array<Vec3, 2> middles{at + split.offsets[0][s], at + split.offsets[1][s]};
        const double halfApart = 0.5 * (middles[0] - middles[1]).norm();
        for (const Bone& bone : skeleton.bones()) {
            const bool onChain = std::find(chain.begin(), chain.end(), bone.head) != chain.end() &&
                                 std::find(chain.begin(), chain.end(), bone.tail) != chain.end();
            if (!onChain && pointSegmentDistance(middles[k], {skeleton.joint(bone.head).position,
                                                              skeleton.joint(bone.tail).position}) <
                                halfApart) {
                ++taken;
                break;
            }
        }
    }
    return 2 * taken > static_cast<int>(split.arcs.size());
}

std::optional<Split> findSplit(const Polyline& line, const Welded& mesh, const Welded& proxy) {
    const double step = line.length() / kStations;
    std::vector<std::optional<ProxyCut>> proxyCuts(kStations);
    const auto plane = [&](int i) {
        const double arc = (i + 0.5) * step;
        return std::pair{line.at(arc), Vec3(line.at(arc + step) - line.at(arc - step))};
    };
    for (int i = 0; i < kStations; ++i)
        if (const auto [p, d] = plane(i); d.norm() > 0.0)
            proxyCuts[i] = proxyCutAt(proxy, p, d.normalized());
    // Only the mesh's faces that may reach the proxy's outlines around the
    // given stations are cut: a corner within their reach of the chain, or
    // within that and the face's longest edge.
    std::vector<double> fromChain(mesh.points.size(), INFINITY);
    for (std::size_t v = 0; v < mesh.points.size(); ++v)
        for (std::size_t j = 1; j < line.points.size(); ++j)
            fromChain[v] = std::min(
                fromChain[v],
                pointSegmentDistance(mesh.points[v], {line.points[j - 1], line.points[j]}));
    std::vector<std::vector<Outline>> cuts(kStations);
    const auto cut = [&](int from, int to) {
        double reach = 0.0;
        for (int i = from; i < to; ++i)
            if (proxyCuts[i])
                reach = std::max(reach, proxyCuts[i]->reach(plane(i).first));
        std::vector<std::array<int, 3>> faces;
        for (const auto& f : mesh.faces) {
            double longest = 0.0;
            for (int i = 0; i < 3; ++i)
                longest =
                    std::max(longest, (mesh.points[f[i]] - mesh.points[f[(i + 1) % 3]]).norm());
            if (std::min({fromChain[f[0]], fromChain[f[1]], fromChain[f[2]]}) <= reach + longest)
                faces.push_back(f);
        }
        for (int i = from; i < to; ++i)
            if (proxyCuts[i]) {
                const auto [p, d] = plane(i);
                cuts[i] = limbsAt(mesh, faces, *proxyCuts[i], p, d.normalized());
            }
    };
    // The stations nearest the tip first: most chains are one limb there.
    cut(kStations - kTipStations, kStations);
    if (std::none_of(cuts.end() - kTipStations, cuts.end(),
                     [](const std::vector<Outline>& outlines) { return outlines.size() == 2; }))
        return std::nullopt;
    cut(0, kStations - kTipStations);
    // The two limbs followed from the station nearest the tip that has
    // exactly two up the chain: at each station the outline nearest each,
    // when that is another for each and no farther than their distance
    // apart (a third outline, a skirt's flap, is passed by).
    // Both limbs reach the tip: the two outlines are found among the
    // stations nearest it.
    int start = kStations - 1;
    while (start >= kStations - kTipStations && cuts[start].size() != 2)
        --start;
    if (start < kStations - kTipStations)
        return std::nullopt;
    std::vector<std::optional<std::array<Vec3, 2>>> limbs(kStations);
    std::array<Vec3, 2> last{cuts[start][0].centroid, cuts[start][1].centroid};
    std::array<double, 2> lastLength{cuts[start][0].length, cuts[start][1].length};
    for (int i = start; i >= 0; --i) {
        if (cuts[i].size() < 2)
            continue;
        const double apart = (last[0] - last[1]).norm();
        std::array<int, 2> nearest{-1, -1};
        for (int k = 0; k < 2; ++k) {
            double best = INFINITY;
            for (int o = 0; o < static_cast<int>(cuts[i].size()); ++o)
                if ((cuts[i][o].centroid - last[k]).norm() < best) {
                    best = (cuts[i][o].centroid - last[k]).norm();
                    nearest[k] = o;
                }
            // A limb's outline moves and changes little from one station
            // to the next; one that jumps is another part (the torso).
            if (best > apart + step || cuts[i][nearest[k]].length > kLengthChange * lastLength[k] ||
                cuts[i][nearest[k]].length * kLengthChange < lastLength[k])
                nearest[k] = -1;
        }
        if (nearest[0] < 0 || nearest[1] < 0 || nearest[0] == nearest[1])
            continue;
        last = {cuts[i][nearest[0]].centroid, cuts[i][nearest[1]].centroid};
        lastLength = {cuts[i][nearest[0]].length, cuts[i][nearest[1]].length};
        limbs[i] = last;
    }
    // The highest station from which most stations to the tip are split.
    int top = -1, count = 0;
    for (int i = kStations - 1; i >= 0; --i) {
        count += limbs[i] ? 1 : 0;
        if (limbs[i] && count >= kFewestSplitStations && count >= kSplitShare * (kStations - i))
            top = i;
    }
    if (top < 0)
        return std::nullopt;
    Split split;
    split.low = top > kHighestTop;
    split.arc = top * step;  // halfway to the station above, which is one limb
    for (int i = top; i < kStations; ++i)
        if (limbs[i]) {
            const double arc = (i + 0.5) * step;
            split.arcs.push_back(arc);
            for (int k = 0; k < 2; ++k)
                split.offsets[k].push_back((*limbs[i])[k] - line.at(arc));
        }
    return split;
}

}  // namespace

FusedLimbsReport splitFusedLimbs(Skeleton& skeleton, const TriMesh& mesh, const TriMesh& proxy) {
    FusedLimbsReport report;
    const Welded welded = weld(mesh);
    const Welded proxyWelded{proxy.vertices, proxy.faces, {}};
    std::vector<JointId> leaves;
    for (const Joint& joint : skeleton.joints())
        if (skeleton.degree(joint.id) == 1 && joint.id != skeleton.root())
            leaves.push_back(joint.id);
    for (JointId leaf : leaves) {
        if (!skeleton.hasJoint(leaf) || skeleton.degree(leaf) != 1)
            continue;
        const std::vector<JointId> chain = leafChain(skeleton, leaf);
        if (chain.size() < 2)
            continue;
        Polyline line;
        for (JointId joint : chain) {
            const Vec3& p = skeleton.joint(joint).position;
            line.arcs.push_back(
                line.points.empty() ? 0.0 : line.arcs.back() + (p - line.points.back()).norm());
            line.points.push_back(p);
        }
        if (!(line.length() > 0.0))
            continue;
        const std::optional<Split> split = findSplit(line, welded, proxyWelded);
        if (!split || limbHasItsOwnChain(skeleton, chain, line, *split, 0) ||
            limbHasItsOwnChain(skeleton, chain, line, *split, 1))
            continue;
        const double step = line.length() / kStations;
        // A low split: the limb whose top lies nearer another chain's leaf,
        // where the tree cut that chain (within the limbs' distance apart
        // and a station), continues it.
        int cutLimb = -1;
        JointId cutLeaf = kNoJoint;
        if (split->low) {
            const double topArc = split->arcs.front();
            const std::array<Vec3, 2> tops{line.at(topArc) + split->offsets[0].front(),
                                           line.at(topArc) + split->offsets[1].front()};
            const double reach = (tops[0] - tops[1]).norm() + step;
            double best = INFINITY;
            for (const Joint& joint : skeleton.joints()) {
                if (skeleton.degree(joint.id) != 1 || joint.id == skeleton.root() ||
                    std::find(chain.begin(), chain.end(), joint.id) != chain.end())
                    continue;
                const std::array<double, 2> from{(joint.position - tops[0]).norm(),
                                                 (joint.position - tops[1]).norm()};
                const int k = from[0] <= from[1] ? 0 : 1;
                if (from[k] <= reach && from[k] < best) {
                    best = from[k];
                    cutLeaf = joint.id;
                    cutLimb = k;
                }
            }
        }
        // The chain is rebuilt: its joints above the split stay, a joint
        // where the limbs part (the nearest kept one within half a station),
        // and each limb gets a joint for each of the chain's joints below,
        // moved to the middle of its own outline.
        std::vector<JointId> kept{chain.front()};
        std::vector<std::pair<double, Vec3>> below;
        for (std::size_t i = 1; i < chain.size(); ++i) {
            if (line.arcs[i] > split->arc + 0.5 * step || i + 1 == chain.size())
                below.emplace_back(line.arcs[i], line.points[i]);
            else
                kept.push_back(chain[i]);
        }
        for (std::size_t i = 1; i < chain.size(); ++i)
            if (std::find(kept.begin(), kept.end(), chain[i]) == kept.end())
                skeleton.removeJoint(chain[i]);
        JointId parting = kept.back();
        if (line.arcs[kept.size() - 1] < split->arc - 0.5 * step) {
            const JointId at = skeleton.addJoint(line.at(split->arc));
            skeleton.addBone(parting, at);
            parting = at;
        }
        std::array<JointId, 2> tips{};
        for (int k = 0; k < 2; ++k) {
            JointId from = k == cutLimb ? cutLeaf : parting;
            for (const auto& [arc, point] : below) {
                const JointId next =
                    skeleton.addJoint(point + interpolate(split->arcs, split->offsets[k], arc));
                skeleton.addBone(from, next);
                from = next;
            }
            tips[k] = from;
        }
        // Each tip in the middle of its own end of the mesh: the points
        // beyond the last split station, each the nearer tip's (the
        // chain's one tip sat between the two ends the proxy joined).
        {
            const double lastArc = split->arcs.back();
            const Vec3 at = line.at(lastArc);
            const Vec3 along = (line.at(lastArc + step) - line.at(lastArc - step)).normalized();
            std::array<Vec3, 2> sums{Vec3::Zero(), Vec3::Zero()};
            std::array<int, 2> counts{0, 0};
            const std::array<Vec3, 2> was{skeleton.joint(tips[0]).position,
                                          skeleton.joint(tips[1]).position};
            for (const Vec3& p : welded.points)
                if ((p - at).dot(along) > 0.0 && (p - at).norm() < line.length()) {
                    const int k = (p - was[0]).norm() <= (p - was[1]).norm() ? 0 : 1;
                    sums[k] += p;
                    ++counts[k];
                }
            if (counts[0] >= kFewestEndPoints && counts[1] >= kFewestEndPoints)
                for (int k = 0; k < 2; ++k)
                    skeleton.setJointPosition(tips[k], sums[k] / counts[k]);
        }
        const double topArc = split->arcs.front();
        report.splits.push_back(
            {line.at(topArc),
             (line.at(topArc + step) - line.at(topArc - step)).normalized(),
             {skeleton.joint(tips[0]).position, skeleton.joint(tips[1]).position}});
        ++report.chainsSplit;
    }
    skeleton.reorient();
    return report;
}

namespace {

// The bones from the leaf up to the first branching joint.
std::vector<BoneId> limbBones(const Skeleton& skeleton, JointId leaf) {
    std::vector<BoneId> bones;
    JointId here = leaf;
    BoneId came = kNoBone;
    while (true) {
        BoneId next = kNoBone;
        for (BoneId bone : skeleton.bonesAt(here))
            if (bone != came)
                next = bone;
        if (next == kNoBone)
            break;
        bones.push_back(next);
        came = next;
        here = otherEnd(skeleton, next, here);
        if (skeleton.degree(here) != 2 || here == skeleton.root())
            break;
    }
    return bones;
}

JointId leafNearest(const Skeleton& skeleton, const Vec3& p) {
    JointId best = kNoJoint;
    for (const Joint& joint : skeleton.joints())
        if (skeleton.degree(joint.id) == 1 && joint.id != skeleton.root() &&
            (best == kNoJoint ||
             (joint.position - p).norm() < (skeleton.joint(best).position - p).norm()))
            best = joint.id;
    return best;
}

double distanceToBones(const Skeleton& skeleton, const std::vector<BoneId>& bones, const Vec3& p) {
    double nearest = INFINITY;
    for (BoneId bone : bones)
        nearest = std::min(
            nearest, pointSegmentDistance(p, {skeleton.joint(skeleton.bone(bone).head).position,
                                              skeleton.joint(skeleton.bone(bone).tail).position}));
    return nearest;
}

}  // namespace

int separateFusedLimbWeights(const TriMesh& mesh, const Skeleton& skeleton,
                             const FusedLimbsReport& report, WeightsById& weights) {
    if (report.splits.empty())
        return 0;
    int changed = 0;
    for (const FusedLimbsReport::Split& split : report.splits) {
        const std::array<JointId, 2> leaves{leafNearest(skeleton, split.tips[0]),
                                            leafNearest(skeleton, split.tips[1])};
        if (leaves[0] == kNoJoint || leaves[0] == leaves[1])
            continue;
        const std::array<std::vector<BoneId>, 2> limbs{limbBones(skeleton, leaves[0]),
                                                       limbBones(skeleton, leaves[1])};
        if (limbs[0].empty() || limbs[1].empty())
            continue;
        const std::array<std::set<BoneId>, 2> limbSets{
            std::set<BoneId>(limbs[0].begin(), limbs[0].end()),
            std::set<BoneId>(limbs[1].begin(), limbs[1].end())};
        // Beyond the plane where the limbs part, each vertex is the nearer
        // limb's: the limbs' bones run through the middles of their own
        // outlines, so the two sides meet in the gap between them.
        const int count = std::min(mesh.vertexCount(), static_cast<int>(weights.size()));
        for (int v = 0; v < count; ++v) {
            if ((mesh.vertices[v] - split.point).dot(split.normal) <= 0.0)
                continue;
            const int k = distanceToBones(skeleton, limbs[0], mesh.vertices[v]) <=
                                  distanceToBones(skeleton, limbs[1], mesh.vertices[v])
                              ? 0
                              : 1;
            auto& list = weights[v];
            const auto before = list.size();
            std::erase_if(
                list, [&](const auto& weight) { return limbSets[1 - k].contains(weight.first); });
            if (list.size() == before)
                continue;
            if (list.empty()) {
                BoneId nearest = limbs[k].front();
                for (BoneId bone : limbs[k])
                    if (distanceToBones(skeleton, {bone}, mesh.vertices[v]) <
                        distanceToBones(skeleton, {nearest}, mesh.vertices[v]))
                        nearest = bone;
                list = {{nearest, 1.0}};
            }
            normaliseWeights(list);
            ++changed;
        }
    }
    return changed;
}

}  // namespace rigmesh
