#pragma once
// Derives the subdivision matrix of a non-uniform B-spline with a self-similar
// knot sequence (t_i = left*i for i < 0, right*i for i >= 0) by inserting the
// midpoint of every knot interval (Boehm's algorithm, exact rationals).
#include <map>
#include <vector>

#include "algebra/rational.hpp"
#include "curve/curve_scheme.hpp"

namespace sg {

struct Column {
  long first = 0;                 // fine control index of coefficients[0]
  std::vector<Rational> coefficients;
};

// Columns of S (coarse control c -> fine controls) for |c| <= radius. Control c
// owns the B-spline whose knots start at t_{c - (degree+1)/2}.
std::map<long, Column> knot_insertion_columns(const KnotSpec& spec, long radius);

}  // namespace sg
