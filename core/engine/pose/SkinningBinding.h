// A part's skin weights laid out once for skinning many poses (playback of
// a clip, a drag, baking several frames): the weight lists (one heap vector
// per vertex, part/BoneWeights.h) flattened into arrays (CSR: per vertex an
// offset into the influences; per influence a bone and its weight, every
// influence kept, in the lists' order) with each vertex's dominant bone
// found once. Bones are numbered compactly over the ids the weights name, so
// a pose's per-bone data fits a small packed table, and the binding stays
// valid for any skeleton that has those bones. The result is the same, bit
// for bit, as skinVertices over the weight lists (pose/Skinning.h): both run
// the kernels of pose/SkinningKernel.h with the influences in the same order.
#pragma once

#include <cstdint>
#include <vector>

#include "part/BoneWeights.h"
#include "pose/Skinning.h"

namespace rigmesh {

class SkinningBinding {
  public:
    SkinningBinding() = default;
    // Throws std::logic_error if there are 2^32 or more influences.
    explicit SkinningBinding(const WeightsById& weights);

    int vertexCount() const { return static_cast<int>(pivot_.size()); }
    std::size_t influenceCount() const { return weights_.size(); }
    // The distinct bone ids the weights name, ascending.
    const std::vector<BoneId>& bones() const { return bones_; }

    // Vertex v's influences are [offset(v), offset(v + 1)).
    std::uint32_t offset(int v) const { return offsets_[v]; }
    // Index into bones().
    std::uint32_t bone(std::uint32_t influence) const { return bone_[influence]; }
    double weight(std::uint32_t influence) const { return weights_[influence]; }
    // Vertex v's bone with the largest weight (the first of equals), as an
    // index into bones(); 0 for a vertex without influences.
    std::uint32_t pivot(int v) const { return pivot_[v]; }

  private:
    std::vector<BoneId> bones_;
    std::vector<std::uint32_t> offsets_{0};
    std::vector<std::uint32_t> bone_;
    std::vector<double> weights_;
    std::vector<std::uint32_t> pivot_;
};

// skinVertices (pose/Skinning.h) over a binding, into `out`: its buffers are
// reused when they already have the size, so a caller skinning every frame
// allocates (and the system maps pages) once. Throws std::logic_error as
// skinVertices does: the binding's vertex count differs from the rest
// positions', a bone it names is not in the transforms' skeleton, the
// normals are neither none nor one per position, or options.threads < 1.
void skinVertices(const std::vector<Vec3>& restPositions, const std::vector<Vec3>& restNormals,
                  const SkinningBinding& binding, const SkinningTransforms& transforms,
                  const SkinningOptions& options, SkinnedVertices& out);

}  // namespace rigmesh
