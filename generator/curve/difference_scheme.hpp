#pragma once
// Derivatives of a uniform scheme's basis function through its difference
// schemes (Dyn and Levin, "Subdivision schemes in geometric modelling", 2002).
//
// With sigma(z) = 1 + z + ... + z^(a-1) and symbol s(z) = sum_i s_i z^i of
// phi(x) = sum_i s_i phi(a x - i), put s_0 = s and s_r = a s_(r-1) / sigma
// (exact polynomial division). When the scheme of s_r converges, its
// normalised basis psi_r is continuous and
//     phi^(r)(x) = sum_{i=0..r} (-1)^i C(r, i) psi_r(x - i).
// (Order 1: both sides satisfy phi'(x) = a sum_i s_i phi'(a x - i), and
// sum_j j (psi(x - j) - psi(x - j - 1)) = sum_j psi(x - j) = 1 is the
// derivative of the linear reproduction sum_j j phi(x - j) = x + c; order r
// repeats the step.) The scheme of s_r converges exactly when sigma divides s_r
// and the scheme q = s_r / sigma is contractive, ||S_q^L||_inf < 1 for some L;
// then phi is C^r. The check is exact (rational coefficients).
#include <map>
#include <string>
#include <vector>

#include "curve/curve_scheme.hpp"
#include "curve/curve_solution.hpp"
#include "curve/curve_table.hpp"

namespace sg {

// The derivative orders a uniform scheme has, and the schemes of psi_1, psi_2, ...
struct DerivativeSchemes {
  std::vector<CurveScheme> schemes;  // schemes[r - 1]: the scheme of psi_r (uniform, supports computed)
  // Why there is no order schemes.size() + 1 (empty when max_order was reached).
  std::string stop;
};

// Orders 1..max_order as far as the scheme is shown to be C^r. A scheme that
// is not uniform gets none, with the reason in `stop`.
DerivativeSchemes derivative_schemes(const CurveScheme& scheme, int max_order);

// Whether the uniform scheme with mask `mask` (shift -> coefficient) of arity
// `arity` converges uniformly: sigma divides it and the quotient scheme is
// contractive within `max_steps` steps. `why` gets the reason when it does not.
bool converges(const std::map<long, Rational>& mask, int arity, int max_steps, std::string& why);

// Why a uniform scheme is not shown to converge (its difference scheme is not
// contractive within 16 steps), or "" if it is, or if it is not uniform (not
// analysed). Its tables are then the exact solution of the scaling
// relations, which need not be the values of any limit function.
std::string convergence_doubt(const CurveScheme& scheme);

// The table of a uniform scheme's values at their rate, with the derivatives of
// `derivatives` (psi_r solved by residue classes at the same rate).
CurveTable table_with_derivatives(const CurveScheme& scheme, const CurveSolution& values, const DerivativeSchemes& derivatives);

// (-1)^i C(r, i), i = 0..r: phi^(r)(x) = sum_i weights[i] psi_r(x - i).
std::vector<long> difference_weights(int r);

// The nonzero values of phi^(r) on (1/n)Z from psi_r's there (`psi`: the
// solution of derivative scheme r at rate n), keyed by grid index.
std::map<long, Rational> derivative_from_difference(const TypeValues& psi, int r, long n);

}  // namespace sg
