#include "curve/knot_insertion.hpp"

#include "base/error.hpp"
#include "base/limits.hpp"

namespace sg {

std::map<long, Column> knot_insertion_columns(const KnotSpec& spec, long radius) {
  const int d = spec.degree;
  if (d < limits::kMinKnotDegree || d > limits::kMaxKnotDegree)
    throw Error("knot degree " + std::to_string(d) + " is outside " + std::to_string(limits::kMinKnotDegree) + ".." +
                std::to_string(limits::kMaxKnotDegree));
  if (spec.left_spacing <= 0 || spec.right_spacing <= 0) throw Error("knot spacings must be positive");
  const long centre = (d + 1) / 2;
  const long K = 2 * radius + 2 * (d + 2);  // knot window t_{-K} .. t_K, wide enough to keep columns exact
  auto knot = [&](long i) { return i < 0 ? Rational(spec.left_spacing * i) : Rational(spec.right_spacing * i); };

  std::vector<Rational> coarse;
  for (long i = -K; i <= K; ++i) coarse.push_back(knot(i));
  const long coarse_count = static_cast<long>(coarse.size()) - d - 1;  // basis functions on the window

  std::map<long, Column> columns;
  for (long c = -radius; c <= radius; ++c) {
    const long start = c - centre;  // knot-start index of the B-spline of control c
    std::vector<Rational> tau = coarse;
    std::vector<Rational> coef(coarse_count, 0);
    coef.at(start + K) = 1;
    for (long i = -K; i < K; ++i) {
      const Rational u = (knot(i) + knot(i + 1)) / 2;
      // k: last index with tau[k] <= u
      long k = 0;
      while (k + 1 < static_cast<long>(tau.size()) && tau[k + 1] <= u) ++k;
      std::vector<Rational> next(coef.size() + 1);
      for (long m = 0; m < static_cast<long>(next.size()); ++m) {
        if (m <= k - d) {
          next[m] = m < static_cast<long>(coef.size()) ? coef[m] : Rational(0);
        } else if (m <= k) {
          const Rational alpha = (u - tau[m]) / (tau[m + d] - tau[m]);
          const Rational left = m - 1 >= 0 ? coef[m - 1] : Rational(0);
          const Rational right = m < static_cast<long>(coef.size()) ? coef[m] : Rational(0);
          next[m] = (1 - alpha) * left + alpha * right;
        } else {
          next[m] = coef[m - 1];
        }
      }
      tau.insert(tau.begin() + k + 1, u);
      coef.swap(next);
    }
    // Fine array index m <-> fine knot-start index m - 2K (self-similarity: tau_i = t_i / 2).
    Column col;
    long lo = -1, hi = -1;
    for (long m = 0; m < static_cast<long>(coef.size()); ++m)
      if (coef[m] != 0) {
        if (lo < 0) lo = m;
        hi = m;
      }
    col.first = lo - 2 * K + centre;
    for (long m = lo; m <= hi; ++m) col.coefficients.push_back(coef[m]);
    columns[c] = std::move(col);
  }
  return columns;
}

}  // namespace sg
