// The paper's non-uniform cubic B-spline against Cox-de Boor on its knot vector.
#include <catch2/catch.hpp>

#include "eigen_solver.hpp"
#include "independent.hpp"
#include "residue_solver.hpp"
#include "scheme_loader.hpp"

using independent::Q;

TEST_CASE("nubspline3 equals the non-uniform cubic B-spline basis after reparameterisation, n = 1..24") {
  const sg::CurveScheme s = sg::load_curve_scheme("nubspline3");
  REQUIRE(s.types.size() == 5);  // left, right and the three special columns of the paper
  auto knot = [](long i) { return i < 0 ? Q(2 * i) : Q(i); };
  auto t_of = [](const Q& x) { return x < 0 ? Q(2 * x) : x; };
  for (long n = 1; n <= 24; ++n) {
    const sg::CurveSolution sol = sg::solve_by_residues(s, n);
    // Control j owns the cubic B-spline with knots t_{j-2} .. t_{j+2}.
    for (long j = -7; j <= 7; ++j) {
      std::size_t type = s.types.size();
      for (std::size_t h = 0; h < s.types.size(); ++h)
        if (s.types[h].placed_at(j)) type = h;
      REQUIRE(type < s.types.size());
      for (long k = (j - 3) * n; k <= (j + 3) * n; ++k) {
        const Q x(k, n);
        INFO("n = " << n << " control " << j << " x = " << x.str());
        REQUIRE(sol.types[type].at(k - j * n) == independent::cox_de_boor(knot, j - 2, 3, t_of(x)));
      }
    }
  }
}

TEST_CASE("nubspline3 has the paper's five column types with uniform cubic B-spline ends") {
  const sg::CurveScheme s = sg::load_curve_scheme("nubspline3");
  std::vector<long> special;
  for (const auto& t : s.types)
    if (t.placement == sg::Placement::Single) special.push_back(t.position);
  CHECK(special == std::vector<long>{-1, 0, 1});
  // Uniform ends: mask 1/8, 1/2, 3/4, 1/2, 1/8.
  const std::vector<Q> cubic{Q(1, 8), Q(1, 2), Q(3, 4), Q(1, 2), Q(1, 8)};
  for (std::size_t h : {0u, 1u}) {
    REQUIRE(s.types[h].terms.size() == 5);
    for (std::size_t i = 0; i < 5; ++i) CHECK(s.types[h].terms[i].coeff == cubic[i]);
  }
}
