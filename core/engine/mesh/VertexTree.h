// The vertices in a k-d tree (split at the median of the box's longest
// side), for exact nearest-vertex queries: the mirror plane search
// (rig/MirrorSymmetry) and the vertex mirror of X-mirror painting
// (rig/VertexMirror). A reflection through a wrong candidate plane lands far
// from the surface; a uniform grid searched in shells of cells then visits
// every cell out to it (measured: 4.3 of 4.8 s of an auto-rig on 4820
// vertices), the tree only the subtrees whose box is nearer than the best
// vertex found.
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "base/Types.h"

namespace rigmesh {

class VertexTree {
  public:
    // `points` must outlive the tree.
    explicit VertexTree(const std::vector<Vec3>& points);

    // The nearest point's index (-1 for none).
    int nearest(const Vec3& p) const;

  private:
    static constexpr int kLeafSize = 8;
    struct Node {
        Eigen::AlignedBox3d box;
        int begin = 0, end = 0;   // the points order_[begin, end)
        int low = -1, high = -1;  // children (none for a leaf)
    };

    int build(int begin, int end);
    // `boxDistance`: the squared distance from p to the node's box.
    void search(int index, double boxDistance, const Vec3& p, int& best,
                double& bestDistance) const;

    const std::vector<Vec3>& points_;
    std::vector<int> order_;
    std::vector<Vec3> sorted_;  // points_[order_[i]], side by side in the leaves
    std::vector<Node> nodes_;
};

}  // namespace rigmesh
