// The curve across a boundary (or an infinitely sharp crease) of the two quad
// schemes, shipped as column schemes (schemes/*-boundary.json), against
// independent computations: Cox-de Boor with OpenSubdiv's phantom point for
// the cubic B-spline, and plain subdivision of the half-line for nonpoly-curve.
#include <catch2/catch.hpp>
#include <map>
#include <string>

#include "curve/curve_scheme_loader.hpp"
#include "curve/eigen_solver.hpp"
#include "curve/residue_solver.hpp"
#include "independent.hpp"

using independent::Q;

namespace {

// The solution's basis of control j at grid index k (parameter k/n).
Q basis(const sg::CurveScheme& s, const sg::CurveSolution& sol, long j, long k) {
  for (std::size_t h = 0; h < s.types.size(); ++h)
    if (s.types[h].placed_at(j)) return sol.types[h].at(k - j * sol.n);
  FAIL("no type is placed at control " << j);
  return 0;
}

// Cubic B-spline on integer knots: control j owns N_{j-2,3}, centred at j.
Q cubic(long j, const Q& x) {
  return independent::cox_de_boor([](long i) { return Q(i); }, j - 2, 3, x);
}

// OpenSubdiv's boundary: on x >= 0 the cubic B-spline with the phantom point
// p(-1) = 2 p(0) - p(1), so control 0 owns N_0 + 2 N_{-1} and control 1 owns
// N_1 - N_{-1}; controls left of 0 do not reach x > 0. Mirrored for x <= 0.
Q phantom_basis(long j, const Q& x) {
  if (x < 0) return phantom_basis(-j, -x);
  if (j < 0) return 0;
  if (j == 0) return cubic(0, x) + 2 * cubic(-1, x);
  if (j == 1) return cubic(1, x) - cubic(-1, x);
  return cubic(j, x);
}

// Plain subdivision on the half-line with the boundary at 0: p'(0) = p(0) and
// p'(r) = sum_c mask[r - 2c] p(c) for r >= 1 (mask indices -2..2).
std::map<long, Q> half_line_step(const std::map<long, Q>& p, const std::vector<Q>& mask) {
  std::map<long, Q> out;
  long last = p.rbegin()->first;
  for (long r = 0; r <= 2 * last + 2; ++r) {
    Q v = 0;
    if (r == 0) {
      v = p.count(0) ? p.at(0) : Q(0);
    } else {
      for (const auto& [c, pc] : p) {
        const long m = r - 2 * c;
        if (m >= -2 && m <= 2) v += mask[static_cast<std::size_t>(m + 2)] * pc;
      }
    }
    out[r] = v;
  }
  return out;
}

}  // namespace

TEST_CASE("bspline3-boundary equals the cubic B-spline with OpenSubdiv's phantom point, both routes, n = 1..24") {
  const sg::CurveScheme s = sg::load_curve_scheme("bspline3-boundary");
  for (long n = 1; n <= 24; ++n) {
    const sg::CurveSolution sol = sg::solve_by_residues(s, n);
    REQUIRE(sg::solve_by_eigenvector(s, n) == sol);
    for (long j = -6; j <= 6; ++j)
      for (long k = (j - 3) * n; k <= (j + 3) * n; ++k) {
        INFO("n = " << n << " control " << j << " x = " << Q(k, n).str());
        REQUIRE(basis(s, sol, j, k) == phantom_basis(j, Q(k, n)));
      }
  }
}

TEST_CASE("nonpoly-curve-boundary equals plain subdivision of the half-line and its limit, n = 2^L") {
  const sg::CurveScheme s = sg::load_curve_scheme("nonpoly-curve-boundary");
  const std::vector<Q> mask{Q(1, 6), Q(1, 2), Q(2, 3), Q(1, 2), Q(1, 6)};
  // Away from the boundary point a fine vertex and its two neighbours are
  // refined by the uniform rules, so its limit is the uniform limit stencil;
  // the boundary point never moves.
  const std::map<long, Q> limit = independent::limit_stencil(2, -2, mask, -1, 1);
  CHECK(limit.at(-1) == Q(1, 5));
  for (int levels = 1; levels <= 5; ++levels) {
    const long n = 1L << levels;
    const sg::CurveSolution sol = sg::solve_by_residues(s, n);
    for (long j = 0; j <= 4; ++j) {
      std::map<long, Q> p;
      for (long c = 0; c <= j + 3; ++c) p[c] = c == j ? 1 : 0;
      for (int l = 0; l < levels; ++l) p = half_line_step(p, mask);
      for (long k = 0; k <= (j + 2) * n; ++k) {
        const Q expected = k == 0 ? p.at(0) : limit.at(-1) * p.at(k - 1) + limit.at(0) * p.at(k) + limit.at(1) * p.at(k + 1);
        INFO("n = " << n << " control " << j << " x = " << Q(k, n).str());
        REQUIRE(basis(s, sol, j, k) == expected);
        // The two sides are decoupled: control j's mirror image on x <= 0.
        REQUIRE(basis(s, sol, -j, -k) == expected);
      }
    }
  }
}

TEST_CASE("the boundary curves are their regular curves with the boundary point held: same mask, three columns") {
  for (const auto& [boundary, regular] : {std::pair{"bspline3-boundary", "bspline3"}, {"nonpoly-curve-boundary", "nonpoly-curve"}}) {
    const sg::CurveScheme b = sg::load_curve_scheme(boundary), r = sg::load_curve_scheme(regular);
    INFO(boundary);
    REQUIRE(b.types.size() == 5);  // left, right, columns -1, 0, 1
    for (std::size_t h : {0u, 1u}) {
      REQUIRE(b.types[h].terms.size() == r.types[0].terms.size());
      for (std::size_t i = 0; i < r.types[0].terms.size(); ++i) {
        CHECK(b.types[h].terms[i].shift == r.types[0].terms[i].shift);
        CHECK(b.types[h].terms[i].coeff == r.types[0].terms[i].coeff);
      }
    }
    // The boundary basis interpolates: phi_0(0) = 1 and every other basis is 0 there.
    const sg::CurveSolution sol = sg::solve_by_residues(b, 3);
    for (long j = -3; j <= 3; ++j) CHECK(basis(b, sol, j, 0) == (j == 0 ? 1 : 0));
  }
}
