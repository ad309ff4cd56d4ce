// The generator's proof that a curve scheme's scaling function is piecewise
// polynomial (what the runtime evaluates regular Catmull-Clark patches with at
// any parameter): the B-splines of degree 1..7 and Chaikin are found, with the
// degree and pieces of the cardinal B-spline by Cox-de Boor, exactly; the
// non-polynomial schemes are not.
#include <catch2/catch.hpp>

#include "curve/curve_scheme_loader.hpp"
#include "curve/polynomial_pieces.hpp"
#include "independent.hpp"

using independent::Q;

TEST_CASE("B-spline scaling functions are proved piecewise polynomial, with Cox-de Boor's pieces", "[curve][polynomial]") {
  const std::pair<const char*, int> splines[] = {{"bspline1", 1}, {"bspline2", 2}, {"bspline3", 3}, {"bspline4", 4},
                                                 {"bspline5", 5}, {"bspline6", 6}, {"bspline7", 7}, {"chaikin", 2}};
  for (const auto& [name, degree] : splines) {
    const sg::CurveScheme scheme = sg::load_curve_scheme(name);
    const auto pieces = sg::polynomial_pieces(scheme);
    INFO(name);
    REQUIRE(pieces);
    REQUIRE(pieces->degree == degree);
    // phi is the cardinal B-spline on the integer knots starting at its support's left end.
    const long lo = sg::floor_to_long(scheme.types[0].support_lo);
    const auto knot = [](long i) { return Q(i); };
    for (long m = lo - 1; m <= lo + degree + 1; ++m)
      for (int k = 0; k <= 7; ++k) {
        const Q t(k, 7);
        INFO("piece " << m << " at t = " << k << "/7");
        REQUIRE(pieces->at(m, t) == independent::cox_de_boor(knot, lo, degree, Q(m) + t));
      }
  }
}

TEST_CASE("non-polynomial and ternary schemes have no polynomial pieces", "[curve][polynomial]") {
  for (const char* name : {"nonpoly-curve", "fourpoint", "dd6", "ternary-bspline3", "ternary-dd4"}) {
    INFO(name);
    CHECK_FALSE(sg::polynomial_pieces(sg::load_curve_scheme(name)));
  }
}
