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

#include "rational.hpp"

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

}  // namespace sg
