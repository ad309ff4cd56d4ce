#pragma once
// Exact parametric derivatives d/du and d/dv of a quad patch's stencils on the
// grid (1/g)Z^2, wherever they exist: at every grid point but the
// extraordinary vertex (0, 0) itself.
//
// The value recursion of ev_patch_solver.hpp differentiates term by term:
// in the extraordinary child, W(x) = W(2x) A0 gives W_u(x) = 2 W_u(2x) A0; in a
// regular child with offset o, W(x) = R(2x - o) C_c gives W_u(x) = 2 R_u(2x - o) C_c,
// where the regular stencil R(X, Y) = phi(X - a) phi(Y - b) has R_u = phi'(X - a)
// phi(Y - b) and R_v = phi(X - a) phi'(Y - b). Every x other than 0 reaches a
// regular child after finitely many halvings, so the recursion ends there; it
// needs the regular curve's phi' on the grid, which exists when that curve is C1
// (curve/difference_scheme.hpp). At the vertex the patch has no parametric
// derivative for valences other than 4: its tangent plane comes from the
// subdominant eigenvectors (not computed here).
#include <vector>

#include "algebra/rational.hpp"
#include "curve/curve_solution.hpp"
#include "quad/quad_scheme.hpp"

namespace sg {

struct PatchDerivativeGrid {
  int valence = 4;
  long grid = 1;
  std::size_t points = 0;  // 2v+8 control points per stencil
  // (grid+1)^2 stencils each, index j*(grid+1)+i; the entry of (0, 0) is empty.
  std::vector<std::vector<Rational>> du, dv;
  const std::vector<Rational>& u_at(long i, long j) const { return du[static_cast<std::size_t>(j * (grid + 1) + i)]; }
  const std::vector<Rational>& v_at(long i, long j) const { return dv[static_cast<std::size_t>(j * (grid + 1) + i)]; }
};

// `curve`: the regular curve's values at rate g; `curve_derivative`: phi' on
// the same grid, keyed by grid index k (parameter k/g), nonzero entries only.
PatchDerivativeGrid solve_ev_patch_derivatives(const QuadScheme& scheme, int valence, long g, const CurveSolution& curve,
                                               const std::map<long, Rational>& curve_derivative);
// Convenience: solves the curve and its derivative at rate g first. Throws
// sg::Error when the regular curve has no continuous derivative.
PatchDerivativeGrid solve_ev_patch_derivatives(const QuadScheme& scheme, int valence, long g);

}  // namespace sg
