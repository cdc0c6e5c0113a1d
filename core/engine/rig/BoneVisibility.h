// Which bones a surface vertex "sees" from inside the shape: Pinocchio's bone
// heat skinning only lets a bone heat a vertex if the segment from the vertex
// to the bone's closest point stays inside the volume (Baran & Popovic 2007,
// section 4). RigMesh (section 2.4) knows the answer for cylinder vertices from
// construction and tests only the vertices of connecting regions; those tests
// go through this class (the paper uses a KD-tree, section 5; we use an AABB
// tree over the triangles).
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "base/Types.h"
#include "mesh/TriMesh.h"
#include "rig/BoneSegment.h"

namespace rigmesh {

class BoneVisibility {
  public:
    // Builds the search tree over the mesh triangles once; queries are const
    // and may run concurrently.
    explicit BoneVisibility(const TriMesh& mesh);
    ~BoneVisibility();
    BoneVisibility(BoneVisibility&&) noexcept;
    BoneVisibility& operator=(BoneVisibility&&) noexcept;
    BoneVisibility(const BoneVisibility&) = delete;
    BoneVisibility& operator=(const BoneVisibility&) = delete;

    // True if the open segment from `from` (a surface vertex) to `to` does not
    // cross the surface. Hits at `from` itself (its own triangles) are ignored
    // by starting the test a relative 1e-6 of the segment along it. The caller
    // makes sure the segment leaves `from` towards the inside (see
    // closestVisibleBones), so "no crossing" means "inside the volume".
    bool segmentIsInside(const Vec3& from, const Vec3& to) const;

  private:
    struct Tree;
    std::unique_ptr<Tree> tree_;
};

// For each vertex of `verticesToTest` (in that order), the bone(s) closest to
// it among those it sees from inside, with their distances: the closest
// visible distance d and every visible bone within d * (1 + tieTolerance).
// A bone is visible from vertex v with closest bone point p when v - p lies
// within 60 degrees of v's normal (Pinocchio's vectorInCone, which also makes
// the segment start inwards) and the segment v -> p stays inside. A vertex that
// sees no bone falls back to its closest bone(s) regardless of visibility; the
// number of such vertices goes to `verticesWithoutVisibleBone` if given.
// Bones with non-finite endpoints are never chosen.
std::vector<std::vector<std::pair<int, double>>> closestVisibleBones(
    const TriMesh& mesh, const std::vector<BoneSegment>& bones, const BoneVisibility& visibility,
    const std::vector<int>& verticesToTest, double tieTolerance = 3e-3,
    int* verticesWithoutVisibleBone = nullptr);

// The same with the mesh's unit vertex normals given (mesh/VertexNormals.h),
// for callers that test the same mesh several times.
std::vector<std::vector<std::pair<int, double>>> closestVisibleBones(
    const TriMesh& mesh, const std::vector<Vec3>& normals, const std::vector<BoneSegment>& bones,
    const BoneVisibility& visibility, const std::vector<int>& verticesToTest,
    double tieTolerance = 3e-3, int* verticesWithoutVisibleBone = nullptr);

}  // namespace rigmesh
