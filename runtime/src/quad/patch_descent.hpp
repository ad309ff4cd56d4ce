#pragma once
// A quad patch evaluated at any parameter by the scheme's own subdivision of
// the patch (docs/runtime.md, "Evaluation at any parameter"). The control
// points descend into the child that holds the parameter: the extraordinary
// child through A0, a regular child through its rows, a regular patch into one
// of its four quadrants through the curve's half-interval matrices. The
// descent stops
//  - exactly, where a stored rate holds the child's parameter (a double is an
//    exact dyadic fraction, so this happens within its binary digits);
//  - exactly up to rounding, in a regular patch whose basis is polynomial
//    (Catmull-Clark's bicubic B-splines): the pieces are evaluated directly;
//  - otherwise once the bound is within the tolerance. The approximation is the
//    exact limit point at the nearest node of the finest stored grid; where the
//    scheme's mask and derivative mask are non-negative the limit's partial
//    derivatives lie in the convex hulls of the control points' differences,
//    so |f(x) - f(node)| <= |dx| max|D_u| + |dy| max|D_v| (plus rounding).
#include <array>
#include <vector>

#include "family/family.hpp"
#include "stencil_runtime/derivatives.hpp"
#include "tables/quad_tables.hpp"

namespace stencil_runtime {

// A limit point with its partial derivatives along the patch's two parameters.
using PatchDerivatives = Derivatives;

class QuadPatchDescent {
 public:
  // Throws EvaluationError when the tables hold no patch subdivision.
  explicit QuadPatchDescent(const QuadTables& tables);

  // `points`: the patch's control points in the tables' canonical order (16 or
  // 2v+8), consumed; (x, y): the patch parameter. P is Fraction or double.
  template <class P>
  Approximation evaluate(int valence, std::vector<Point>& points, P x, P y, double tolerance) const;

  // The limit point and its partial derivatives in the patch's own (x, y), at
  // any parameter but the extraordinary vertex (0, 0) of a patch of valence
  // other than 4, where the patch has no parametric derivative. The control
  // points descend (consumed) as in evaluate() but on into a regular patch,
  // each halving doubling the derivatives (no derivative stencils of the
  // extraordinary patch are stored); there the derivatives come from the
  // polynomial basis (Catmull-Clark: exact to rounding) or from the stored
  // phi and phi', directly where a rate's grid 1/(2n) holds a coordinate and
  // through its orbit under halving elsewhere (curve_orbit.hpp), so at any
  // rational or double. Throws EvaluationError at the vertex, for tables
  // without phi' (a curve that is not C1), and for an orbit beyond the limit.
  template <class P>
  PatchDerivatives derivatives(int valence, std::vector<Point>& points, P x, P y) const;
  // The same with second derivatives, where the regular patch is polynomial
  // (Catmull-Clark); throws EvaluationError for other schemes (their tables
  // hold no phi'') and at the extraordinary vertex.
  template <class P>
  SecondDerivatives second_derivatives(int valence, std::vector<Point>& points, P x, P y) const;

  // The child in quadrant (cx, cy) of a patch of kind `valence` (4: regular):
  // for an extraordinary patch quadrant (0,0) is the extraordinary child (A0),
  // the others its regular children; a regular patch's quadrants are regular.
  void child(int valence, const std::vector<Point>& points, int cx, int cy, std::vector<Point>& out, int& out_valence) const;
  // Whether every subdivision weight (mask, A0, regular children) is non-negative.
  bool nonnegative() const;
  // Whether the regular patch is polynomial (derivatives exact at any parameter).
  bool polynomial_regular() const { return d_.degree > 0; }

 private:
  Approximation regular_bound(const std::vector<Point>& q, double x, double y) const;
  Point polynomial(const std::vector<Point>& q, double x, double y) const;
  // The regular patch's basis along one axis at any t in [0, 1], and its
  // derivative, from the stored phi and phi' (directly where a rate's grid
  // 1/(2n) holds t, else through t's orbit under halving: curve_orbit.hpp).
  void regular_basis(const Fraction& t, double* w, double* dw) const;
  void regular_basis(double t, double* w, double* dw) const;
  void polynomial_basis(double t, double* w, double* dw, double* ddw = nullptr) const;
  static SecondDerivatives tensor(const std::vector<Point>& q, const double* wx, const double* wy, const double* dx,
                                  const double* dy, const double* ddx, const double* ddy, double scale);
  // The points descend (consumed) into the regular patch holding (x, y);
  // its parameter there, `scale` multiplied by 2 per halving.
  template <class P>
  // `offset`: where the points were moved to keep their differences (family/recentre.hpp).
  std::array<P, 2> into_regular(int valence, std::vector<Point>& points, P x, P y, double& scale, Point& offset) const;
  void regular_child(std::vector<Point>& q, int cx, int cy) const;

  const QuadTables& tables_;
  const QuadDescent& d_;
  double half_[2][4][4];  // the curve's half-interval matrices: child c point k from parent point j
};

}  // namespace stencil_runtime
