#include "curve/curve_table_verify.hpp"

#include "base/error.hpp"
#include "common/hash.hpp"
#include "curve/partition_of_unity.hpp"

namespace sg {

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
