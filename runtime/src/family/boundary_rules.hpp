#pragma once
// OpenSubdiv's boundary rules for a subdivision step on a mesh with
// boundaries, shared by the quad and Loop steps: a boundary edge's new point is
// its midpoint, a boundary vertex follows the crease curve's vertex mask over
// its two boundary neighbours, and with `corners` (edge-and-corner) a boundary
// vertex in one face stays where it is.
#include <cstdint>

#include "family/refinement.hpp"

namespace stencil_runtime {

struct BoundaryRules {
  double centre = 0, neighbour = 0;  // the crease curve's vertex mask
  bool corners = false;
};

// A boundary vertex's row: itself alone (a corner) or the crease curve's mask
// over its neighbours along the boundary, `after` (across its outgoing boundary
// edge) and `before` (across its incoming one).
inline void boundary_row(SparseEntries& row, std::uint32_t v, std::uint32_t after, std::uint32_t before, int faces,
                         const BoundaryRules& rules) {
  row.assign(1, {v, 1.0});
  if (rules.corners && faces == 1) return;
  row.assign({{v, rules.centre}, {after, rules.neighbour}, {before, rules.neighbour}});
}

}  // namespace stencil_runtime
