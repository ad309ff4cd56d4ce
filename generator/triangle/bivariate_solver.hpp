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

}  // namespace sg
