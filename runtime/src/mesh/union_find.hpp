#pragma once
// Disjoint sets over 0..n-1 as a parent array (parent[x] == x at a root), for
// grouping a vertex's corners into fans: find with path halving.
#include <cstddef>
#include <vector>

namespace stencil_runtime {

inline std::size_t find_root(std::vector<std::size_t>& parent, std::size_t x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

}  // namespace stencil_runtime
