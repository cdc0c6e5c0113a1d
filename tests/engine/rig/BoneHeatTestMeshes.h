// Closed, outward-oriented meshes and checks for the bone heat tests, built
// here so that the tests depend on nothing but the solver.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>
#include <vector>

#include "mesh/TriMesh.h"
#include "rig/BoneHeatSolver.h"
#include "rig/BoneSegment.h"

namespace rigmesh::test {

// A tube along x from 0 to `length`: `rings` circles of `segments` vertices
// and a centre vertex per flat cap (the last two vertices).
inline TriMesh makeCappedTube(int rings, int segments, double radius, double length) {
    TriMesh mesh;
    for (int r = 0; r < rings; ++r) {
        const double x = length * r / (rings - 1);
        for (int s = 0; s < segments; ++s) {
            const double angle = 2.0 * std::numbers::pi * s / segments;
            mesh.vertices.emplace_back(x, radius * std::cos(angle), radius * std::sin(angle));
        }
    }
    const int start = static_cast<int>(mesh.vertices.size());
    mesh.vertices.emplace_back(0.0, 0.0, 0.0);
    mesh.vertices.emplace_back(length, 0.0, 0.0);
    auto at = [segments](int r, int s) { return r * segments + (s % segments); };
    for (int r = 0; r + 1 < rings; ++r) {
        for (int s = 0; s < segments; ++s) {
            mesh.faces.push_back({at(r, s), at(r, s + 1), at(r + 1, s + 1)});
            mesh.faces.push_back({at(r, s), at(r + 1, s + 1), at(r + 1, s)});
        }
    }
    for (int s = 0; s < segments; ++s) {
        mesh.faces.push_back({start, at(0, s + 1), at(0, s)});
        mesh.faces.push_back({start + 1, at(rings - 1, s), at(rings - 1, s + 1)});
    }
    return mesh;
}

// A latitude/longitude sphere around the origin with two poles.
inline TriMesh makeUvSphere(int latitudes, int longitudes, double radius) {
    TriMesh mesh;
    mesh.vertices.emplace_back(0.0, 0.0, radius);
    for (int i = 1; i < latitudes; ++i) {
        const double polar = std::numbers::pi * i / latitudes;
        for (int j = 0; j < longitudes; ++j) {
            const double azimuth = 2.0 * std::numbers::pi * j / longitudes;
            mesh.vertices.emplace_back(radius * std::sin(polar) * std::cos(azimuth),
                                       radius * std::sin(polar) * std::sin(azimuth),
                                       radius * std::cos(polar));
        }
    }
    const int south = static_cast<int>(mesh.vertices.size());
    mesh.vertices.emplace_back(0.0, 0.0, -radius);
    auto at = [longitudes](int i, int j) { return 1 + (i - 1) * longitudes + (j % longitudes); };
    for (int j = 0; j < longitudes; ++j) {
        mesh.faces.push_back({0, at(1, j), at(1, j + 1)});
        mesh.faces.push_back({south, at(latitudes - 1, j + 1), at(latitudes - 1, j)});
    }
    for (int i = 1; i + 1 < latitudes; ++i) {
        for (int j = 0; j < longitudes; ++j) {
            mesh.faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            mesh.faces.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    }
    return mesh;
}

// Signed volume: positive for a closed mesh with outward triangles.
inline double signedVolume(const TriMesh& mesh) {
    double volume = 0.0;
    for (const auto& f : mesh.faces) {
        volume += mesh.vertices[f[0]].dot(mesh.vertices[f[1]].cross(mesh.vertices[f[2]])) / 6.0;
    }
    return volume;
}

inline TriMesh scaled(TriMesh mesh, double factor) {
    for (auto& p : mesh.vertices) {
        p *= factor;
    }
    return mesh;
}

inline std::vector<BoneSegment> scaled(std::vector<BoneSegment> bones, double factor) {
    for (auto& bone : bones) {
        bone.head *= factor;
        bone.tail *= factor;
    }
    return bones;
}

// The weight of `bone` at every vertex (0 where it is absent).
inline std::vector<double> boneWeights(const SkinWeights& weights, int bone) {
    std::vector<double> result(weights.perVertex.size(), 0.0);
    for (std::size_t v = 0; v < weights.perVertex.size(); ++v) {
        for (const auto& [b, w] : weights.perVertex[v]) {
            if (b == bone) {
                result[v] = w;
            }
        }
    }
    return result;
}

// Every vertex weighted, weights positive, each vertex summing to 1.
inline void expectPartitionOfUnity(const SkinWeights& weights, int vertexCount, int boneCount) {
    ASSERT_EQ(static_cast<int>(weights.perVertex.size()), vertexCount);
    for (int v = 0; v < vertexCount; ++v) {
        const auto& list = weights.perVertex[v];
        ASSERT_FALSE(list.empty()) << "vertex " << v << " has no weight";
        double sum = 0.0;
        for (const auto& [bone, w] : list) {
            EXPECT_GE(bone, 0);
            EXPECT_LT(bone, boneCount);
            EXPECT_GT(w, 0.0) << "vertex " << v;
            EXPECT_TRUE(std::isfinite(w)) << "vertex " << v;
            sum += w;
        }
        EXPECT_NEAR(sum, 1.0, 1e-9) << "vertex " << v;
    }
}

}  // namespace rigmesh::test
