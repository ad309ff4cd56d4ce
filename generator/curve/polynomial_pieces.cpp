#include "curve/polynomial_pieces.hpp"

#include "curve/residue_solver.hpp"

namespace sg {

Rational PolynomialPieces::at(long m, const Rational& t) const {
  if (m < first || m >= first + static_cast<long>(pieces.size())) return 0;
  const auto& c = pieces[static_cast<std::size_t>(m - first)];
  Rational y = 0;
  for (std::size_t e = c.size(); e-- > 0;) y = y * t + c[e];  // Horner
  return y;
}

namespace {

// The polynomial of degree <= d through (k/d, y[k]), k = 0..d: Newton's
// divided differences, then expanded to monomial coefficients.
std::vector<Rational> interpolate(const std::vector<Rational>& y, int d) {
  std::vector<Rational> x(static_cast<std::size_t>(d) + 1), diff = y;
  for (int k = 0; k <= d; ++k) x[static_cast<std::size_t>(k)] = Rational(k, d);
  for (int level = 1; level <= d; ++level)
    for (int k = d; k >= level; --k)
      diff[static_cast<std::size_t>(k)] = (diff[static_cast<std::size_t>(k)] - diff[static_cast<std::size_t>(k - 1)]) /
                                          (x[static_cast<std::size_t>(k)] - x[static_cast<std::size_t>(k - level)]);
  std::vector<Rational> c(static_cast<std::size_t>(d) + 1, Rational(0));
  // Horner on the Newton form: p = diff[d]; p = p * (t - x[k]) + diff[k].
  c[0] = diff[static_cast<std::size_t>(d)];
  for (int k = d - 1; k >= 0; --k) {
    std::vector<Rational> next(c.size(), Rational(0));
    for (std::size_t e = 0; e + 1 < c.size(); ++e) {
      next[e + 1] += c[e];
      next[e] -= c[e] * x[static_cast<std::size_t>(k)];
    }
    next[0] += diff[static_cast<std::size_t>(k)];
    c = std::move(next);
  }
  return c;
}

}  // namespace

std::optional<PolynomialPieces> polynomial_pieces(const CurveScheme& curve, int max_degree) {
  if (!curve.is_uniform() || curve.arity != 2) return std::nullopt;
  const ScalingType& type = curve.types[0];
  const long lo = floor_to_long(type.support_lo), hi = ceil_to_long(type.support_hi);
  for (int d = 1; d <= max_degree; ++d) {
    const CurveSolution solution = solve_by_residues(curve, d);
    const TypeValues& phi = solution.types[0];
    PolynomialPieces p;
    p.degree = d;
    p.first = lo;
    for (long m = lo; m < hi; ++m) {
      std::vector<Rational> y;
      for (long k = 0; k <= d; ++k) y.push_back(phi.at(m * d + k));
      p.pieces.push_back(interpolate(y, d));
    }
    // Partition of unity: the pieces sum to the constant 1.
    bool ok = true;
    for (int e = 0; e <= d && ok; ++e) {
      Rational sum = 0;
      for (const auto& c : p.pieces) sum += c[static_cast<std::size_t>(e)];
      ok = sum == (e == 0 ? 1 : 0);
    }
    // The refinement equation phi(x) = sum_i a_i phi(2x - i) on every half
    // interval [m + h/2, m + (h+1)/2], at d + 1 points t = (h + s/d) / 2.
    for (long m = lo - 1; m <= hi && ok; ++m)
      for (int h = 0; h < 2 && ok; ++h)
        for (int s = 0; s <= d && ok; ++s) {
          const Rational t = (Rational(h) + Rational(s, d)) / 2;
          Rational right = 0;
          for (const Term& term : type.terms) right += term.coeff * p.at(2 * m + h - term.shift, Rational(s, d));
          ok = p.at(m, t) == right;
        }
    if (ok) return p;
  }
  return std::nullopt;
}

}  // namespace sg
