// The paper's non-uniform cubic B-spline against Cox-de Boor on its knot vector.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "curve/curve_scheme_loader.hpp"
#include "curve/curve_table_json.hpp"
#include "curve/curve_table_verify.hpp"
#include "curve/eigen_solver.hpp"
#include "curve/generate_curve.hpp"
#include "curve/linear_at_zero.hpp"
#include "curve/residue_solver.hpp"
#include "cli.hpp"
#include "independent.hpp"

using independent::Q;

TEST_CASE("nubspline3, from knots and from explicit columns, equals the non-uniform cubic B-spline basis after "
          "reparameterisation, n = 1..24") {
  for (const std::string name : {"nubspline3", "nubspline3-columns"}) {
  const sg::CurveScheme s = sg::load_curve_scheme(name);
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
        INFO(name << " n = " << n << " control " << j << " x = " << x.str());
        REQUIRE(sol.types[type].at(k - j * n) == independent::cox_de_boor(knot, j - 2, 3, t_of(x)));
      }
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

TEST_CASE("column schemes are validated: contiguous special columns, uniform columns reaching only uniform points") {
  const auto dir = scratch_dir("columns");
  auto scheme_with = [&](const std::string& name, const std::string& columns) {
    const auto path = dir / (name + ".json");
    std::ofstream(path) << R"({"format": "stencilgen-scheme", "version": 1, "name": ")" << name
                        << R"(", "type": "curve-columns", "arity": 2, "mask": {"first": -2, "coefficients": ["1/8", "1/2", "3/4", "1/2", "1/8"]}, "special_columns": [)"
                        << columns << "]}";
    return path.string();
  };
  const std::string col = R"("first": -2, "coefficients": ["1/8", "1/2", "3/4", "1/2", "1/8"]})";
  // Uniform columns written out as special ones: the basis is still the uniform cubic B-spline.
  const sg::CurveScheme plain = sg::load_curve_scheme(scheme_with("plain", R"({"index": -1, "first": -4, "coefficients": ["1/8", "1/2", "3/4", "1/2", "1/8"]}, {"index": 0, )" + col + R"(, {"index": 1, "first": 0, "coefficients": ["1/8", "1/2", "3/4", "1/2", "1/8"]})"));
  const sg::CurveSolution sol = sg::solve_by_residues(plain, 5);
  auto knot = [](long i) { return Q(i - 2); };
  for (std::size_t h = 0; h < plain.types.size(); ++h)
    for (long k = -15; k <= 15; ++k) REQUIRE(sol.types[h].at(k) == independent::cox_de_boor(knot, 0, 3, Q(k, 5)));
  CHECK_THROWS_WITH(sg::load_curve_scheme(scheme_with("gap", R"({"index": -1, "first": -4, "coefficients": ["1"]}, {"index": 1, "first": 0, "coefficients": ["1"]})")),
                    Catch::Contains("contiguous"));
  CHECK_THROWS_WITH(sg::load_curve_scheme(scheme_with("narrow", R"({"index": 0, )" + col)),
                    Catch::Contains("list more columns as special"));
  CHECK_THROWS_WITH(sg::load_curve_scheme(scheme_with("twice", R"({"index": 0, )" + col + R"(, {"index": 0, )" + col)),
                    Catch::Contains("listed twice"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("nubspline3's first derivative in x equals Cox-de Boor's derivative times dt/dx, from the right at 0, "
          "n = 1..24") {
  for (const std::string name : {"nubspline3", "nubspline3-columns"}) {
    const sg::CurveScheme s = sg::load_curve_scheme(name);
    auto knot = [](long i) { return i < 0 ? Q(2 * i) : Q(i); };
    auto t_of = [](const Q& x) { return x < 0 ? Q(2 * x) : x; };
    std::vector<long> rates(24);
    for (long n = 1; n <= 24; ++n) rates[static_cast<std::size_t>(n - 1)] = n;
    const auto tables = sg::generate_curve_tables(s, rates, sg::RouteChoice::Residue, {});
    for (const sg::CurveTable& t : tables) {
      REQUIRE(t.derivative_orders == 1);
      CHECK(t.derivatives_stop.find("2 times that from the left") != std::string::npos);
      const long n = t.n;
      for (long j = -7; j <= 7; ++j) {
        std::size_t type = s.types.size();
        for (std::size_t h = 0; h < s.types.size(); ++h)
          if (s.types[h].placed_at(j)) type = h;
        REQUIRE(type < s.types.size());
        const auto& d = t.functions[type].derivatives.at(0);
        for (long k = (j - 3) * n; k <= (j + 3) * n; ++k) {
          const Q x(k, n);
          // Cox-de Boor's intervals are closed on the left: at t = 0 its
          // derivative is the one from the right, where dt/dx = 1.
          const Q expected = independent::cox_de_boor_derivative(knot, j - 2, 3, t_of(x), 1) * (x < 0 ? Q(2) : Q(1));
          const auto it = d.find(k - j * n);
          INFO(name << " n = " << n << " control " << j << " x = " << x.str());
          REQUIRE((it == d.end() ? Q(0) : it->second) == expected);
        }
      }
    }
  }
}

TEST_CASE("verify checks nubspline3's derivative: a changed value, also at 0 where the relation alone is singular, fails") {
  const sg::CurveScheme s = sg::load_curve_scheme("nubspline3");
  const sg::CurveTable t = sg::generate_curve_tables(s, {3}, sg::RouteChoice::Both, {})[0];
  REQUIRE(sg::verify_curve_table(t, s).empty());
  // c0 (the column at 0) scaled at x = 0 together with c-1 and c1 along the
  // eigenvector: the relation there still holds, the slope does not.
  sg::CurveTable scaled = t;
  for (auto& f : scaled.functions)
    if (f.placement == sg::Placement::Single) {
      const long k = -f.position * t.n;
      if (f.derivatives[0].count(k)) f.derivatives[0][k] *= 2;
    }
  const auto failures = sg::verify_curve_table(scaled, s);
  REQUIRE_FALSE(failures.empty());
  sg::CurveTable changed = t;
  changed.functions[2].derivatives[0].begin()->second += sg::Rational(1, 1000);
  CHECK_FALSE(sg::verify_curve_table(changed, s).empty());
  // The JSON keeps the derivative exactly.
  const sg::CurveTable back = sg::curve_table_from_json(sg::curve_table_to_json(t), "nub-n3.json");
  CHECK(back.functions[2].derivatives == t.functions[2].derivatives);
}

TEST_CASE("nubspline3's linear function at 0 is t itself: slope 1 right of 0, 2 left of it, checked on a grid prime to 2") {
  for (const std::string name : {"nubspline3", "nubspline3-columns"}) {
    const sg::CurveScheme s = sg::load_curve_scheme(name);
    const sg::LinearAtZero l = sg::linear_at_zero(s);
    CHECK(l.left_linear);
    CHECK(l.left_slope == 2);
    // l = sum xi_j B_j is the knot parameter t (2x left of 0, x right), so xi
    // holds the Greville abscissae (t_{j-1} + t_j + t_{j+1}) / 3 in t.
    auto knot = [](long i) { return i < 0 ? Q(2 * i) : Q(i); };
    for (std::size_t i = 0; i < l.functions.size(); ++i) {
      const long j = l.functions[i].j;
      INFO(name << " control " << j);
      CHECK(l.xi[i] == (knot(j - 1) + knot(j) + knot(j + 1)) / 3);
    }
  }
}
