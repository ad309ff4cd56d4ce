#pragma once
// The linear function of a non-uniform scheme at its special point x = 0,
// which fixes the scale of the basis functions' derivatives there.
//
// Let L be the control points whose basis function's closed support holds 0.
// The refinement B_j(x) = sum_k S_kj B_k(a x) maps them among themselves, and
// a right eigenvector xi of S restricted to L for the eigenvalue 1/a gives
// l(x) = sum_{j in L} xi_j B_j(x) with l(a x) = a l(x): homogeneous of degree
// 1 near 0. Where l is linear on each side (as for a scheme reproducing the
// knot parameter, like nubspline3, whose t is 2x left of 0 and x right of it),
// differentiating sum_j xi_j B_j = l at 0 from the right gives the one
// equation that the relation G = a A G at 0 (singular: eigenvalue 1/a) lacks:
// sum_{j in L} xi_j B_j'(0+) = l'(0+). xi is scaled so that l'(0+) = 1.
#include <vector>

#include "algebra/rational.hpp"
#include "curve/curve_scheme.hpp"

namespace sg {

struct PlacedFunction {
  long j = 0;             // control point
  std::size_t type = 0;   // the type placed there
};

struct LinearAtZero {
  std::vector<PlacedFunction> functions;  // L, by increasing j
  std::vector<Rational> xi;               // parallel to functions; l(x) = x for small x > 0
  bool left_linear = false;               // whether l is linear left of 0 too
  Rational left_slope = 0;                // l'(0-) when it is (nubspline3: 2)
};

// The type placed at control point j, or nullopt where none is.
std::optional<std::size_t> type_at(const CurveScheme& s, long j);

// Throws sg::Error with the reason when the eigenvalue 1/a has no unique
// eigenvector on L, or l is not linear to the right of 0 on the grid where
// only L's functions live.
LinearAtZero linear_at_zero(const CurveScheme& s);

}  // namespace sg
