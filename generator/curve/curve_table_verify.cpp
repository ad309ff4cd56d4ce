#include "curve/curve_table_verify.hpp"

#include "base/error.hpp"
#include "common/hash.hpp"
#include "curve/difference_scheme.hpp"
#include "curve/nonuniform_derivative.hpp"
#include "curve/partition_of_unity.hpp"

namespace sg {

namespace {

Rational at_grid(const std::map<long, Rational>& m, long k) {
  const auto it = m.find(k);
  return it == m.end() ? Rational(0) : it->second;
}

// Derivative values of a uniform table: no more orders than the scheme has (its
// difference schemes), zero outside the support, the scaled scaling relation
//     phi^(r)(k/n) = a^r sum_i s_i phi^(r)((a k - n i)/n)
// at every grid point, and the moments sum_j j^m phi^(r)(x - j) = r! [m == r]
// (m = 0..r, the r-th derivative of the reproduced x^m) at every residue.
void verify_derivatives(const CurveTable& table, const CurveScheme& scheme, std::vector<std::string>& failures) {
  const int orders = static_cast<int>(derivative_schemes(scheme, kMaxDerivativeOrder).schemes.size());
  // Fewer orders than the scheme has are allowed (a table made without them, such
  // as a quad scheme's regular curve); more are not.
  if (table.derivative_orders > orders) {
    failures.push_back("the table has " + std::to_string(table.derivative_orders) +
                       " derivative orders; the scheme has only " + std::to_string(orders));
    return;
  }
  if (table.derivative_orders == 0) return;
  const ScalingType& type = scheme.types[0];
  const CurveTable::Function& f = table.functions[0];
  const long n = table.n, a = scheme.arity;
  const GridRange g = open_support_grid(type, n);
  Rational factorial = 1, power = 1;
  for (int r = 1; r <= table.derivative_orders; ++r) {
    const auto& d = f.derivatives.at(static_cast<std::size_t>(r - 1));
    factorial *= r;
    power *= a;
    const std::string name = "derivative " + std::to_string(r) + " of '" + type.name + "'";
    // The closed support: a derivative may be nonzero at its ends.
    for (const auto& [k, v] : d)
      if (k < g.first - 1 || k > g.last + 1) {
        failures.push_back(name + " is nonzero at x = " + to_string(Rational(k, n)) + ", outside the support");
        return;
      }
    for (long k = g.first - n; k <= g.last + n; ++k) {
      Rational rhs = 0;
      for (const Term& term : type.terms) rhs += term.coeff * at_grid(d, a * k - n * term.shift);
      rhs *= power;
      if (rhs != at_grid(d, k)) {
        failures.push_back("scaling relation of " + name + " fails at x = " + to_string(Rational(k, n)) + ": value " +
                           excerpt(to_string(at_grid(d, k))) + ", relation gives " + excerpt(to_string(rhs)));
        if (failures.size() > 20) return;
      }
    }
    // Control points j with x - j in the support, for x = k0/n in [0, 1).
    const long j_lo = floor_to_long(-type.support_hi) - 1, j_hi = ceil_to_long(1 - type.support_lo) + 1;
    for (long k0 = 0; k0 < n; ++k0)
      for (int m = 0; m <= r; ++m) {
        Rational sum = 0;
        for (long j = j_lo; j <= j_hi; ++j) {
          Rational jm = 1;
          for (int e = 0; e < m; ++e) jm *= j;
          sum += jm * at_grid(d, k0 - j * n);
        }
        const Rational expected = m == r ? factorial : Rational(0);
        if (sum != expected) {
          failures.push_back(name + ": sum_j j^" + std::to_string(m) + " phi^(" + std::to_string(r) + ")(x - j) at x = " +
                             to_string(Rational(k0, n)) + " is " + excerpt(to_string(sum)) + ", not " + to_string(expected));
          return;
        }
      }
  }
}

// A non-uniform table's first derivative: zero outside each open support, the
// relation phi_h'(k/n) = a sum c phi_g'((a k - n s)/n) at every grid point (at
// 0 from the right on both sides), the derivatives summing to 0 everywhere, each
// uniform type's sum_j j phi'(x - j) = 1, and at 0 the slope of the linear
// function: sum_{j in L} xi_j B_j'(0) = 1 (linear_at_zero.hpp). The relation at
// 0 is singular; that last equation makes the values unique.
void verify_nonuniform_derivative(const CurveTable& table, const CurveScheme& scheme, std::vector<std::string>& failures) {
  if (table.derivative_orders == 0) return;
  const NonuniformDerivative plan = nonuniform_derivative_plan(scheme);
  if (!plan.available || table.derivative_orders > 1) {
    failures.push_back("the table has " + std::to_string(table.derivative_orders) + " derivative orders; the scheme has " +
                       (plan.available ? "1" : "none: " + plan.stop));
    return;
  }
  const long n = table.n, a = scheme.arity;
  CurveSolution d;
  try {
    d = table_to_solution(table, scheme, 1);
  } catch (const Error& e) {
    failures.push_back(e.what());
    return;
  }
  for (std::size_t h = 0; h < scheme.types.size(); ++h) {
    const ScalingType& t = scheme.types[h];
    const GridRange g = d.types[h].range;
    for (long k = g.first - n; k <= g.last + n; ++k) {
      Rational rhs = 0;
      for (const Term& term : t.terms) rhs += term.coeff * d.types[term.type].at(a * k - n * term.shift);
      rhs *= a;
      if (rhs != d.types[h].at(k)) {
        failures.push_back("scaling relation of the derivative of '" + t.name + "' fails at x = " + to_string(Rational(k, n)) +
                           ": value " + excerpt(to_string(d.types[h].at(k))) + ", relation gives " + excerpt(to_string(rhs)));
        return;
      }
    }
    if (!t.translation_invariant()) continue;
    const long j_lo = floor_to_long(-t.support_hi) - 1, j_hi = ceil_to_long(1 - t.support_lo) + 1;
    for (long k0 = 0; k0 < n; ++k0) {
      Rational sum = 0;
      for (long j = j_lo; j <= j_hi; ++j) sum += Rational(j) * d.types[h].at(k0 - j * n);
      if (sum != 1) {
        failures.push_back("the derivative of '" + t.name + "': sum_j j phi'(x - j) at x = " + to_string(Rational(k0, n)) +
                           " is " + excerpt(to_string(sum)) + ", not 1");
        return;
      }
    }
  }
  if (const auto sum = check_partition_of_unity(scheme, d, 0)) failures.push_back("the derivatives' sum: " + *sum);
  Rational slope = 0;
  for (std::size_t i = 0; i < plan.at_zero.functions.size(); ++i) {
    const PlacedFunction& f = plan.at_zero.functions[i];
    slope += plan.at_zero.xi[i] * d.types[f.type].at(-f.j * n);
  }
  if (slope != 1)
    failures.push_back("at x = 0 the derivatives give the linear function the slope " + excerpt(to_string(slope)) +
                       " from the right, not 1");
}

}  // namespace

std::vector<std::string> verify_curve_table(const CurveTable& table, const CurveScheme& scheme) {
  std::vector<std::string> failures;
  if (table.scheme != scheme.name) failures.push_back("table is for scheme '" + table.scheme + "', not '" + scheme.name + "'");
  if (table.scheme_hash != hex64(scheme.hash))
    failures.push_back("scheme hash " + excerpt(table.scheme_hash) + " differs from " + hex64(scheme.hash) +
                       " (the scheme file or its parameters changed)");
  if (table.arity != scheme.arity) failures.push_back("arity " + std::to_string(table.arity) + " differs from the scheme's");
  if (!failures.empty()) return failures;
  CurveSolution sol;
  try {
    sol = table_to_solution(table, scheme);
  } catch (const Error& e) {
    return {e.what()};
  }
  const long n = table.n, a = scheme.arity;
  for (std::size_t h = 0; h < scheme.types.size(); ++h) {
    const ScalingType& t = scheme.types[h];
    const CurveTable::Function& f = table.functions[h];
    if (f.name != t.name || f.support_lo != t.support_lo || f.support_hi != t.support_hi)
      failures.push_back("function " + std::to_string(h) + " ('" + excerpt(f.name) + "') does not match the scheme's type '" +
                         t.name + "' and its support");
    // Scaling relation phi_h(k/n) = sum c phi_g((a k - n shift)/n), one grid step beyond the support too.
    const GridRange g = sol.types[h].range;
    for (long k = g.first - n; k <= g.last + n; ++k) {
      Rational rhs = 0;
      for (const Term& term : t.terms) rhs += term.coeff * sol.types[term.type].at(a * k - n * term.shift);
      if (rhs != sol.types[h].at(k)) {
        failures.push_back("scaling relation of '" + t.name + "' fails at x = " + to_string(Rational(k, n)) +
                           ": value " + excerpt(to_string(sol.types[h].at(k))) + ", relation gives " + excerpt(to_string(rhs)));
        if (failures.size() > 20) return failures;
      }
    }
  }
  if (const auto pou = check_partition_of_unity(scheme, sol)) failures.push_back(*pou);
  if (scheme.is_uniform()) verify_derivatives(table, scheme, failures);
  else verify_nonuniform_derivative(table, scheme, failures);
  // A uniform mask symmetric about its centre gives phi symmetric about (l + r) / (2 (a - 1)).
  if (scheme.is_uniform()) {
    const auto& terms = scheme.types[0].terms;
    const long l = terms.front().shift, r = terms.back().shift;
    bool symmetric = true;
    for (const Term& t : terms) {
      Rational mirror = 0;
      for (const Term& u : terms)
        if (u.shift == l + r - t.shift) mirror = u.coeff;
      if (mirror != t.coeff) symmetric = false;
    }
    if (symmetric && ((l + r) * n) % (a - 1) == 0) {
      const long twice_centre = (l + r) * n / (a - 1);  // 2c in grid units
      const GridRange g = sol.types[0].range;
      for (long k = g.first; k <= g.last; ++k)
        if (sol.types[0].at(k) != sol.types[0].at(twice_centre - k)) {
          failures.push_back("symmetric mask but phi(" + to_string(Rational(k, n)) + ") != phi(" +
                             to_string(Rational(twice_centre - k, n)) + ")");
          break;
        }
    }
  }
  return failures;
}

}  // namespace sg
