#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "stencil_runtime/mesh.hpp"

namespace stencil_runtime {

// A small sparse matrix of exact weights rounded to double: row r is
// sum over e in [offsets[r], offsets[r+1]) of weights[e] * input[columns[e]].
// The tables' patch subdivisions (quad and triangle) are stored this way.
struct SparseRows {
  std::size_t columns_count = 0;
  std::vector<std::size_t> offsets{0};
  std::vector<std::uint32_t> columns;
  std::vector<double> weights;
  std::size_t rows() const { return offsets.size() - 1; }
};

// The largest coordinate magnitude of a set of points.
inline double largest_magnitude(const std::vector<Point>& q) {
  double m = 0;
  for (const Point& p : q)
    for (double c : p) m = std::max(m, std::fabs(c));
  return m;
}

// out = rows * q, and the rounding this may add (the widest row's entries, plus
// two, times epsilon times the largest coordinate; the weights of a row sum to 1).
inline double apply(const SparseRows& rows, const std::vector<Point>& q, std::vector<Point>& out) {
  out.assign(rows.rows(), Point{0, 0, 0});
  std::size_t widest = 0;
  for (std::size_t r = 0; r < rows.rows(); ++r) {
    Point& p = out[r];
    for (std::size_t e = rows.offsets[r]; e != rows.offsets[r + 1]; ++e)
      for (std::size_t k = 0; k < 3; ++k) p[k] += rows.weights[e] * q[rows.columns[e]][k];
    widest = std::max(widest, rows.offsets[r + 1] - rows.offsets[r]);
  }
  return static_cast<double>(widest + 2) * std::numeric_limits<double>::epsilon() * largest_magnitude(q);
}

}  // namespace stencil_runtime
