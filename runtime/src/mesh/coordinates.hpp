#pragma once
// The one rule for control-point coordinates: finite and at most
// limits::kMaxCoordinate in magnitude (tessellations are written as floats).
// Surface::set_positions, subdivide, write_obj and the fit apply it, each with
// its own error type.
#include <cmath>
#include <cstddef>
#include <cstdio>
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

// `x` where it keeps the rule, else LoadError "<where>: coordinate <x> is not
// a finite number of magnitude at most 1e37": what the readers of points and
// meshes in files say (a file's number, named by its line or item).
inline double checked_file_coordinate(double x, const std::string& where) {
  if (!std::isfinite(x) || std::fabs(x) > limits::kMaxCoordinate) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", x);
    throw LoadError(where + ": coordinate " + text + " is not a finite number of magnitude at most 1e37");
  }
  return x;
}

// The diagonal of the bounding box of points[0 .. count) (0 for none): what
// relative tolerances and extents are measured against. hypot: no underflow
// for a tiny mesh.
inline double box_diagonal(const Point* points, std::size_t count) {
  Point lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  for (std::size_t i = 0; i < count; ++i)
    for (int k = 0; k < 3; ++k) lo[k] = std::fmin(lo[k], points[i][k]), hi[k] = std::fmax(hi[k], points[i][k]);
  return count > 0 ? std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) : 0.0;
}

}  // namespace stencil_runtime
