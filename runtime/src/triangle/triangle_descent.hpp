#pragma once
// A triangle patch evaluated at any parameter by the scheme's own subdivision
// of the patch (docs/runtime.md, "Evaluation at any parameter"): the control
// points descend into the cell that holds the parameter (the tables' children:
// Loop 4 cells, sqrt(3) 9 per composite step), each cell a patch of a kind the
// tables hold (the EV's own patch, a band region, or the regular patch). The
// descent stops
//  - exactly, where a stored rate holds the cell's parameter;
//  - exactly up to rounding, in a regular patch whose basis is polynomial
//    (Loop's quartic box spline), evaluated directly;
//  - otherwise once the bound is within the tolerance: the approximation is the
//    exact limit point f(s) at the sample s of the finest stored grid nearest to
//    the parameter x. Every subdivision weight is non-negative, so the limit over
//    a cell lies in the convex hull of its control points: for the smallest
//    cell (descending further) whose closure holds both x and s,
//    |f(x) - f(s)| <= max_j |P_j - f(s)| (plus rounding). That cell is about as
//    small as |x - s|, which keeps the bound within a small factor of the error.
#include <vector>

#include "family/family.hpp"
#include "family/parameter_ops.hpp"
#include "tables/triangle_tables.hpp"

namespace stencil_runtime {

// A parameter whose descent reaches a regular point no stored grid holds, where
// a non-polynomial regular patch (sqrt(3)) has no exact derivative stencil.
struct OffGridDerivative : EvaluationError {
  using EvaluationError::EvaluationError;
};

class TrianglePatchDescent {
 public:
  // Throws EvaluationError when the tables hold no patch subdivision (version 2).
  explicit TrianglePatchDescent(const TriangleTables& tables);

  // `points`: the patch's control points over layout(valence, region), consumed;
  // (x, y): the patch parameter. P is Fraction or double.
  template <class P>
  Approximation evaluate(int valence, int region, std::vector<Point>& points, P x, P y, double tolerance) const;

  // The limit point and its derivatives along the original face's (u, v), for
  // a scheme whose regular patch is polynomial (Loop): the descent runs to a
  // regular cell and differentiates its polynomial; (x, y) carry the
  // derivatives of the patch parameter along (u, v), and so every cell's.
  // Throws EvaluationError at the extraordinary vertex itself (no parametric
  // derivative there) and for a scheme without a polynomial regular patch.
  Derivatives derivatives(int valence, int region, std::vector<Point>& points, Dual x, Dual y) const;
  // The same at an exact parameter, for every scheme: a regular basis that is
  // not a polynomial (sqrt(3)) is differentiated by the tables' derivative
  // stencils (version 6) at the grid point the descent reaches. A point of a
  // stored grid reaches one (the cells' maps scale by m and keep the grid
  // 1/n); other parameters may not, and get an OffGridDerivative saying so.
  Derivatives derivatives(int valence, int region, std::vector<Point>& points, ExactDual x, ExactDual y) const;
  // The same with the second derivatives along (u, v) (the cells' maps are
  // affine: the chain rule has no second-order terms).
  SecondDerivatives second_derivatives(int valence, int region, std::vector<Point>& points, Dual x, Dual y) const;

 private:
  // Down the cells holding (x, y) until the cell is regular (valence 6);
  // throws EvaluationError at the extraordinary vertex itself.
  template <class P>
  // `offset`: where the points were moved to keep their differences (family/recentre.hpp).
  void descend_to_regular(int& valence, int& region, std::vector<Point>& points, P& x, P& y, Point& offset) const;
  // Throws EvaluationError for a scheme without a polynomial regular patch.
  void require_polynomial() const;
  // The regular cell's polynomial at (x, y) with its first and second derivatives along (u, v).
  SecondDerivatives regular_derivatives(const std::vector<Point>& points, const Dual& x, const Dual& y) const;
  Approximation nearest_sample(int valence, int region, const std::vector<Point>& q, double x, double y, double& sx,
                               double& sy) const;
  double common_cell_bound(int valence, int region, std::vector<Point> q, double x, double y, double sx, double sy,
                           const Point& at, double bound) const;
  Point polynomial(const std::vector<Point>& q, double x, double y) const;

  const TriangleTables& tables_;
};

}  // namespace stencil_runtime
