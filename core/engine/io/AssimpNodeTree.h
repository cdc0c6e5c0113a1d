// An aiScene's node hierarchy flattened parent first, with rest and animated
// global transforms. A node's parent is the one its
// mParent names when that leads to the root (Assimp 5.2.5's Half-Life MDL
// reader lists every bone under one node and names the real parent bone
// only there), else the node whose children list holds it. Internal to io/: included only from
// .cpp files (it includes Assimp).
#pragma once

#include <assimp/scene.h>

#include <string>
#include <unordered_map>
#include <vector>

#include <Eigen/Geometry>

namespace rigmesh {

class AssimpNodeTree {
  public:
    // `scale`: metres per file unit, applied above the root (FBX units).
    explicit AssimpNodeTree(const aiScene& scene, double scale = 1.0);

    int size() const { return static_cast<int>(nodes_.size()); }
    const aiNode& node(int i) const { return *nodes_[static_cast<std::size_t>(i)]; }
    int parent(int i) const { return parents_[static_cast<std::size_t>(i)]; }
    // -1 when no node has that name.
    int find(const std::string& name) const;
    // The node's transform relative to the root, as stored in the file.
    const Eigen::Affine3d& restGlobal(int i) const { return rest_[static_cast<std::size_t>(i)]; }
    // Every node's global transform with `animation` sampled at `ticks`
    // (nodes without a channel keep their stored transform).
    std::vector<Eigen::Affine3d> animatedGlobals(const aiAnimation& animation, double ticks) const;

  private:
    Eigen::Affine3d scale_ = Eigen::Affine3d::Identity();
    std::vector<const aiNode*> nodes_;
    std::vector<int> parents_;
    std::vector<Eigen::Affine3d> rest_;
    std::unordered_map<std::string, int> byName_;
};

// A channel's local transform at `ticks`: keys interpolated linearly
// (rotations by slerp), clamped outside the keys; a part without keys
// (position, rotation or scaling) keeps that part of `rest`.
Eigen::Affine3d sampleChannel(const aiNodeAnim& channel, double ticks, const Eigen::Affine3d& rest);

}  // namespace rigmesh
