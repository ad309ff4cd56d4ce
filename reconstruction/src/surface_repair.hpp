#pragma once
// What a reconstruction needs before it can be a control mesh: one closed,
// outward-oriented surface. Unused vertices and all but the largest connected
// component are removed, every hole is triangulated (CGAL's minimal-area
// hole triangulation, refined to the surrounding density).
#include <cstddef>

#include "cgal_mesh.hpp"

namespace stencil_reconstruction {

struct RepairCounts {
  std::size_t holes_filled = 0, components_dropped = 0;
};

// Throws ReconstructionError when no closed surface results.
RepairCounts close_surface(TriangleMesh& mesh);

}  // namespace stencil_reconstruction
