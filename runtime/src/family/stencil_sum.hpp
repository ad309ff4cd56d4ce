#pragma once
// The sum every stencil evaluation ends in: sum_h weights[h] * prepared[points[h]],
// h = 0..count-1, in that order (so every route to a point rounds alike).
#include <cstddef>

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

}  // namespace stencil_runtime
