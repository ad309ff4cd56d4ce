#include "curve/special_columns.hpp"

#include <algorithm>
#include <cstdlib>

#include "base/error.hpp"

namespace sg {

Rational global_value(const CurveScheme& s, const CurveSolution& sol, std::size_t h, long K) {
  return sol.types[h].at(K - sol.n * s.types[h].position);
}

void set_global_value(const CurveScheme& s, CurveSolution& sol, std::size_t h, long K, const Rational& v) {
  TypeValues& tv = sol.types[h];
  tv.values[static_cast<std::size_t>(K - sol.n * s.types[h].position - tv.range.first)] = v;
}

Rational special_relation(const CurveScheme& s, const CurveSolution& sol, std::size_t h, long K,
                          std::vector<std::pair<std::size_t, Rational>>& special_terms) {
  const long a = s.arity, n = sol.n;
  const ScalingType& t = s.types[h];
  Rational known = 0;
  for (const Term& term : t.terms) {
    const ScalingType& g = s.types[term.type];
    if (g.translation_invariant()) {
      known += term.coeff * sol.types[term.type].at(a * K - n * (a * t.position + term.shift));
    } else {
      if (term.shift != g.position - a * t.position)
        throw Error(s.source + ": special column " + t.name + " is not stationary around 0");
      special_terms.emplace_back(term.type, term.coeff);
    }
  }
  return known;
}

void solve_special_orbits(const CurveScheme& s, CurveSolution& sol, const Rational& factor) {
  const long a = s.arity, n = sol.n;
  std::vector<std::size_t> special;
  for (std::size_t h = 0; h < s.types.size(); ++h)
    if (!s.types[h].translation_invariant()) special.push_back(h);
  long kmax = 0;
  for (std::size_t h : special) {
    const GridRange& g = sol.types[h].range;
    const long p = s.types[h].position;
    kmax = std::max({kmax, std::labs(g.first + n * p), std::labs(g.last + n * p)});
  }
  // Orbits K -> aK grow in modulus, so descending |K| meets every dependency first.
  for (long mag = kmax; mag >= 1; --mag)
    for (long K : {mag, -mag})
      for (std::size_t h : special) {
        if (!sol.types[h].range.contains(K - n * s.types[h].position)) continue;
        std::vector<std::pair<std::size_t, Rational>> terms;
        Rational v = special_relation(s, sol, h, K, terms);
        for (const auto& [g, c] : terms) v += c * global_value(s, sol, g, a * K);
        set_global_value(s, sol, h, K, factor * v);
      }
}

std::vector<std::size_t> special_types_at_zero(const CurveScheme& s, const CurveSolution& sol) {
  std::vector<std::size_t> at_zero;
  for (std::size_t h = 0; h < s.types.size(); ++h)
    if (!s.types[h].translation_invariant() && sol.types[h].range.contains(-sol.n * s.types[h].position))
      at_zero.push_back(h);
  return at_zero;
}

std::size_t position_in(const std::vector<std::size_t>& types, std::size_t h) {
  return static_cast<std::size_t>(std::find(types.begin(), types.end(), h) - types.begin());
}

void add_relations_at_zero(const CurveScheme& s, const CurveSolution& sol, const std::vector<std::size_t>& at_zero,
                           const Rational& factor, ExactLinearSystem& system) {
  for (std::size_t h : at_zero) {
    std::vector<std::pair<std::size_t, Rational>> terms, eq{{position_in(at_zero, h), Rational(1)}};
    const Rational known = special_relation(s, sol, h, 0, terms);
    for (const auto& [g, c] : terms)
      if (position_in(at_zero, g) < at_zero.size()) eq.emplace_back(position_in(at_zero, g), -factor * c);
    system.add_equation(eq, factor * known);
  }
}

}  // namespace sg
