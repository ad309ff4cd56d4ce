#pragma once
#include "curve/curve_solution.hpp"

namespace sg {

// Route (b), the paper's section 3: build the subdivision matrix S^ of the
// upsampled (matrix) mask s_hg(z^n) over the local index set {(h, y)}, whose
// left eigenvectors for eigenvalue 1 hold phi_h(-y/n); add partition of unity
// and solve the whole system at once with the sparse exact solver. No residue
// classes, no orbit order: an independent route to the same numbers.
CurveSolution solve_by_eigenvector(const CurveScheme& scheme, long n);

}  // namespace sg
