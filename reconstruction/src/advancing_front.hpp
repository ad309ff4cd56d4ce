#pragma once
// Advancing-front surface reconstruction (Cohen-Steiner and Da, CGAL): an
// oriented triangle surface through (a subset of) the points. It may leave
// holes, and points no face uses (removed later).
#include <vector>

#include "cgal_mesh.hpp"

namespace stencil_reconstruction {

TriangleMesh advancing_front(const std::vector<CgalPoint>& points);

}  // namespace stencil_reconstruction
