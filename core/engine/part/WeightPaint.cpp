#include "part/WeightPaint.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "base/Error.h"
#include "mesh/MeshAdjacency.h"

namespace rigmesh {

namespace {

// Weights below this are dropped after a dab (far below the 1e-6 a sum may
// be off by).
constexpr double kDropBelow = 1e-9;

double weightOf(const std::vector<std::pair<BoneId, double>>& list, BoneId bone) {
    for (const auto& [b, w] : list)
        if (b == bone)
            return w;
    return 0.0;
}

// Sets `bone` to `target` in `list`, the other unlocked bones scaled to take
// up the difference. False if that cannot be done (only locked bones left).
bool setWeight(std::vector<std::pair<BoneId, double>>& list, BoneId bone, double target,
               const std::set<BoneId>& locked) {
    double lockedSum = 0.0, freeSum = 0.0;
    for (const auto& [b, w] : list) {
        if (b == bone)
            continue;
        (locked.contains(b) ? lockedSum : freeSum) += w;
    }
    target = std::clamp(target, 0.0, 1.0 - lockedSum);
    const double freeTarget = 1.0 - lockedSum - target;
    if (freeSum <= 0.0 && (freeTarget > kDropBelow || target == weightOf(list, bone)))
        return false;  // nothing unlocked to hand the rest to, or to take it from
    std::map<BoneId, double> out;
    for (const auto& [b, w] : list)
        if (b != bone)
            out[b] = locked.contains(b) ? w : (freeSum > 0.0 ? w * freeTarget / freeSum : 0.0);
    out[bone] = target;
    // Locked weights are kept bit for bit; by construction the weights sum
    // to 1 up to rounding.
    list.clear();
    for (const auto& [b, w] : out)
        if (w > kDropBelow)
            list.emplace_back(b, w);
    return true;
}

}  // namespace

DabResult paintWeights(Part& part, const WeightDab& dab) {
    const Skeleton& skeleton = part.skeleton;
    if (!skeleton.hasBone(dab.bone))
        throw Error("The part has no bone " + std::to_string(dab.bone) + " to paint.");
    if (dab.locked.contains(dab.bone))
        throw Error("Bone " + std::to_string(dab.bone) + " is locked; unlock it to paint it.");
    if (!(dab.radius > 0.0) || !std::isfinite(dab.radius) || !(dab.strength >= 0.0) ||
        !(dab.strength <= 1.0) || !(dab.value >= 0.0) || !(dab.value <= 1.0) ||
        !dab.centre.allFinite())
        throw Error(
            "A brush needs a finite centre, a positive radius, and a strength and value "
            "between 0 and 1.");
    if (dab.mirror && part.mirror.size() != part.mesh.vertices.size())
        throw Error(
            "This part is not mirror symmetric any more (merged or cut), so X-mirror "
            "cannot paint it.");
    const BoneId bone = dab.bone;

    // The vertices under the brush (and their reflections) with their falloff.
    std::map<int, double> influence;
    auto gather = [&](const Vec3& centre) {
        for (int v = 0; v < part.mesh.vertexCount(); ++v) {
            const double d = (part.mesh.vertices[v] - centre).norm() / dab.radius;
            if (d < 1.0) {
                const double f = dab.strength * (1.0 - d * d) * (1.0 - d * d);
                double& slot = influence[v];
                slot = std::max(slot, f);
            }
        }
    };
    gather(dab.centre);
    if (dab.mirror)
        gather(Vec3(dab.centre.x(), dab.centre.y(), -dab.centre.z()));

    std::vector<std::vector<int>> neighbours;
    if (dab.mode == BrushMode::Smooth)
        neighbours = vertexNeighbours(part.mesh);
    auto& weights = part.weights.perVertex;
    const WeightsById old = weights;
    DabResult result;
    for (const auto& [v, f] : influence) {
        const double w = weightOf(old[v], bone);
        double target = w;
        switch (dab.mode) {
            case BrushMode::Add:
                target = w + f * (1.0 - w);
                break;
            case BrushMode::Subtract:
                target = w * (1.0 - f);
                break;
            case BrushMode::Replace:
                target = w + f * (dab.value - w);
                break;
            case BrushMode::Smooth: {
                double mean = 0.0;
                for (int n : neighbours[v])
                    mean += weightOf(old[n], bone);
                mean /= std::max<std::size_t>(neighbours[v].size(), 1);
                target = w + f * (mean - w);
                break;
            }
        }
        if (target == w)
            continue;
        std::vector<std::pair<BoneId, double>> updated = old[v];
        if (!setWeight(updated, bone, target, dab.locked)) {
            ++result.skippedLocked;
            continue;
        }
        if (updated == old[v])
            continue;
        result.changed.push_back(v);
        result.before.push_back(old[v]);
        result.after.push_back(updated);
        weights[v] = std::move(updated);
    }
    return result;
}

namespace {

// Keeps the entries `keep` says yes to (always the largest), renormalised.
template <typename Keep>
int filterWeights(Part& part, Keep&& keep) {
    int changed = 0;
    for (auto& list : part.weights.perVertex) {
        if (list.empty())
            continue;
        std::vector<std::pair<BoneId, double>> sorted = list;
        std::sort(sorted.begin(), sorted.end(),
                  [](const auto& a, const auto& b) { return a.second > b.second; });
        std::vector<std::pair<BoneId, double>> kept;
        for (std::size_t rank = 0; rank < sorted.size(); ++rank)
            if (rank == 0 || keep(sorted[rank], rank))
                kept.push_back(sorted[rank]);
        double sum = 0.0;
        for (const auto& entry : kept)
            sum += entry.second;
        if (kept.size() == list.size() && std::abs(sum - 1.0) <= 1e-12)
            continue;  // already as asked: left bit for bit
        for (auto& entry : kept)
            entry.second /= sum;
        std::sort(kept.begin(), kept.end());
        if (kept != list) {
            list = std::move(kept);
            ++changed;
        }
    }
    return changed;
}

}  // namespace

int normalizeAllWeights(Part& part) {
    return filterWeights(part, [](const auto&, std::size_t) { return true; });
}

int cleanWeights(Part& part, double threshold) {
    if (!(threshold >= 0.0) || !(threshold < 1.0))
        throw Error("The clean threshold must be at least 0 and below 1.");
    return filterWeights(part,
                         [&](const auto& entry, std::size_t) { return entry.second >= threshold; });
}

int limitWeightInfluences(Part& part, int influences) {
    if (influences < 1)
        throw Error("A vertex needs at least one influence.");
    return filterWeights(
        part, [&](const auto&, std::size_t rank) { return static_cast<int>(rank) < influences; });
}

}  // namespace rigmesh
