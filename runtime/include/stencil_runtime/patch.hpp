#pragma once
// The patch of one face of a prepared quad mesh: which table evaluates it
// (regular, or the extraordinary patch of valence v), how the face's parameters
// map to the patch's (the extraordinary vertex is at patch (0,0)), and the
// mesh vertices that are its control points, in the tables' canonical order
// (docs/table-format.md).
#include <vector>

#include "quad_topology.hpp"

namespace stencil_runtime {

struct Patch {
  int valence = 4;    // 4: regular patch (16 points); otherwise 2v+8 points
  int rotation = 0;   // face corner at patch (0,0); face (i,j) -> patch via to_patch()
  std::vector<int> points;

  // Grid indices (i/n, j/n) of the face -> grid indices of the patch.
  void to_patch(long i, long j, long n, long& pi, long& pj) const {
    switch (rotation) {
      case 0: pi = i, pj = j; break;
      case 1: pi = j, pj = n - i; break;
      case 2: pi = n - i, pj = n - j; break;
      default: pi = n - j, pj = i; break;
    }
  }
};

// Requires at most one extraordinary corner on the face (prepare_mesh).
Patch gather_patch(const QuadTopology& topology, std::size_t face);

}  // namespace stencil_runtime
