#pragma once
// Exact values of a bivariate scaling function phi(x) = sum_i s_i phi(m x - i)
// (dilation M = m I on a lattice, e.g. the triangular lattice of Loop and
// sqrt(3)) on the grid (1/n)Z^2, with partition of unity, by residue classes:
// the relation maps the class k mod n to (m k) mod n, so the unknowns split
// into classes; classes on cycles of r -> m r mod n solve a small eigenvalue-1
// problem (product of transfer matrices around the cycle, fixed by partition of
// unity), the others follow by substitution. The note, sections 1 and 3.
#include <map>
#include <utility>

#include "algebra/rational.hpp"

namespace sg {

using LatticeIndex = std::pair<long, long>;

struct BivariateMask {
  int dilation = 2;                                // m
  std::map<LatticeIndex, Rational> coefficients;  // s_i, nonzero; sum = m^2
};

struct BivariateSolution {
  long n = 1;
  std::map<LatticeIndex, Rational> values;  // phi(k/n) at every grid point of the open support hull
  Rational at(long a, long b) const {
    const auto it = values.find({a, b});
    return it == values.end() ? Rational(0) : it->second;
  }
};

// Throws sg::Error when a cycle's system has no unique solution.
BivariateSolution solve_bivariate(const BivariateMask& mask, long n);

// The gradient of phi on the same grid, in the lattice's own coordinates (a, b):
// where phi is C1, each partial satisfies the relation with the factor m,
// g(x) = m sum_i s_i g(m x - i), so the same classes solve it with the
// eigenvalue m^-L on a cycle of length L; each cycle is fixed by differentiating
// the reproduction of linear functions (the scheme must reproduce them).
// Throws sg::Error when a cycle has no unique solution (phi not C1, or no
// linear reproduction).
struct BivariateGradient {
  long n = 1;
  std::map<LatticeIndex, Rational> da, db;  // d phi / da and d phi / db at k / n
  Rational at(const std::map<LatticeIndex, Rational>& partial, long a, long b) const {
    const auto it = partial.find({a, b});
    return it == partial.end() ? Rational(0) : it->second;
  }
};
BivariateGradient solve_bivariate_gradient(const BivariateMask& mask, long n);
// Both at once: the classes' cycle products, which cost most, are made once.
std::pair<BivariateSolution, BivariateGradient> solve_bivariate_with_gradient(const BivariateMask& mask, long n);

}  // namespace sg
