// Derivative tables of curve schemes (stencilgen's difference-scheme route,
// both solvers compared, verified) against independent computations:
// Cox-de Boor's derivative formula for B-splines, plain subdivision of a delta
// followed by differencing and the derivative scheme's limit stencil (a left
// eigenvector from separate Gauss-Jordan code), and difference quotients of
// the exact values at finer rates.
#include <catch2/catch.hpp>

#include <cmath>
#include <tbb/task_arena.h>

#include "curve/curve_scheme_loader.hpp"
#include "curve/curve_table_json.hpp"
#include "curve/curve_table_verify.hpp"
#include "curve/generate_curve.hpp"
#include "curve_masks.hpp"
#include "independent.hpp"

using independent::Q;

namespace {

std::vector<long> rates_up_to(long n_max) {
  std::vector<long> r;
  for (long n = 1; n <= n_max; ++n) r.push_back(n);
  return r;
}

Q at(const std::map<long, sg::Rational>& m, long k) {
  const auto it = m.find(k);
  return it == m.end() ? Q(0) : it->second;
}

// t(z) = a s(z) (1 - z) / (1 - z^a): the mask of the derivative scheme, by long
// division written here (coefficients from `first`).
independent::UniformMask derivative_mask(const independent::UniformMask& s) {
  const long a = s.arity;
  std::vector<Q> num(s.coeffs.size() + 1, 0);  // a s(z) (1 - z), from s.first
  for (std::size_t i = 0; i < s.coeffs.size(); ++i) {
    num[i] += a * s.coeffs[i];
    num[i + 1] -= a * s.coeffs[i];
  }
  std::vector<Q> q(num.size() - static_cast<std::size_t>(a), 0);
  for (std::size_t i = 0; i < q.size(); ++i) {  // num = q (1 - z^a): q_i = num_i + q_(i-a)
    q[i] = num[i] + (i >= static_cast<std::size_t>(a) ? q[i - static_cast<std::size_t>(a)] : Q(0));
  }
  for (std::size_t i = q.size(); i < num.size(); ++i)  // the remainder must vanish
    REQUIRE(num[i] == -(i >= static_cast<std::size_t>(a) ? q[i - static_cast<std::size_t>(a)] : Q(0)));
  return {a, s.first, q};
}

// a^j (p_k - p_(k-1)): the control points of the derivative scheme at level j.
independent::Sequence scaled_differences(const independent::Sequence& p, long scale) {
  independent::Sequence d;
  for (const auto& [k, v] : p) {
    d[k] += scale * v;
    d[k + 1] -= scale * v;
  }
  return d;
}

Q apply_limit(const std::map<long, Q>& limit, const independent::Sequence& c, long i) {
  Q value = 0;
  for (const auto& [offset, weight] : limit) {
    const auto it = c.find(i + offset);
    if (it != c.end()) value += weight * it->second;
  }
  return value;
}

void check_bspline(const std::string& name, int degree, long n_max) {
  const sg::CurveScheme s = sg::load_curve_scheme(name);
  const auto tables = sg::generate_curve_tables(s, rates_up_to(n_max), sg::RouteChoice::Both, {});
  const long first = s.types[0].terms.front().shift;
  const Q start = Q(first, s.arity - 1);
  auto knot = [&](long i) { return start + i; };
  const int orders = degree >= 3 ? 2 : degree == 2 ? 1 : 0;
  for (const sg::CurveTable& t : tables) {
    INFO(name << " n = " << t.n);
    REQUIRE(t.derivative_orders == orders);
    REQUIRE(t.functions[0].derivatives.size() == static_cast<std::size_t>(orders));
    for (int r = 1; r <= orders; ++r)
      for (long k = -10 * t.n; k <= 10 * t.n; ++k) {
        const Q x(k, t.n);
        INFO("order " << r << " x = " << x.str());
        REQUIRE(at(t.functions[0].derivatives[static_cast<std::size_t>(r - 1)], k) ==
                independent::cox_de_boor_derivative(knot, 0, degree, x, r));
      }
  }
}

// At n = a^j: phi^(r)(i / a^j) from j steps of plain subdivision of a delta,
// r scaled differences (each followed by the next derivative scheme) and the
// limit stencil of the order-r derivative scheme.
void check_against_difference_subdivision(const std::string& name, int orders, int max_steps) {
  const independent::UniformMask m = independent::mask_of(name);
  std::vector<independent::UniformMask> masks{m};
  for (int r = 1; r <= orders; ++r) masks.push_back(derivative_mask(masks.back()));
  std::vector<std::map<long, Q>> limits;
  for (const auto& d : masks) {
    const long reach = static_cast<long>(d.coeffs.size());
    limits.push_back(independent::limit_stencil(d.arity, d.first, d.coeffs, -reach, reach));
  }
  const sg::CurveScheme s = sg::load_curve_scheme(name);
  std::vector<long> rates;
  for (long n = m.arity, j = 1; j <= max_steps; ++j, n *= m.arity) rates.push_back(n);
  const auto tables = sg::generate_curve_tables(s, rates, sg::RouteChoice::Both, {});
  independent::Sequence p{{0, Q(1)}};
  for (int j = 1; j <= max_steps; ++j) {
    p = independent::subdivide(p, m.arity, m.first, m.coeffs);
    const sg::CurveTable& t = tables[static_cast<std::size_t>(j - 1)];
    REQUIRE(t.derivative_orders == orders);
    independent::Sequence c = p;
    for (int r = 1; r <= orders; ++r) {
      c = scaled_differences(c, t.n);
      const long reach = static_cast<long>(masks[static_cast<std::size_t>(r)].coeffs.size());
      for (long i = c.begin()->first - reach; i <= c.rbegin()->first + reach; ++i) {
        INFO(name << " order " << r << " n = " << t.n << " x = " << Q(i, t.n).str());
        REQUIRE(at(t.functions[0].derivatives[static_cast<std::size_t>(r - 1)], i) ==
                apply_limit(limits[static_cast<std::size_t>(r)], c, i));
      }
    }
  }
}

}  // namespace

TEST_CASE("B-spline derivatives equal Cox-de Boor's exactly, degrees 1..7, n = 1..24") {
  for (int d = 1; d <= 7; ++d) check_bspline("bspline" + std::to_string(d), d, 24);
  check_bspline("chaikin", 2, 24);
  check_bspline("ternary-bspline3", 3, 12);
}

TEST_CASE("interpolatory and nonpoly derivatives at n = a^j equal the difference scheme's subdivision of a delta") {
  check_against_difference_subdivision("fourpoint", 1, 6);
  check_against_difference_subdivision("dd6", 2, 5);
  check_against_difference_subdivision("ternary-dd4", 1, 3);
  check_against_difference_subdivision("nonpoly-curve", 1, 6);
  check_against_difference_subdivision("bspline3", 2, 5);
  check_against_difference_subdivision("ternary-bspline3", 2, 3);
}

TEST_CASE("central difference quotients of exact values at rate k n converge to the derivative") {
  for (const std::string name : {"fourpoint", "nonpoly-curve", "dd6"}) {
    const sg::CurveScheme s = sg::load_curve_scheme(name);
    const long n = 3;
    const std::vector<long> ks{1, 2, 4, 8, 16};
    std::vector<long> rates{n};
    for (long k : ks) rates.push_back(2 * k * n);
    std::sort(rates.begin(), rates.end());
    rates.erase(std::unique(rates.begin(), rates.end()), rates.end());
    const auto tables = sg::generate_curve_tables(s, rates, sg::RouteChoice::Residue, {});
    auto table = [&](long rate) -> const sg::CurveTable& {
      for (const auto& t : tables)
        if (t.n == rate) return t;
      throw std::runtime_error("missing rate");
    };
    const auto& exact = table(n).functions[0].derivatives.at(0);
    std::vector<double> errors;
    for (long k : ks) {  // step h = 1/(2 k n): quotient (phi(x + h) - phi(x - h)) / (2h) on the rate-2kn grid
      const auto& fine = table(2 * k * n).functions[0].values;
      double worst = 0;
      for (long i = -4 * n; i <= 4 * n; ++i) {
        const Q quotient = (at(fine, 2 * k * i + 1) - at(fine, 2 * k * i - 1)) * Q(2 * k * n, 2);
        worst = std::max(worst, std::abs(sg::to_double(quotient - at(exact, i))));
      }
      errors.push_back(worst);
    }
    INFO(name << ": errors at k = 1, 2, 4, 8, 16: " << errors[0] << " " << errors[1] << " " << errors[2] << " "
              << errors[3] << " " << errors[4]);
    for (std::size_t i = 1; i < errors.size(); ++i) REQUIRE(errors[i] <= errors[i - 1] * 0.75);
    REQUIRE(errors.back() < 0.05 * errors.front());
  }
}

TEST_CASE("schemes without a continuous derivative get value tables and the reason") {
  const auto hat = sg::generate_curve_tables(sg::load_curve_scheme("bspline1"), {4}, sg::RouteChoice::Both, {});
  CHECK(hat[0].derivative_orders == 0);
  CHECK(hat[0].functions[0].derivatives.empty());
  CHECK(hat[0].derivatives_stop.find("C1") != std::string::npos);
  const auto nonpoly = sg::generate_curve_tables(sg::load_curve_scheme("nonpoly-curve"), {4}, sg::RouteChoice::Both, {});
  CHECK(nonpoly[0].derivative_orders == 1);
  CHECK(nonpoly[0].derivatives_stop.find("not C2") != std::string::npos);
  const auto nub = sg::generate_curve_tables(sg::load_curve_scheme("nubspline3"), {4}, sg::RouteChoice::Both, {});
  CHECK(nub[0].derivative_orders == 1);
  CHECK(nub[0].derivatives_stop.find("second derivatives are not generated for non-uniform schemes") != std::string::npos);
}

TEST_CASE("verify checks the derivatives, and the JSON keeps them exactly") {
  const sg::CurveScheme s = sg::load_curve_scheme("dd6");
  const sg::CurveTable t = sg::generate_curve_tables(s, {5}, sg::RouteChoice::Both, {})[0];
  const sg::CurveTable back = sg::curve_table_from_json(sg::curve_table_to_json(t), "dd6-n5.json");
  REQUIRE(back.derivative_orders == 2);
  REQUIRE(back.functions[0].derivatives == t.functions[0].derivatives);
  REQUIRE(sg::verify_curve_table(back, s).empty());

  for (std::size_t order = 0; order < 2; ++order) {
    sg::CurveTable changed = back;
    auto& d = changed.functions[0].derivatives[order];
    d.begin()->second += sg::Rational(1, 1000000);
    INFO("order " << order + 1);
    CHECK_FALSE(sg::verify_curve_table(changed, s).empty());
  }
  // A second derivative claimed for a scheme that is only C1 (four-point).
  const sg::CurveScheme four = sg::load_curve_scheme("fourpoint");
  sg::CurveTable more = sg::generate_curve_tables(four, {5}, sg::RouteChoice::Both, {})[0];
  REQUIRE(sg::verify_curve_table(more, four).empty());
  more.derivative_orders = 2;
  more.functions[0].derivatives.push_back(more.functions[0].derivatives[0]);
  CHECK_FALSE(sg::verify_curve_table(more, four).empty());
  // A scaled copy still satisfies the (homogeneous) scaled relation; only the moments catch it.
  sg::CurveTable scaled = back;
  for (auto& [k, v] : scaled.functions[0].derivatives[0]) v *= 2;
  CHECK_FALSE(sg::verify_curve_table(scaled, s).empty());

  std::string v1 = sg::curve_table_to_json(t);
  v1.replace(v1.find("\"version\": 2"), 12, "\"version\": 1");
  try {
    sg::curve_table_from_json(v1, "old.json");
    FAIL("a version 1 table loaded");
  } catch (const sg::Error& e) {
    CHECK(std::string(e.what()).find("regenerate") != std::string::npos);
  }
}

TEST_CASE("a curve run stops once its exact tables pass the size limit, largest rates first", "[limits]") {
  const sg::CurveScheme s = sg::load_curve_scheme("fourpoint");
  // exact_digits against the digits of the JSON's exact strings ("p/q", or "p" with denominator 1).
  const sg::CurveTable t = sg::generate_curve_tables(s, {7}, sg::RouteChoice::Residue)[0];
  const nlohmann::json doc = nlohmann::json::parse(sg::curve_table_to_json(t));
  std::uint64_t counted = 0, numbers = 0;
  auto count = [&](const nlohmann::json& values) {
    for (const auto& [key, value] : values.items()) {
      const std::string text = value.get<std::string>();
      for (char c : text) counted += std::isdigit(static_cast<unsigned char>(c)) ? 1 : 0;
      if (text.find('/') == std::string::npos) ++counted;  // the denominator 1
      ++numbers;
    }
  };
  for (const auto& f : doc["functions"]) {
    count(f["values"]);
    for (const auto& d : f["derivatives"]) count(d["values"]);
  }
  REQUIRE(numbers > 0);
  // GMP's digit count is exact or one too many, for numerator and denominator.
  CHECK(sg::exact_digits(t) >= counted);
  CHECK(sg::exact_digits(t) <= counted + 2 * numbers);
  // With a limit a few small tables pass, the run stops naming it, and the rates done first were the largest.
  std::vector<long> rates;
  for (long n = 1; n <= 40; ++n) rates.push_back(n);
  std::vector<std::string> lines;
  // Room for n = 40 and 39, not for a third table as well.
  const auto largest = sg::generate_curve_tables(s, {39, 40}, sg::RouteChoice::Residue);
  const std::uint64_t limit = sg::exact_digits(largest[0]) + sg::exact_digits(largest[1]) + 1;
  CHECK_THROWS_WITH(sg::generate_curve_tables(s, rates, sg::RouteChoice::Residue, [&](const std::string& l) { lines.push_back(l); }, limit),
                    Catch::Contains("above the limit of " + std::to_string(limit) + " for one run"));
  CHECK(lines.size() < 10);  // the first line names the derivatives, then a few rates
  // The first rate to finish is one of those the workers took first: 40, 39, ... one per worker.
  REQUIRE(lines.size() >= 2);
  INFO(lines[1]);
  const std::size_t at = lines[1].find("n = ");
  REQUIRE(at != std::string::npos);
  CHECK(std::stol(lines[1].substr(at + 4)) > 40 - std::max(1, tbb::this_task_arena::max_concurrency()));
  for (std::size_t k = 1; k < lines.size(); ++k) CHECK(lines[k].find("n = 1 ") == std::string::npos);
  // Within the default limit the same rates all pass.
  CHECK(sg::generate_curve_tables(s, rates, sg::RouteChoice::Residue).size() == rates.size());
}
