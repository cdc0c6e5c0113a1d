// How left-right symmetric a stroke painted with X-mirror is: each vertex
// is paired with the vertex nearest its reflection through the part's
// mirror plane, and what the stroke changed of a bone at the vertex is
// compared with what it changed of the bone's mirror image at the pair.
#pragma once

#include <algorithm>
#include <functional>
#include <limits>
#include <vector>

#include "PartWeightOf.h"
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
    double largest = 0.0;  // the largest difference of the two changes
    double mean = 0.0;
};

// Over the vertices where the stroke changed `bone` (and `include` holds),
// the difference between that change and the change of `image` at the
// vertex's pair.
inline MirrorMismatch mirrorMismatch(const Part& before, const Part& after, BoneId bone,
                                     BoneId image, const MirrorPlane& plane,
                                     const std::function<bool(int, int)>& include = {}) {
    const std::vector<int> pair = mirrorVertices(after.mesh, plane);
    MirrorMismatch mismatch;
    double sum = 0.0;
    for (int v = 0; v < after.mesh.vertexCount(); ++v) {
        const double change = weightOf(after, v, bone) - weightOf(before, v, bone);
        if (change == 0.0 || (include && !include(v, pair[v])))
            continue;
        const double mirrored = weightOf(after, pair[v], image) - weightOf(before, pair[v], image);
        const double difference = std::abs(change - mirrored);
        ++mismatch.compared;
        sum += difference;
        mismatch.largest = std::max(mismatch.largest, difference);
    }
    if (mismatch.compared > 0)
        mismatch.mean = sum / mismatch.compared;
    return mismatch;
}

}  // namespace rigmesh::testsupport
