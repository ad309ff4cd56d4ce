#pragma once
// Exact values of every scaling function of a scheme on the grid (1/n)Z.
#include <vector>

#include "algebra/rational.hpp"
#include "curve/curve_scheme.hpp"

namespace sg {

// Grid indices k with lo < k/n < hi: the grid points of the open support.
struct GridRange {
  long first = 0, last = -1;
  long size() const { return last - first + 1; }
  bool contains(long k) const { return k >= first && k <= last; }
};
GridRange open_support_grid(const ScalingType& type, long n);

struct TypeValues {
  GridRange range;                // local grid indices k (parameter k/n)
  std::vector<Rational> values;   // values[k - range.first] = phi_h(k/n)
  Rational at(long k) const { return range.contains(k) ? values[k - range.first] : Rational(0); }
};

struct CurveSolution {
  long n = 1;
  std::vector<TypeValues> types;  // parallel to CurveScheme::types
  bool operator==(const CurveSolution& o) const;
};

// Every type of `scheme` on its open support's grid at rate n, all values zero.
CurveSolution zero_solution(const CurveScheme& scheme, long n);

}  // namespace sg
