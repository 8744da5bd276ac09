// Sets of the items 0 … n−1 joined pairwise (union-find with path halving):
// the connected patches of a surface, the folds of a scan, the groups of a
// node's star, nodes that share an element.
#pragma once
#include <cstddef>
#include <numeric>
#include <vector>

namespace anvil {

class DisjointSets {
public:
  /// `count` items, each its own set.
  explicit DisjointSets(std::size_t count) : parent_(count) { std::iota(parent_.begin(), parent_.end(), 0); }

  /// The item that names the set of `item`.
  int root(int item) {
    while (parent_[item] != item)
      item = parent_[item] = parent_[parent_[item]];
    return item;
  }

  /// Joins the sets of `a` and `b`, named by b's root from then on.
  void join(int a, int b) { parent_[root(a)] = root(b); }

private:
  std::vector<int> parent_;
};

} // namespace anvil
