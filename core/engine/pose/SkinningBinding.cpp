#include "pose/SkinningBinding.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "base/ParallelFor.h"
#include "pose/SkinningKernel.h"

namespace rigmesh {

namespace {

// One pose's per-bone data by the binding's bone index, packed: a bone's dual
// quaternion in one cache line, its matrix and translation in the next two.
struct alignas(64) PackedBone {
    double real[4];
    double dual[4];
    double matrix[9];  // column-major
    double translation[3];
    bool identity;
};

struct PackedTable {
    const std::vector<PackedBone>& bones;
    const double* real(std::size_t i) const { return bones[i].real; }
    const double* dual(std::size_t i) const { return bones[i].dual; }
    const double* matrix(std::size_t i) const { return bones[i].matrix; }
    const double* translation(std::size_t i) const { return bones[i].translation; }
    bool identity(std::size_t i) const { return bones[i].identity; }
};

// The binding's influences as the kernels read them.
struct BindingSource {
    const SkinningBinding& binding;
    bool empty(int v) const { return binding.offset(v) == binding.offset(v + 1); }
    std::size_t pivot(int v) const { return binding.pivot(v); }
    template <class F>
    void forEach(int v, F&& f) const {
        for (std::uint32_t i = binding.offset(v), end = binding.offset(v + 1); i < end; ++i)
            f(static_cast<std::size_t>(binding.bone(i)), binding.weight(i));
    }
};

}  // namespace

SkinningBinding::SkinningBinding(const WeightsById& weights) {
    std::size_t total = 0;
    for (const auto& list : weights) {
        total += list.size();
        for (const auto& [bone, weight] : list)
            bones_.push_back(bone);
    }
    if (total >= std::numeric_limits<std::uint32_t>::max())
        throw std::logic_error("A skinning binding holds fewer than 2^32 influences.");
    std::sort(bones_.begin(), bones_.end());
    bones_.erase(std::unique(bones_.begin(), bones_.end()), bones_.end());
    // Bone id -> index into bones_: a plain array for the usual compact ids,
    // a hash map for ids far beyond the bone count (a hand-edited file).
    const bool dense = bones_.empty() || bones_.back() < 4 * bones_.size() + 1024;
    std::vector<std::uint32_t> denseIndex(dense && !bones_.empty() ? bones_.back() + 1 : 0);
    std::unordered_map<BoneId, std::uint32_t> sparseIndex;
    for (std::size_t i = 0; i < bones_.size(); ++i) {
        if (dense)
            denseIndex[bones_[i]] = static_cast<std::uint32_t>(i);
        else
            sparseIndex.emplace(bones_[i], static_cast<std::uint32_t>(i));
    }

    offsets_.reserve(weights.size() + 1);
    pivot_.reserve(weights.size());
    bone_.reserve(total);
    weights_.reserve(total);
    for (const auto& list : weights) {
        std::uint32_t pivot = 0;
        double largest = 0;
        for (std::size_t k = 0; k < list.size(); ++k) {
            const std::uint32_t b =
                dense ? denseIndex[list[k].first] : sparseIndex.at(list[k].first);
            // The first of the largest weights, as std::max_element finds it.
            if (k == 0 || largest < list[k].second) {
                largest = list[k].second;
                pivot = b;
            }
            bone_.push_back(b);
            weights_.push_back(list[k].second);
        }
        pivot_.push_back(pivot);
        offsets_.push_back(static_cast<std::uint32_t>(bone_.size()));
    }
}

void skinVertices(const std::vector<Vec3>& restPositions, const std::vector<Vec3>& restNormals,
                  const SkinningBinding& binding, const SkinningTransforms& transforms,
                  const SkinningOptions& options, SkinnedVertices& out) {
    skinning::checkInput(static_cast<std::size_t>(binding.vertexCount()), restPositions.size(),
                         restNormals.size(), options.threads);
    const int count = static_cast<int>(restPositions.size());
    const bool withNormals = !restNormals.empty();

    // The pose's per-bone data, once per call, for the bones the weights name.
    std::vector<PackedBone> packed(binding.bones().size());
    for (std::size_t i = 0; i < packed.size(); ++i) {
        const BoneId id = binding.bones()[i];
        skinning::checkBone(transforms, id);
        const std::size_t slot = transforms.slotOf(id);
        PackedBone& p = packed[i];
        std::copy_n(transforms.dualQuaternionReal(slot).data(), 4, p.real);
        std::copy_n(transforms.dualQuaternionDual(slot).data(), 4, p.dual);
        std::copy_n(transforms.rotationMatrix(slot).data(), 9, p.matrix);
        std::copy_n(transforms.translation(slot).data(), 3, p.translation);
        p.identity = transforms.isIdentity(slot);
    }

    out.positions.resize(count);
    out.normals.resize(withNormals ? count : 0);
    const PackedTable table{packed};
    const BindingSource source{binding};
    const auto run = [&](int begin, int end) {
        skinning::skinRange(table, source, options.method, begin, end, restPositions, restNormals,
                            out);
    };
    // Contiguous vertex ranges as skinVertices over the lists: the output
    // does not depend on the thread count.
    parallelFor(count, options.threads, [&](int begin, int end, int) { run(begin, end); });
}

}  // namespace rigmesh
