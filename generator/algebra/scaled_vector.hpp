#pragma once
// A rational vector stored as integer numerators over one common denominator,
// the form in which the quad patch solver multiplies stencils by exact matrices
// (integer products, no per-entry gcd) and the form the tables record.
#include <utility>
#include <vector>

#include "algebra/rational.hpp"

namespace sg {

struct ScaledVector {
  std::vector<Integer> num;
  Integer den = 1;

  // Divides numerators and denominator by their gcd; denominator positive.
  void reduce();
  std::vector<Rational> rationals() const;
  bool operator==(const ScaledVector& o) const { return num == o.num && den == o.den; }
};

// An exact matrix as integer entries over one denominator, rows stored sparse.
struct ScaledMatrix {
  std::vector<std::vector<std::pair<std::size_t, Integer>>> rows;
  Integer den = 1;
  std::size_t columns = 0;
};

ScaledMatrix scale_rows(const std::vector<std::vector<std::pair<std::size_t, Rational>>>& rows, std::size_t columns);

// x * M (x has one entry per row of M); result not reduced.
ScaledVector left_multiply(const ScaledVector& x, const ScaledMatrix& m);

ScaledVector scaled_from_rationals(const std::vector<Rational>& values);

}  // namespace sg
