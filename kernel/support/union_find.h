#pragma once

#include <algorithm>
#include <numeric>
#include <vector>

namespace mechanist {

/// Disjoint sets of 0 .. n-1 (union-find with path halving; Tarjan 1975). Each set's root is
/// its smallest member, so the roots do not depend on the order of the joins.
struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  /// The root of x's set.
  int Find(int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  /// Merges the sets of a and b.
  void Join(int a, int b) {
    a = Find(a), b = Find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

}  // namespace mechanist
