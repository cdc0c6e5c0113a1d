// The auto-rig tests' common ground: shared sketches written as plain OBJ
// without a rig, imported through Assimp, rigged; cached per test binary.
#pragma once

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "../part/LimbWeightMetrics.h"
#include "MeshInside.h"
#include "SharedSketchPart.h"
#include "autorig/AutoRig.h"
#include "io/SceneImport.h"
#include "mesh/MeshWriter.h"
#include "part/BoneWeights.h"
#include "rig/BoneVisibility.h"

namespace rigmesh::autorigtest {

inline std::vector<std::string> sketchesToRig() {
    return testsupport::sharedSketchNames(false);
}

inline int leafCount(const Skeleton& skeleton) {
    int leaves = 0;
    for (const Joint& joint : skeleton.joints())
        leaves += skeleton.degree(joint.id) == 1 ? 1 : 0;
    return leaves;
}

struct ImportedSketch {
    Part sketched;  // the sketch's own rigged part
    Part imported;  // its mesh read back from the OBJ, unrigged
    AutoRigResult rigged;
    double seconds = 0;
};

inline std::string scratchPath(const std::string& name) {
    const auto folder = std::filesystem::temp_directory_path() / "rigmesh-autorig-tests";
    std::filesystem::create_directories(folder);
    return (folder / name).string();
}

inline const ImportedSketch& importedSketch(const std::string& name) {
    static std::map<std::string, ImportedSketch> cache;
    auto found = cache.find(name);
    if (found == cache.end()) {
        ImportedSketch sketch;
        sketch.sketched = testsupport::sharedSketchPart(name);
        const std::string path = scratchPath(name + ".obj");
        writeMesh(sketch.sketched.mesh, path);
        ImportedScene scene = importScene(path);
        sketch.imported = scene.parts.at(0).part;
        const auto start = std::chrono::steady_clock::now();
        sketch.rigged = autoRigPart(sketch.imported);
        sketch.seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        found = cache.emplace(name, std::move(sketch)).first;
    }
    return found->second;
}

// The share of vertices whose largest weight is one of their closest
// visible bones (paper 2.4's p_j), tested with BoneVisibility on every vertex.
inline double dominantIsClosestVisibleShare(const Part& part) {
    std::vector<int> all(part.mesh.vertices.size());
    for (std::size_t v = 0; v < all.size(); ++v)
        all[v] = static_cast<int>(v);
    const BoneVisibility visibility(part.mesh);
    return parttest::dominantIsClosestVisibleRate(
        weightsByIndex(part.skeleton, part.weights),
        closestVisibleBones(part.mesh, part.boneSegments(), visibility, all,
                            parttest::kTieTolerance));
}

// Points along every bone (joints included, 9 per bone) outside the surface.
inline int bonePointsOutside(const Part& part) {
    int outside = 0;
    for (const BoneSegment& bone : part.boneSegments())
        for (int i = 0; i <= 8; ++i) {
            const Vec3 p = bone.head + (bone.tail - bone.head) * (i / 8.0);
            outside += parttest::windingNumber(part.mesh, p) < 0.5 ? 1 : 0;
        }
    return outside;
}

// One weight list per vertex, none empty, every weight positive, each
// list summing to 1.
inline void expectPositiveWeightsSummingToOne(const WeightsById& perVertex, int vertexCount) {
    ASSERT_EQ(perVertex.size(), static_cast<std::size_t>(vertexCount));
    for (const auto& list : perVertex) {
        ASSERT_FALSE(list.empty());
        double sum = 0.0;
        for (const auto& [bone, weight] : list) {
            EXPECT_GT(weight, 0.0);
            sum += weight;
        }
        EXPECT_NEAR(sum, 1.0, 1e-9);
    }
}

}  // namespace rigmesh::autorigtest
