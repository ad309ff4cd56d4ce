#include "curve/curve_solution.hpp"

#include <algorithm>

namespace sg {

GridRange open_support_grid(const ScalingType& type, long n) {
  GridRange g;
  g.first = floor_to_long(type.support_lo * n) + 1;
  g.last = ceil_to_long(type.support_hi * n) - 1;
  return g;
}

CurveSolution zero_solution(const CurveScheme& scheme, long n) {
  CurveSolution sol;
  sol.n = n;
  for (const ScalingType& t : scheme.types) {
    TypeValues tv;
    tv.range = open_support_grid(t, n);
    tv.values.assign(static_cast<std::size_t>(std::max(0L, tv.range.size())), Rational(0));
    sol.types.push_back(std::move(tv));
  }
  return sol;
}

bool CurveSolution::operator==(const CurveSolution& o) const {
  if (n != o.n || types.size() != o.types.size()) return false;
  for (std::size_t h = 0; h < types.size(); ++h) {
    const GridRange& a = types[h].range;
    const GridRange& b = o.types[h].range;
    for (long k = std::min(a.first, b.first); k <= std::max(a.last, b.last); ++k)
      if (types[h].at(k) != o.types[h].at(k)) return false;
  }
  return true;
}

}  // namespace sg
