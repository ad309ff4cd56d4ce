#include "curve/partition_of_unity.hpp"

#include <algorithm>

#include "algebra/integer_division.hpp"
#include "base/error.hpp"

namespace sg {
std::vector<std::vector<std::size_t>> pou_groups(const CurveScheme& s, const std::vector<std::size_t>& invariant) {
  std::vector<std::size_t> left, right;
  for (std::size_t h : invariant) {
    const Placement p = s.types[h].placement;
    if (p == Placement::Everywhere || p == Placement::AtMost) left.push_back(h);
    if (p == Placement::Everywhere || p == Placement::AtLeast) right.push_back(h);
  }
  std::vector<std::vector<std::size_t>> groups;
  if (!left.empty()) groups.push_back(left);
  if (!right.empty() && right != left) groups.push_back(right);
  return groups;
}

Rational invariant_sum_at(const CurveScheme& s, const CurveSolution& sol, long K) {
  const long n = sol.n;
  Rational sum = 0;
  for (std::size_t h = 0; h < s.types.size(); ++h) {
    if (!s.types[h].translation_invariant()) continue;
    const GridRange& g = sol.types[h].range;
    for (long j = ceil_div(K - g.last, n); j <= floor_div(K - g.first, n); ++j)
      if (s.types[h].placed_at(j)) sum += sol.types[h].at(K - j * n);
  }
  return sum;
}

std::optional<std::string> check_partition_of_unity(const CurveScheme& s, const CurveSolution& sol,
                                                    const Rational& expected) {
  const long n = sol.n;
  std::vector<std::size_t> invariant, special;
  for (std::size_t h = 0; h < s.types.size(); ++h)
    (s.types[h].translation_invariant() ? invariant : special).push_back(h);
  for (const auto& group : pou_groups(s, invariant))
    for (long r = 0; r < n; ++r) {
      Rational sum = 0;
      for (std::size_t h : group) {
        const GridRange& g = sol.types[h].range;
        for (long j = ceil_div(g.first - r, n); j <= floor_div(g.last - r, n); ++j) sum += sol.types[h].at(j * n + r);
      }
      if (sum != expected) {
        std::string names;
        for (std::size_t h : group) names += (names.empty() ? "" : "+") + s.types[h].name;
        return "partition of unity fails at x = " + std::to_string(r) + "/" + std::to_string(n) + " (mod 1) for " +
               names + ": the sum is " + excerpt(to_string(sum));
      }
    }
  if (special.empty()) return std::nullopt;
  long lo = 0, hi = 0;
  for (std::size_t h : special) {
    lo = std::min(lo, sol.types[h].range.first + n * s.types[h].position);
    hi = std::max(hi, sol.types[h].range.last + n * s.types[h].position);
  }
  for (long K = lo - n; K <= hi + n; ++K) {
    Rational sum = invariant_sum_at(s, sol, K);
    for (std::size_t h : special) sum += sol.types[h].at(K - n * s.types[h].position);
    if (sum != expected)
      return "partition of unity fails at x = " + to_string(Rational(K, n)) + ": the sum is " + excerpt(to_string(sum));
  }
  return std::nullopt;
}

}  // namespace sg
