#pragma once
// The sum every stencil evaluation ends in: sum_h weights[h] * prepared[points[h]],
// h = 0..count-1, in that order (so every route to a point rounds alike).
#include <cstddef>
#include <vector>

#include "stencil_runtime/mesh.hpp"

namespace stencil_runtime {

inline Point stencil_sum(const double* weights, const int* points, std::size_t count, const Point* prepared) {
  Point out{0, 0, 0};
  for (std::size_t h = 0; h < count; ++h) {
    const Point& q = prepared[points[h]];
    for (std::size_t k = 0; k < 3; ++k) out[k] += weights[h] * q[k];
  }
  return out;
}

// A patch's control points, copied out of the prepared points (descents and
// sub-patches consume their own copy): out[h] = prepared[points[h]].
inline void gather_points(const std::vector<int>& points, const Point* prepared, std::vector<Point>& out) {
  out.resize(points.size());
  for (std::size_t h = 0; h < points.size(); ++h) out[h] = prepared[points[h]];
}
inline std::vector<Point> gather_points(const std::vector<int>& points, const Point* prepared) {
  std::vector<Point> out;
  gather_points(points, prepared, out);
  return out;
}

}  // namespace stencil_runtime
