#pragma once
// The patch of one face of a prepared quad mesh: which table evaluates it
// (regular, or the extraordinary patch of valence v), how the face's parameters
// map to the patch's (the extraordinary vertex is at patch (0,0)), and the
// mesh vertices that are its control points, in the tables' canonical order
// (docs/table-format.md).
#include <vector>

#include "mesh/uniform_topology.hpp"
#include "stencil_runtime/exact_parameter.hpp"

namespace stencil_runtime {

struct QuadPatch {
  int valence = 4;    // 4: regular patch (16 points); otherwise 2v+8 points
  int rotation = 0;   // face corner at patch (0,0)
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
  // The same for an exact parameter.
  ExactParameter to_patch(const ExactParameter& p) const {
    const Fraction one{1, 1};
    switch (rotation) {
      case 0: return p;
      case 1: return {p.v, subtract(one, p.u)};
      case 2: return {subtract(one, p.u), subtract(one, p.v)};
      default: return {subtract(one, p.v), p.u};
    }
  }
};

// Requires at most one extraordinary corner on the face (the preparation).
QuadPatch gather_quad_patch(const QuadTopology& topology, std::size_t face);

}  // namespace stencil_runtime
