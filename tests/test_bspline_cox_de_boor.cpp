// Uniform B-spline tables against an independent Cox-de Boor evaluation.
#include <catch2/catch.hpp>

#include "curve/curve_scheme_loader.hpp"
#include "curve/residue_solver.hpp"
#include "independent.hpp"

using independent::Q;

namespace {
// phi of a B-spline scheme whose mask starts at `first` is N_{0,d} on knots first, first+1, ...
void check_uniform_bspline(const std::string& name, int degree, long n_max) {
  const sg::CurveScheme s = sg::load_curve_scheme(name);
  REQUIRE(s.is_uniform());
  const long first = s.types[0].terms.front().shift;
  // The mask of a B-spline of arity a spans first .. first + (a-1)(d+1); its phi starts at first/(a-1).
  const Q start = Q(first, s.arity - 1);
  auto knot = [&](long i) { return start + i; };
  for (long n = 1; n <= n_max; ++n) {
    const sg::CurveSolution sol = sg::solve_by_residues(s, n);
    for (long k = -10 * n; k <= 10 * n; ++k) {
      const Q x(k, n);
      INFO(name << " n = " << n << " x = " << x.str());
      REQUIRE(sol.types[0].at(k) == independent::cox_de_boor(knot, 0, degree, x));
    }
  }
}
}  // namespace

TEST_CASE("uniform B-splines of degree 1..7 equal Cox-de Boor exactly, n = 1..24") {
  for (int d = 1; d <= 7; ++d) check_uniform_bspline("bspline" + std::to_string(d), d, 24);
}

TEST_CASE("Chaikin and the ternary cubic B-spline equal Cox-de Boor exactly, n = 1..24") {
  check_uniform_bspline("chaikin", 2, 24);
  check_uniform_bspline("ternary-bspline3", 3, 24);
}
