#pragma once
#include "curve/curve_solution.hpp"

namespace sg {

// Route (a): the scaling relations on (1/n)Z plus partition of unity, split by
// residue class. For translation-invariant types, x = j + r/n is related to
// residue a*r mod n; classes on a cycle of that map solve a tiny fixed-point
// problem (product of transfer matrices), classes on its trees follow by
// substitution. Special (single-column) types are then solved in global
// coordinates along the orbits x -> a*x, which leave the support unless x = 0;
// at x = 0 the values are the eigenvalue-1 left eigenvector fixed by partition
// of unity. Throws sg::Error when the system has no unique solution.
CurveSolution solve_by_residues(const CurveScheme& scheme, long n);

}  // namespace sg
