// Union-find over dense indices with path halving: connected pieces of a
// mesh, cycles and components of a skeleton.
#pragma once

#include <numeric>
#include <vector>

namespace rigmesh {

class DisjointSets {
  public:
    explicit DisjointSets(std::size_t n) : parent_(n) {
        std::iota(parent_.begin(), parent_.end(), 0);
    }
    int find(int i) {
        while (parent_[i] != i)
            i = parent_[i] = parent_[parent_[i]];
        return i;
    }
    // Joins the sets of a and b (b's under a's root); false when they were one.
    bool unite(int a, int b) {
        a = find(a);
        b = find(b);
        if (a == b)
            return false;
        parent_[b] = a;
        return true;
    }

  private:
    std::vector<int> parent_;
};

}  // namespace rigmesh
