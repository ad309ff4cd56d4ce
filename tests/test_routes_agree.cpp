// The residue-class route and the eigenvector route are independent; they must
// give identical rationals, and every table must pass exact verification.
#include <catch2/catch.hpp>

#include "curve/curve_scheme_loader.hpp"
#include "curve/curve_table.hpp"
#include "curve/curve_table_verify.hpp"
#include "curve/eigen_solver.hpp"
#include "curve/residue_solver.hpp"

TEST_CASE("both solvers give identical rationals for every shipped scheme, n = 1..24, and tables verify") {
  const auto names = sg::available_schemes(sg::default_schemes_dir(), sg::SchemeFamily::Curve);
  REQUIRE(names.size() >= 14);
  for (const std::string& name : names) {
    const sg::CurveScheme s = sg::load_curve_scheme(name);
    for (long n = 1; n <= 24; ++n) {
      INFO(name << " n = " << n);
      const sg::CurveSolution a = sg::solve_by_residues(s, n);
      const sg::CurveSolution b = sg::solve_by_eigenvector(s, n);
      REQUIRE(a == b);
      CHECK(sg::verify_curve_table(sg::make_table(s, a), s).empty());
    }
  }
}

TEST_CASE("interpolatory schemes give phi(k) = delta(k)") {
  for (const std::string name : {"fourpoint", "dd6", "ternary-dd4"}) {
    const sg::CurveScheme s = sg::load_curve_scheme(name);
    for (long n = 1; n <= 24; ++n) {
      const sg::CurveSolution sol = sg::solve_by_residues(s, n);
      for (long k = -6; k <= 6; ++k) {
        INFO(name << " n = " << n << " k = " << k);
        REQUIRE(sol.types[0].at(k * n) == (k == 0 ? 1 : 0));
      }
    }
  }
}

TEST_CASE("verification catches a wrong value, a wrong hash and a wrong support") {
  const sg::CurveScheme s = sg::load_curve_scheme("fourpoint");
  const sg::CurveTable good = sg::make_table(s, sg::solve_by_residues(s, 3));
  REQUIRE(sg::verify_curve_table(good, s).empty());

  sg::CurveTable bad_value = good;
  bad_value.functions[0].values.at(1) += sg::Rational(1, 5589);
  CHECK_FALSE(sg::verify_curve_table(bad_value, s).empty());

  sg::CurveTable bad_hash = good;
  bad_hash.scheme_hash = "0000000000000000";
  CHECK_FALSE(sg::verify_curve_table(bad_hash, s).empty());

  sg::CurveTable outside = good;
  outside.functions[0].values[9] = 1;  // x = 3 is on the support's boundary
  CHECK_FALSE(sg::verify_curve_table(outside, s).empty());

  // The same table checked against another tension w is rejected by identity and by relations.
  const sg::CurveScheme other = sg::load_curve_scheme("fourpoint", {"w=1/32"});
  CHECK_FALSE(sg::verify_curve_table(good, other).empty());
}

TEST_CASE("the four-point tension parameter changes the values as the mask says") {
  const sg::CurveScheme s = sg::load_curve_scheme("fourpoint", {"w=1/32"});
  CHECK(s.parameters.at("w") == sg::Rational(1, 32));
  const sg::CurveSolution sol = sg::solve_by_residues(s, 2);
  // At dyadic points the value is the mask entry: phi(1/2) = 1/2 + w, phi(3/2) = -w.
  CHECK(sol.types[0].at(1) == sg::Rational(17, 32));
  CHECK(sol.types[0].at(3) == sg::Rational(-1, 32));
  CHECK(sg::solve_by_eigenvector(s, 5) == sg::solve_by_residues(s, 5));
}
