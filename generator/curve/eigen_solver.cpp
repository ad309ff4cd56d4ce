#include "curve/eigen_solver.hpp"

#include <algorithm>
#include <map>

#include "algebra/exact_linear_system.hpp"
#include "algebra/integer_division.hpp"
#include "base/error.hpp"

namespace sg {

CurveSolution solve_by_eigenvector(const CurveScheme& s, long n) {
  if (n < 1) throw Error("rate n must be at least 1, got " + std::to_string(n));
  const long a = s.arity;
  const std::size_t T = s.types.size();
  // Index set: (h, y) with -y/n in the open support of phi_h, i.e. y in -range.
  std::vector<GridRange> yr(T);
  std::vector<std::size_t> base(T);
  std::size_t total = 0;
  for (std::size_t h = 0; h < T; ++h) {
    const GridRange g = open_support_grid(s.types[h], n);
    yr[h] = {-g.last, -g.first};
    base[h] = total;
    total += static_cast<std::size_t>(std::max(0L, yr[h].size()));
  }
  auto index = [&](std::size_t h, long y) -> long {
    return yr[h].contains(y) ? static_cast<long>(base[h] + (y - yr[h].first)) : -1;
  };

  ExactLinearSystem sys(total);
  // u = u S^:  column (h, y) of S^ holds the upsampled mask of h: row (g, a*y + n*shift) gets coeff.
  for (std::size_t h = 0; h < T; ++h)
    for (long y = yr[h].first; y <= yr[h].last; ++y) {
      std::vector<std::pair<std::size_t, Rational>> eq{{static_cast<std::size_t>(index(h, y)), Rational(-1)}};
      for (const Term& t : s.types[h].terms) {
        const long row = index(t.type, a * y + n * t.shift);
        if (row >= 0) eq.emplace_back(static_cast<std::size_t>(row), t.coeff);
      }
      sys.add_equation(eq, 0);
    }

  // Partition of unity at global x = K/n: sum over types h and placements p of phi_h(x - p),
  // i.e. u(h, -(K - n p)). Far from the special point one period suffices; near it, every point.
  auto add_pou = [&](long K, const std::vector<std::size_t>& types) {
    std::vector<std::pair<std::size_t, Rational>> eq;
    for (std::size_t h : types) {
      // -(K - n p) in yr[h]  <=>  p in [(K + y_first)/n, (K + y_last)/n]
      const long pmin = ceil_div(K + yr[h].first, n), pmax = floor_div(K + yr[h].last, n);
      for (long p = pmin; p <= pmax; ++p)
        if (s.types[h].placed_at(p)) eq.emplace_back(static_cast<std::size_t>(index(h, -(K - n * p))), Rational(1));
    }
    sys.add_equation(eq, 1);
  };
  std::vector<std::size_t> all(T);
  for (std::size_t h = 0; h < T; ++h) all[h] = h;
  long lo = 0, hi = 0;
  bool has_special = false;
  for (std::size_t h = 0; h < T; ++h)
    if (s.types[h].placement == Placement::Single) {
      has_special = true;
      lo = std::min(lo, -yr[h].last + n * s.types[h].position);
      hi = std::max(hi, -yr[h].first + n * s.types[h].position);
    }
  // One full period on each side of the special region reaches the uniform parts.
  long far = 0;
  for (std::size_t h = 0; h < T; ++h) far = std::max({far, std::labs(yr[h].first), std::labs(yr[h].last)});
  if (!has_special)
    for (long K = 0; K < n; ++K) add_pou(K, all);  // translation invariance: one period
  else {
    // Every point of the special region, and one period on each side far enough
    // out that only one uniform type is present there.
    for (long K = lo; K <= hi; ++K) add_pou(K, all);
    for (long K = lo - far - n; K < lo - far; ++K) add_pou(K, all);
    for (long K = hi + far + 1; K <= hi + far + n; ++K) add_pou(K, all);
  }

  const LinearSolution result = sys.solve();
  if (result.status != LinearSolution::Status::Unique)
    throw Error("scheme '" + s.name + "', n = " + std::to_string(n) +
                ": the eigenvalue-1 left eigenspace of the upsampled subdivision matrix (" + std::to_string(total) +
                " unknowns) with partition of unity has " + result.describe());
  CurveSolution sol;
  sol.n = n;
  for (std::size_t h = 0; h < T; ++h) {
    TypeValues tv;
    tv.range = {-yr[h].last, -yr[h].first};
    for (long k = tv.range.first; k <= tv.range.last; ++k) tv.values.push_back(result.values[index(h, -k)]);
    sol.types.push_back(std::move(tv));
  }
  return sol;
}

}  // namespace sg
