#pragma once
// Limit points as sparse rows over the control vertices: row r of a
// StencilRows holds the weights w with limit point = sum_c w[c] * control[c]
// (OpenSubdiv's Far::LimitStencilTable in spirit). This is what fitting and
// editing systems use: the rows are linear in the control points.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mesh.hpp"

namespace stencil_runtime {

struct StencilRows {
  std::size_t columns = 0;               // control vertices
  std::vector<std::size_t> offsets{0};   // row r: entries [offsets[r], offsets[r+1])
  std::vector<std::uint32_t> vertices;   // ascending within each row
  std::vector<double> weights;

  std::size_t rows() const { return offsets.size() - 1; }
  // The rows applied to positions (one per column).
  std::vector<Point> apply(const std::vector<Point>& control) const;
};

}  // namespace stencil_runtime
