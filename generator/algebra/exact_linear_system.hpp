#pragma once
// Exact solution of a sparse, possibly over-determined linear system with
// rational coefficients. Rows are kept as integer vectors (fraction-free
// elimination with content removal), pivots are chosen by smallest column
// count, then shortest row, so that tree-like and chain-like systems (the
// scaling relations) eliminate with little fill.
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "algebra/rational.hpp"

namespace sg {

struct LinearSolution {
  enum class Status { Unique, Underdetermined, Inconsistent };
  Status status = Status::Unique;
  std::size_t nullity = 0;      // dimension of the solution space when Underdetermined
  std::vector<Rational> values;  // when Unique
  std::string describe() const;  // "unique", "a solution space of dimension 3", "no solution"
};

class ExactLinearSystem {
 public:
  explicit ExactLinearSystem(std::size_t unknowns) : unknowns_(unknowns) {}
  std::size_t unknowns() const { return unknowns_; }
  std::size_t equations() const { return rows_.size(); }

  // sum coeffs[i].second * x[coeffs[i].first] = rhs. Repeated indices are summed.
  void add_equation(const std::vector<std::pair<std::size_t, Rational>>& coeffs, const Rational& rhs);

  LinearSolution solve() const;

 private:
  struct Row {
    std::vector<std::pair<std::size_t, Integer>> entries;  // sorted by column; column == unknowns_ is the rhs
  };
  std::size_t unknowns_;
  std::vector<Row> rows_;
};

// The left eigenvector x = x S for eigenvalue 1 of the square matrix S whose
// row r is `rows[r]` (any range of (column, entry) pairs), normalised so that
// its entries sum to 1: the limit stencil of a subdivision matrix.
template <class Rows>
LinearSolution left_fixed_vector(const Rows& rows) {
  const std::size_t m = rows.size();
  std::vector<std::vector<std::pair<std::size_t, Rational>>> columns(m);
  for (std::size_t r = 0; r < m; ++r)
    for (const auto& [c, w] : rows[r]) columns[c].emplace_back(r, w);
  ExactLinearSystem system(m);
  for (std::size_t c = 0; c < m; ++c) {
    columns[c].emplace_back(c, Rational(-1));
    system.add_equation(columns[c], 0);
  }
  std::vector<std::pair<std::size_t, Rational>> unity;
  for (std::size_t r = 0; r < m; ++r) unity.emplace_back(r, Rational(1));
  system.add_equation(unity, 1);
  return system.solve();
}

}  // namespace sg
