#pragma once
// The regular curve's basis at ANY parameter t in [0, 1], exactly up to
// rounding: the four values phi(t - p), p = -1..2, and their derivatives,
// for a scheme whose basis is not polynomial (nonpoly), from the stored
// values on the tables' grids and the curve's two half-interval matrices.
//
// Halving maps t to 2t - c (c = 0 or 1) and the basis row v(t) to
// v(t) = v(2t - c) H_c, v'(t) = 2 v'(2t - c) H_c. The orbit of t
//  - reaches a grid the tables hold (every double does: its binary digits run
//    out), and the rows are carried back; or
//  - for a rational whose odd denominator no stored grid holds, becomes
//    periodic: around a cycle of length r, v is the left eigenvector of the
//    cycle's product M for the eigenvalue 1 (with sum v = 1) and v' the one
//    for 2^-r (with sum v' = 0 and sum_p p v'_p = 1, the derivative of the
//    reproduced linear function t). Both come out by power iteration around
//    the cycle, whose other eigenvalues are smaller (the scheme converges and
//    is C1).
// Carried back in doubles, 2 v' H doubles any error in the direction of the
// limit stencil; that direction is exactly the part of v' whose sum is not 0,
// so each step projects it away (and renormalises sum v = 1), which keeps the
// rounding to a few ulps per step instead of 2^steps.
#include <cstdint>
#include <functional>

#include "stencil_runtime/exact_parameter.hpp"

namespace stencil_runtime {

// half[c][k][j]: child c's point k from parent point j.
using HalfMatrices = double[2][4][4];

// `held(t, w, dw)` writes the stored basis and derivative at t and returns
// true when a stored grid holds t exactly. Throws EvaluationError when a
// cycle is longer than the stated limit or its iteration does not converge.
void curve_basis_by_orbit(const HalfMatrices& half, const Fraction& t,
                          const std::function<bool(const Fraction&, double*, double*)>& held, double* w, double* dw);
void curve_basis_by_orbit(const HalfMatrices& half, double t, const std::function<bool(double, double*, double*)>& held,
                          double* w, double* dw);

// The longest orbit followed (a rational's period can be as long as its odd denominator).
inline constexpr std::int64_t kMaxOrbitSteps = std::int64_t{1} << 20;

}  // namespace stencil_runtime
