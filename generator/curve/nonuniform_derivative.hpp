#pragma once
// The first derivative in x of a non-uniform scheme's basis functions
// (docs/table-format.md), by the differentiated scaling relations
//     phi_h'(x) = a sum c phi_g'(a x - s):
//  - each translation-invariant type is a uniform scheme of its own: its
//    derivative comes from its difference scheme (difference_scheme.hpp), which
//    also shows that it is C1;
//  - the special types follow along the orbits x -> a x from those, as their
//    values do (special_columns.hpp); away from 0 the scheme is uniform after
//    enough steps, so the derivative exists there;
//  - at x = 0 the relation G = a A G is singular (A has the eigenvalue 1/a), and
//    the derivative is one-sided where the parameter x is not the scheme's
//    natural one (nubspline3: t = 2x left of 0, t = x right of it). The stored
//    value is the derivative from the right, fixed by the linear function at 0
//    (linear_at_zero.hpp); from the left it is l'(0-) times that.
#include <optional>
#include <string>
#include <vector>

#include "curve/curve_scheme.hpp"
#include "curve/curve_solution.hpp"
#include "curve/linear_at_zero.hpp"

namespace sg {

struct NonuniformDerivative {
  bool available = false;
  std::string stop;  // why none, or why no second order
  std::vector<std::optional<CurveScheme>> psi;  // per type: an invariant type's first difference scheme
  LinearAtZero at_zero;
};

// What the derivative needs, or the reason it is not generated (in `stop`).
NonuniformDerivative nonuniform_derivative_plan(const CurveScheme& s);

// phi_h' on (1/n)Z for every type h, each on its open support's grid (x = 0:
// from the right). Throws sg::Error when the relations have no unique solution.
CurveSolution solve_nonuniform_derivative(const CurveScheme& s, const NonuniformDerivative& plan, long n);

}  // namespace sg
