#include "algebra/scaled_vector.hpp"

#include <boost/multiprecision/integer.hpp>

namespace sg {

void ScaledVector::reduce() {
  if (den < 0) {
    den = -den;
    for (auto& x : num) x = -x;
  }
  Integer g = den;
  for (const auto& x : num) {
    if (g == 1) break;
    if (x != 0) g = boost::multiprecision::gcd(g, x);
  }
  if (g > 1) {
    den /= g;
    for (auto& x : num) x /= g;
  }
}

std::vector<Rational> ScaledVector::rationals() const {
  std::vector<Rational> out;
  out.reserve(num.size());
  for (const auto& x : num) out.emplace_back(x, den);
  return out;
}

ScaledMatrix scale_rows(const std::vector<std::vector<std::pair<std::size_t, Rational>>>& rows, std::size_t columns) {
  ScaledMatrix m;
  m.columns = columns;
  Integer den = 1;
  for (const auto& row : rows)
    for (const auto& [c, w] : row) den = boost::multiprecision::lcm(den, boost::multiprecision::denominator(w));
  m.den = den;
  m.rows.resize(rows.size());
  for (std::size_t r = 0; r < rows.size(); ++r)
    for (const auto& [c, w] : rows[r])
      m.rows[r].emplace_back(c, boost::multiprecision::numerator(w) * (den / boost::multiprecision::denominator(w)));
  return m;
}

ScaledVector left_multiply(const ScaledVector& x, const ScaledMatrix& m) {
  ScaledVector y;
  y.num.assign(m.columns, Integer(0));
  y.den = x.den * m.den;
  for (std::size_t r = 0; r < m.rows.size(); ++r) {
    if (x.num[r] == 0) continue;
    for (const auto& [c, w] : m.rows[r]) y.num[c] += x.num[r] * w;
  }
  return y;
}

ScaledVector scaled_from_rationals(const std::vector<Rational>& values) {
  ScaledVector v;
  Integer den = 1;
  for (const auto& x : values) den = boost::multiprecision::lcm(den, boost::multiprecision::denominator(x));
  v.den = den;
  for (const auto& x : values)
    v.num.push_back(boost::multiprecision::numerator(x) * (den / boost::multiprecision::denominator(x)));
  return v;
}

}  // namespace sg
