// How left-right symmetric a stroke painted with X-mirror is: each vertex
// the stroke changed is paired with the vertex nearest its reflection
// through the part's mirror plane, and its weight of the painted bone is
// compared with the pair's weight of the bone's mirror image.
#pragma once

#include <Eigen/Geometry>
#include <algorithm>
#include <functional>
#include <limits>
#include <vector>

#include "PartWeightOf.h"
#include "SymmetricOutline.h"
#include "part/Part.h"
#include "rig/MirrorSymmetry.h"

namespace rigmesh::testsupport {

// The vertex nearest each vertex's reflection (brute force: a test's part
// has a few thousand vertices).
inline std::vector<int> mirrorVertices(const TriMesh& mesh, const MirrorPlane& plane) {
    std::vector<int> image(mesh.vertexCount(), -1);
    for (int v = 0; v < mesh.vertexCount(); ++v) {
        const Vec3 reflected = plane.reflect(mesh.vertices[v]);
        double best = std::numeric_limits<double>::infinity();
        for (int w = 0; w < mesh.vertexCount(); ++w) {
            const double d = (mesh.vertices[w] - reflected).squaredNorm();
            if (d < best) {
                best = d;
                image[v] = w;
            }
        }
    }
    return image;
}

struct MirrorMismatch {
    int compared = 0;      // vertices the stroke changed, compared with their pair
    int unequal = 0;       // pairs whose weights differ by more than 1e-9
    double largest = 0.0;  // the largest difference of the two weights
    double mean = 0.0;
};

// The mean length of the mesh's edges (each face's three, shared edges
// counted twice).
inline double meanEdgeLength(const TriMesh& mesh) {
    double sum = 0.0;
    for (const auto& face : mesh.faces)
        for (int i = 0; i < 3; ++i)
            sum += (mesh.vertices[face[i]] - mesh.vertices[face[(i + 1) % 3]]).norm();
    return mesh.faces.empty() ? 0.0 : sum / (3.0 * mesh.faceCount());
}

// Over the vertices where the stroke changed `bone` whose reflection has a
// vertex within `pairDistance` (where the surface is symmetric: outlines
// are sampled from different starts on the two sides) and where `include`
// holds, the difference between the vertex's weight of `bone` after the
// stroke and its pair's weight of `image`.
inline MirrorMismatch mirrorMismatch(const Part& before, const Part& after, BoneId bone,
                                     BoneId image, const MirrorPlane& plane, double pairDistance,
                                     const std::function<bool(int, int)>& include = {}) {
    const std::vector<int> pair = mirrorVertices(after.mesh, plane);
    MirrorMismatch mismatch;
    double sum = 0.0;
    for (int v = 0; v < after.mesh.vertexCount(); ++v) {
        const double change = weightOf(after, v, bone) - weightOf(before, v, bone);
        if (change == 0.0 || (include && !include(v, pair[v])))
            continue;
        if ((after.mesh.vertices[pair[v]] - plane.reflect(after.mesh.vertices[v])).norm() >
            pairDistance)
            continue;
        const double difference =
            std::abs(weightOf(after, v, bone) - weightOf(after, pair[v], image));
        ++mismatch.compared;
        if (difference > 1e-9)
            ++mismatch.unequal;
        sum += difference;
        mismatch.largest = std::max(mismatch.largest, difference);
    }
    if (mismatch.compared > 0)
        mismatch.mean = sum / mismatch.compared;
    return mismatch;
}

}  // namespace rigmesh::testsupport
