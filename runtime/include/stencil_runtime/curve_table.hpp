#pragma once
// Loads the compact binary curve tables written by stencilgen (format in
// docs/table-format.md) and evaluates curves from them. Doubles only.
#include <cstdint>
#include <string>
#include <vector>

#include "binary_format.hpp"
#include "error.hpp"

namespace stencil_runtime {

// values[k - first] at grid index k, zero outside the stored range.
inline double grid_value(std::int64_t first, const std::vector<double>& values, std::int64_t k) {
  std::int64_t i = 0;
  if (__builtin_sub_overflow(k, first, &i)) return 0.0;  // far outside the support, either way
  return (i >= 0 && i < static_cast<std::int64_t>(values.size())) ? values[static_cast<std::size_t>(i)] : 0.0;
}

// Values on the grid (1/n)Z from the grid index `first` on; zero elsewhere.
struct GridValues {
  std::int64_t first = 0;
  std::vector<double> values;
  double at(std::int64_t k) const { return grid_value(first, values, k); }
};

struct CurveFunction {
  std::string name;
  format::Placement placement = format::Placement::Everywhere;
  std::int64_t position = 0;
  std::int64_t first = 0;       // grid index of values[0]
  std::vector<double> values;   // phi(k/n) for k = first, first+1, ...
  double at(std::int64_t k) const { return grid_value(first, values, k); }
  // derivatives[r - 1]: phi^(r)(k/n), the exact derivative rounded (version 2
  // tables; as many orders as the table's derivative_orders).
  std::vector<GridValues> derivatives;
};

struct CurveTable {
  std::uint64_t scheme_hash = 0;
  std::uint32_t arity = 2, n = 1;
  // Orders of derivative every function carries: 0 (a scheme that is not C1,
  // or a non-uniform one), 1 or 2 (format::kMaxCurveDerivativeOrder).
  std::uint32_t derivative_orders = 0;
  std::vector<CurveFunction> functions;
};

// Throws LoadError naming the file and what is wrong (missing, truncated,
// bad magic, unsupported version, checksum mismatch, or a scheme hash other
// than `expected_hash` when that is nonzero).
CurveTable load_curve_table(const std::string& path, std::uint64_t expected_hash = 0);

// Limit point of a uniform curve scheme at parameter k/n:
// sum_j points[j] * phi(k/n - j) over the control points given.
double evaluate_uniform_curve(const CurveTable& table, const std::vector<double>& points, std::int64_t k);

// Its derivative of order r (1 or 2) in x at k/n: sum_j points[j] * phi^(r)(k/n - j).
// Throws EvaluationError for a table without that order (the message says why).
double evaluate_uniform_curve_derivative(const CurveTable& table, const std::vector<double>& points, std::int64_t k, int order);

}  // namespace stencil_runtime
