#pragma once
// Whether a uniform binary curve scheme's scaling function phi is a piecewise
// polynomial on the unit intervals [m, m+1] (a B-spline, say), and its pieces,
// proved exactly. Candidate pieces of degree d are interpolated from phi's
// exact values on the grid 1/d; they are phi if and only if they satisfy the
// scheme's refinement equation and partition of unity, because the equation
// has one compactly supported solution with that normalisation. Both are
// checked exactly: each side of the equation is a polynomial of degree <= d on
// each half interval, so agreement at d + 1 points there is an identity.
// The runtime evaluates such a scheme's regular patches at any real parameter.
#include <optional>
#include <vector>

#include "algebra/rational.hpp"
#include "curve/curve_scheme.hpp"

namespace sg {

struct PolynomialPieces {
  int degree = 0;
  long first = 0;  // pieces[m - first] is phi on [m, m+1] as a polynomial in t = x - m
  std::vector<std::vector<Rational>> pieces;  // coefficients of t^0 .. t^degree
  // phi(m + t), t in [0, 1] (0 outside the pieces).
  Rational at(long m, const Rational& t) const;
};

// nullopt when phi is no piecewise polynomial of degree <= max_degree on the
// unit intervals, or the scheme is not a uniform binary one.
std::optional<PolynomialPieces> polynomial_pieces(const CurveScheme& curve, int max_degree = 7);

}  // namespace sg
