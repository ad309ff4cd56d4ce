#pragma once
// Control points moved to their centroid, the move kept in `offset`: a
// descent towards an extraordinary vertex takes differences of points whose
// spread shrinks by the subdominant eigenvalue per step while their
// coordinates stay as large, so that derivatives (differences over the
// sub-patch's size) of points rounded at the size of the coordinates lose a
// digit every few steps (1e-13 from the vertex, whole digits of the normal).
// Subdivision rows are affine (they sum to one), so the children of the moved
// points are the children moved; derivatives do not see the move, and the
// point is the one found plus `offset`.
#include <vector>

#include "stencil_runtime/mesh.hpp"

namespace stencil_runtime {

inline void recentre(std::vector<Point>& points, Point& offset) {
  if (points.empty()) return;
  Point centre{0, 0, 0};
  for (const Point& p : points)
    for (int k = 0; k < 3; ++k) centre[k] += p[k];
  for (int k = 0; k < 3; ++k) centre[k] /= static_cast<double>(points.size());
  for (Point& p : points)
    for (int k = 0; k < 3; ++k) p[k] -= centre[k];
  for (int k = 0; k < 3; ++k) offset[k] += centre[k];
}

}  // namespace stencil_runtime
