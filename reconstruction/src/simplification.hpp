#pragma once
// Edge-collapse simplification (Lindstrom-Turk costs and placements, CGAL) of
// a closed triangle surface down to a number of vertices.
#include <cstddef>

#include "cgal_mesh.hpp"

namespace stencil_reconstruction {

void simplify_to_vertices(TriangleMesh& mesh, std::size_t vertices);

}  // namespace stencil_reconstruction
