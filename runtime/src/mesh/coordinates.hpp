#pragma once
// The one rule for control-point coordinates: finite and at most
// limits::kMaxCoordinate in magnitude (tessellations are written as floats).
// Surface::set_positions, subdivide, write_obj and the fit apply it, each with
// its own error type.
#include <cmath>
#include <cstddef>
#include <string>

#include "stencil_runtime/error.hpp"
#include "stencil_runtime/limits.hpp"
#include "stencil_runtime/mesh.hpp"

namespace stencil_runtime {

// "" when every coordinate of points[0 .. count) keeps the rule, else what the
// first that does not is: "vertex 3 (numbered from 0) has the coordinate nan; ...",
// the point named by `noun` ("point 3" for the fit's data).
inline std::string coordinate_fault(const Point* points, std::size_t count, const char* noun = "vertex") {
  for (std::size_t v = 0; v < count; ++v)
    for (const double x : points[v])
      if (!std::isfinite(x) || std::fabs(x) > limits::kMaxCoordinate)
        return std::string(noun) + " " + std::to_string(v) + " (numbered from 0) has the coordinate " + number_text(x) +
               "; coordinates must be finite and at most " + number_text(limits::kMaxCoordinate) + " in magnitude";
  return {};
}

}  // namespace stencil_runtime
