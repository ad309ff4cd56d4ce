// The bivariate solver for triangle schemes (Loop; two steps of sqrt(3)) on
// the triangular lattice, against the paper's Figure 3, plain subdivision of a
// delta followed by the published limit stencils, and the lattice's symmetries.
#include <catch2/catch.hpp>
#include <map>

#include "triangle/bivariate_solver.hpp"
#include "triangle/triangle_masks.hpp"

using sg::Rational;
using Field = std::map<sg::LatticeIndex, Rational>;

namespace {

const sg::BivariateMask& loop() {
  static const sg::BivariateMask m = sg::loop_regular_mask(Rational(3, 8), Rational(1, 8), Rational(5, 8), Rational(1, 16));
  return m;
}
const sg::BivariateMask& sqrt3() {
  // Kobbelt's alpha(v) = (4 - 2 cos(2 pi / v)) / 9 is 1/3 at v = 6.
  static const sg::BivariateMask m = sg::sqrt3_composite_mask(Rational(1, 3));
  return m;
}

// One step of plain subdivision with the mask: c'[m k + i] += s_i c[k].
Field subdivide(const Field& c, const sg::BivariateMask& mask) {
  Field out;
  for (const auto& [k, v] : c)
    for (const auto& [i, s] : mask.coefficients)
      out[{mask.dilation * k.first + i.first, mask.dilation * k.second + i.second}] += s * v;
  return out;
}

// Limit position of a regular vertex, both schemes (Loop 1987; Kobbelt 2000,
// beta = 3 alpha / (1 + 3 alpha) = 1/2 at alpha = 1/3): 1/2 centre, 1/12 each neighbour.
Rational limit_at(const Field& c, long a, long b) {
  auto at = [&](long x, long y) {
    const auto it = c.find({x, y});
    return it == c.end() ? Rational(0) : it->second;
  };
  Rational v = at(a, b) / 2;
  for (const auto& d : sg::kTriangleNeighbours) v += at(a + d[0], b + d[1]) / 12;
  return v;
}

}  // namespace

TEST_CASE("the regular sqrt(3) stencil at an edge midpoint is the paper's Figure 3 (sum 2256)", "[triangle]") {
  const sg::BivariateSolution s = sg::solve_bivariate(sqrt3(), 2);
  // Weight of lattice point j at x = (1/2, 0): phi(x - j) = value at grid index (1 - 2 j_a, -2 j_b).
  std::map<sg::LatticeIndex, long> expected = {
      {{0, 0}, 740}, {{1, 0}, 740},                                  // the edge's ends
      {{1, 1}, 312}, {{0, -1}, 312},                                 // the two opposite vertices
      {{-1, 0}, 18}, {{2, 0}, 18},                                   // along the edge's line
      {{0, 1}, 28},  {{2, 1}, 28},  {{-1, -1}, 28}, {{1, -1}, 28},   // beside the opposite vertices
      {{1, 2}, 1},   {{2, 2}, 1},   {{-1, -2}, 1},  {{0, -2}, 1}};   // beyond them
  long total = 0;
  for (long b = -4; b <= 4; ++b)
    for (long a = -4; a <= 5; ++a) {
      const Rational w = s.at(1 - 2 * a, -2 * b) * 2256;
      const auto it = expected.find({a, b});
      INFO("lattice point (" << a << "," << b << ")");
      REQUIRE(w == (it == expected.end() ? 0 : it->second));
      total += it == expected.end() ? 0 : it->second;
    }
  REQUIRE(total == 2256);
}

TEST_CASE("bivariate values satisfy every scaling relation and partition of unity", "[triangle]") {
  for (const auto* mask : {&loop(), &sqrt3()})
    for (long n = 1; n <= 12; ++n) {
      const sg::BivariateSolution s = sg::solve_bivariate(*mask, n);
      const long m = mask->dilation;
      std::map<sg::LatticeIndex, Rational> per_class;
      for (const auto& [k, v] : s.values) {
        Rational rhs = 0;
        for (const auto& [i, c] : mask->coefficients) rhs += c * s.at(m * k.first - n * i.first, m * k.second - n * i.second);
        INFO("m = " << m << " n = " << n << " k = (" << k.first << "," << k.second << ")");
        REQUIRE(v == rhs);
        per_class[{((k.first % n) + n) % n, ((k.second % n) + n) % n}] += v;
      }
      REQUIRE(per_class.size() == static_cast<std::size_t>(n * n));
      for (const auto& [r, sum] : per_class) REQUIRE(sum == 1);
    }
}

TEST_CASE("bivariate values have the triangular lattice's twelve symmetries", "[triangle]") {
  for (const auto* mask : {&loop(), &sqrt3()})
    for (long n : {1L, 4L, 5L, 9L}) {
      const sg::BivariateSolution s = sg::solve_bivariate(*mask, n);
      for (const auto& [k, v] : s.values) {
        const auto [a, b] = k;
        // 60 degree rotation (a, b) -> (a - b, a) and the reflection (a, b) -> (b, a).
        INFO("m = " << mask->dilation << " n = " << n << " (" << a << "," << b << ")");
        REQUIRE(s.at(a - b, a) == v);
        REQUIRE(s.at(b, a) == v);
      }
    }
}

TEST_CASE("at n = 2^j (Loop) and 3^j (sqrt(3)) values equal subdivision of a delta then the limit stencil", "[triangle]") {
  struct Case {
    const sg::BivariateMask* mask;
    int steps;
  };
  for (const Case& c : {Case{&loop(), 1}, Case{&loop(), 2}, Case{&loop(), 3}, Case{&sqrt3(), 1}, Case{&sqrt3(), 2}}) {
    Field f{{{0, 0}, Rational(1)}};
    long n = 1;
    for (int j = 0; j < c.steps; ++j) {
      f = subdivide(f, *c.mask);
      n *= c.mask->dilation;
    }
    const sg::BivariateSolution s = sg::solve_bivariate(*c.mask, n);
    for (long a = -3 * n; a <= 3 * n; ++a)
      for (long b = -3 * n; b <= 3 * n; ++b) {
        INFO("m = " << c.mask->dilation << " n = " << n << " (" << a << "," << b << ")");
        REQUIRE(s.at(a, b) == limit_at(f, a, b));
      }
  }
}

#include "algebra/expression.hpp"
#include "base/error.hpp"

TEST_CASE("cos2pi is exact where it is rational and refused where it is not", "[triangle]") {
  const sg::Bindings v6{{"v", Rational(6)}}, v3{{"v", Rational(3)}}, v5{{"v", Rational(5)}};
  // Kobbelt's relaxation weight and Loop's beta at the rational valences.
  REQUIRE(sg::evaluate_expression("(4 - 2*cos2pi(1/v))/9", v6) == Rational(1, 3));
  REQUIRE(sg::evaluate_expression("(4 - 2*cos2pi(1/v))/9", v3) == Rational(5, 9));
  REQUIRE(sg::evaluate_expression("(5/8 - (3/8 + cos2pi(1/v)/4)^2)/v", v6) == Rational(1, 16));
  REQUIRE(sg::evaluate_expression("cos2pi(1/4) + cos2pi(3/2) + cos2pi(-1/3)", {}) == Rational(-3, 2));
  REQUIRE_THROWS_WITH(sg::evaluate_expression("cos2pi(1/v)", v5), Catch::Contains("cos2pi(1/5)") && Catch::Contains("irrational"));
}

// The gradient solver (derivative stencils of the regular triangle patch).
namespace {

// phi at the grid point k / n of a solution on that grid.
Rational value_at(const sg::BivariateSolution& s, long a, long b) { return s.at(a, b); }

}  // namespace

TEST_CASE("Loop's gradient equals the exact one-sided derivative of its quartic pieces at every grid point", "[triangle]") {
  // Loop's regular basis is a quartic box spline on the three-direction mesh.
  // From a point k/n, the segment [k/n, k/n + e/n] along e_a or e_b crosses no
  // mesh line inside, so the 5 values at spacing h = 1/(4n) (exact, on the grid
  // 4n) fix the quartic there and f'(0) = (-25 f0 + 48 f1 - 36 f2 + 16 f3 - 3 f4) / (12 h).
  for (long n = 1; n <= 5; ++n) {
    const sg::BivariateGradient g = sg::solve_bivariate_gradient(loop(), n);
    const sg::BivariateSolution fine = sg::solve_bivariate(loop(), 4 * n);
    long checked = 0;
    for (long a = -3 * n; a <= 3 * n; ++a)
      for (long b = -3 * n; b <= 3 * n; ++b)
        for (int c = 0; c < 2; ++c) {
          const long da = c == 0 ? 1 : 0, db = c == 1 ? 1 : 0;
          Rational f[5];
          for (long j = 0; j < 5; ++j) f[j] = value_at(fine, 4 * a + j * da, 4 * b + j * db);
          const Rational expected = (-25 * f[0] + 48 * f[1] - 36 * f[2] + 16 * f[3] - 3 * f[4]) * Rational(4 * n, 12);
          INFO("n = " << n << " (" << a << "," << b << ") along " << (c == 0 ? "a" : "b"));
          REQUIRE(g.at(c == 0 ? g.da : g.db, a, b) == expected);
          if (expected != 0) ++checked;
        }
    REQUIRE(checked >= 12 * n * n);  // the support was covered, not just zeros
  }
}

TEST_CASE("sqrt(3)'s gradient is the limit of central differences of exact values at finer rates", "[triangle]") {
  // sqrt(3)'s regular basis is not polynomial: the difference quotients with
  // spacing h = 1/(k n) converge to the derivative as k grows.
  const long n = 2;
  const sg::BivariateGradient g = sg::solve_bivariate_gradient(sqrt3(), n);
  double scale = 0;
  for (const auto& [k, v] : g.da) scale = std::max(scale, std::abs(sg::to_double(v)));
  REQUIRE(scale > 0.1);
  std::vector<double> errors;
  for (long k : {2L, 4L, 8L}) {
    const sg::BivariateSolution fine = sg::solve_bivariate(sqrt3(), k * n);
    double worst = 0;
    for (long a = -3 * n; a <= 3 * n; ++a)
      for (long b = -3 * n; b <= 3 * n; ++b)
        for (int c = 0; c < 2; ++c) {
          const long da = c == 0 ? 1 : 0, db = c == 1 ? 1 : 0;
          const Rational quotient = (fine.at(k * a + da, k * b + db) - fine.at(k * a - da, k * b - db)) * Rational(k * n, 2);
          worst = std::max(worst, std::abs(sg::to_double(quotient - g.at(c == 0 ? g.da : g.db, a, b))));
        }
    errors.push_back(worst);
  }
  INFO("errors at k = 2, 4, 8: " << errors[0] << " " << errors[1] << " " << errors[2]);
  REQUIRE(errors[1] < errors[0] / 2.5);  // sqrt(3) is C2: about 1/4 per halving
  REQUIRE(errors[2] < errors[1] / 2.5);
  REQUIRE(errors[2] < 0.01 * scale);
}

TEST_CASE("the gradient satisfies its scaling relation and has the lattice's symmetries", "[triangle]") {
  for (const auto* mask : {&loop(), &sqrt3()})
    for (long n : {1L, 3L, 4L}) {
      const sg::BivariateGradient g = sg::solve_bivariate_gradient(*mask, n);
      const long m = mask->dilation;
      for (const auto* partial : {&g.da, &g.db})
        for (const auto& [k, v] : *partial) {
          Rational rhs = 0;
          for (const auto& [i, c] : mask->coefficients)
            rhs += c * g.at(*partial, m * k.first - n * i.first, m * k.second - n * i.second);
          INFO("m = " << m << " n = " << n << " k = (" << k.first << "," << k.second << ")");
          REQUIRE(v == m * rhs);
        }
      // The reflection (a, b) -> (b, a) swaps the partials; the point reflection negates them.
      for (const auto& [k, v] : g.da) {
        INFO("m = " << m << " n = " << n << " (" << k.first << "," << k.second << ")");
        REQUIRE(g.at(g.db, k.second, k.first) == v);
        REQUIRE(g.at(g.da, -k.first, -k.second) == -v);
      }
    }
}
