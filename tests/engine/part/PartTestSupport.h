// Helpers for the sketch -> rigged part tests: the pipeline's result on the
// shared sketches (built once per test binary and per variant), and small
// queries on skin weights and skeletons.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <limits>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "SketchToSurfaceTestSupport.h"
#include "base/Statistics.h"
#include "pipeline/SketchToPart.h"
#include "rig/BoneVisibility.h"

namespace rigmesh::parttest {

// The shared sketches the pipeline must accept.
inline std::vector<std::string> goodSketches() {
    return testsupport::sharedSketchNames(false);
}

// sketchToPart on a shared sketch whose stroke is scaled by `scale`, with CDP
// (`cylindrical`) or plain DP; cached for the whole test binary.
inline const SketchToPartResult& sharedPart(const std::string& sketch, double scale = 1.0,
                                            bool cylindrical = true) {
    using Key = std::tuple<std::string, double, bool>;
    static std::map<Key, SketchToPartResult> cache;
    const Key key{sketch, scale, cylindrical};
    auto found = cache.find(key);
    if (found == cache.end()) {
        std::vector<Vec2> stroke = testsupport::sharedSketchPoints(sketch);
        for (Vec2& p : stroke)
            p *= scale;
        SketchToPartOptions options;
        options.skeleton.cylindrical = cylindrical;
        found = cache.emplace(key, sketchToPart(stroke, sketch, options)).first;
    }
    return found->second;
}

// Relative tolerance under which equally close visible bones tie in the
// figures (1%); the solver's own is 3e-3 (BoneHeatOptions::tieTolerance),
// so a figure's "closest visible" also accepts a bone within 1%.
inline constexpr double kTieTolerance = 1e-2;

// The closest visible bones of every vertex of a shared sketch's part,
// tested with BoneVisibility on all vertices (no construction shortcut),
// ties within `tieTolerance` (the figures' 1% unless told); cached.
inline const ClosestBones& sharedClosestVisibleBones(const std::string& sketch,
                                                     double tieTolerance = kTieTolerance) {
    static std::map<std::pair<std::string, double>, ClosestBones> cache;
    const std::pair<std::string, double> key{sketch, tieTolerance};
    auto found = cache.find(key);
    if (found == cache.end()) {
        const Part& part = sharedPart(sketch).part;
        std::vector<int> all(part.mesh.vertices.size());
        for (std::size_t v = 0; v < all.size(); ++v)
            all[v] = static_cast<int>(v);
        const BoneVisibility visibility(part.mesh);
        found = cache
                    .emplace(key, closestVisibleBones(part.mesh, part.boneSegments(), visibility,
                                                      all, tieTolerance))
                    .first;
    }
    return found->second;
}

// Distance from a point to the nearest of `bones`.
inline double distanceToNearestBone(const Vec3& p, const std::vector<BoneSegment>& bones) {
    double best = std::numeric_limits<double>::infinity();
    for (const BoneSegment& bone : bones)
        best = std::min(best, pointSegmentDistance(p, bone));
    return best;
}

inline double boundingBoxDiagonal(const TriMesh& mesh) {
    Eigen::AlignedBox3d box;
    for (const Vec3& v : mesh.vertices)
        box.extend(v);
    return box.diagonal().norm();
}

// A vertex's weights as a dense vector over `boneCount` bones.
// A part's weights by bone position (skeleton.bones() order), as the solver
// gives them and as the index-based figures below read them.
inline SkinWeights weightsByPosition(const Part& part) {
    return weightsByIndex(part.skeleton, part.weights);
}

inline std::vector<double> denseWeights(const std::vector<std::pair<int, double>>& sparse,
                                        int boneCount) {
    std::vector<double> dense(boneCount, 0.0);
    for (const auto& [bone, weight] : sparse)
        dense[bone] += weight;
    return dense;
}

// L1 norm of the difference of two sparse weight vectors.
inline double weightDifferenceL1(const std::vector<std::pair<int, double>>& a,
                                 const std::vector<std::pair<int, double>>& b, int boneCount) {
    const std::vector<double> da = denseWeights(a, boneCount);
    const std::vector<double> db = denseWeights(b, boneCount);
    double sum = 0.0;
    for (int i = 0; i < boneCount; ++i)
        sum += std::abs(da[i] - db[i]);
    return sum;
}

// The bone with the largest weight (the lowest index on a tie); -1 if none.
inline int dominantBone(const std::vector<std::pair<int, double>>& weights) {
    int best = -1;
    double bestWeight = -1.0;
    for (const auto& [bone, weight] : weights) {
        if (weight > bestWeight) {
            best = bone;
            bestWeight = weight;
        }
    }
    return best;
}

// Every undirected mesh edge once, as (smaller, larger) vertex index.
inline std::vector<std::pair<int, int>> meshEdges(const TriMesh& mesh) {
    std::vector<std::pair<int, int>> edges;
    for (const auto& face : mesh.faces) {
        for (int k = 0; k < 3; ++k) {
            const int a = face[k];
            const int b = face[(k + 1) % 3];
            edges.emplace_back(std::min(a, b), std::max(a, b));
        }
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    return edges;
}

// The value below which `fraction` of `values` lie (base/Statistics.h).
using rigmesh::percentile;

// A known engine defect: the sketch and what is wrong, for GTEST_SKIP.
struct KnownDefect {
    std::string sketch;
    std::string reason;
};

// The reason a sketch is listed among `defects`; empty if it is not.
inline std::string knownDefect(const std::vector<KnownDefect>& defects, const std::string& sketch) {
    for (const KnownDefect& defect : defects)
        if (defect.sketch == sketch)
            return defect.reason;
    return {};
}

// Joints of the given degree.
inline std::vector<Joint> jointsOfDegree(const Skeleton& skeleton, int degree) {
    std::vector<Joint> joints;
    for (const Joint& joint : skeleton.joints())
        if (skeleton.degree(joint.id) == degree)
            joints.push_back(joint);
    return joints;
}

}  // namespace rigmesh::parttest
