#pragma once
// A bound on a sub-patch's surface that is tight near a closest point
// (docs/runtime.md, "Closest points"). Where a sub-patch's scheme reproduces
// affine functions (Family::affine_parameters: control point i at parameter
// g_i, sum_i phi_i(x) g_i = x, sum_i phi_i(x) = 1, phi_i >= 0), any affine map
// L gives S(x) = L(x) + sum_i phi_i(x) (P_i - L(g_i)), so the surface over the
// sub-patch's unit square lies in the parallelogram L([0,1]^2) (for a
// triangle sub-patch: the triangle L of its unit triangle) plus the hull
// of the residuals E_i = P_i - L(g_i): inside the slab made by growing the
// parallelogram in its plane by the residuals' largest part across its normal
// and along the normal by their range. L is the least-squares fit of the
// control points to their parameters. Unlike the control points' hull, the
// slab covers the sub-patch's own domain only, and the residuals are of second
// order in the sub-patch's size (mostly along the plane where the
// parametrisation is uneven, which the slab does not charge to the distance).
#include <array>
#include <vector>

#include "family/family.hpp"

namespace stencil_runtime {

class AffineEnclosure {
 public:
  AffineEnclosure() = default;  // none: lower_bound() is never asked
  explicit AffineEnclosure(const AffineParameters& parameters);

  bool empty() const { return fit_.empty(); }

  // The slab of one sub-patch: what does not depend on the query point (made
  // once per face patch, or per sub-patch as the search splits it).
  struct Slab {
    Point o{0, 0, 0}, u{0, 0, 0}, v{0, 0, 0};  // L(X, Y) = o + X u + Y v
    Point m{0, 0, 0};                          // the unit normal of L's plane (0 where L is degenerate)
    bool flat = false;                         // whether L's image is a proper parallelogram (triangle)
    double low = 0, high = 0;                  // the residuals' range along m
    double across = 0;                         // their largest part across m
    double uu = 0, uv = 0, vv = 0;
  };
  Slab slab(const std::vector<Point>& points) const;
  // An axis-aligned box that holds the slab (so the sub-patch's surface): a
  // far tighter box than its control points' for a regular patch, whose points
  // reach a ring beyond its face.
  std::array<Point, 2> box(const Slab& slab) const;
  // A lower bound on the distance from q to the surface of a sub-patch of this kind.
  double lower_bound(const Slab& slab, const Point& q) const;
  double lower_bound(const std::vector<Point>& points, const Point& q) const { return lower_bound(slab(points), q); }

 private:
  std::vector<std::array<double, 2>> at_;
  std::vector<std::array<double, 3>> fit_;  // per control point: its weights in L's origin, u and v columns
  double residual_ = 0;
  bool triangle_ = false;  // the unit domain is the triangle X, Y >= 0, X + Y <= 1 (else the square)
};

// The distance from q to the triangle (a, b, c).
double point_triangle_distance(const Point& q, const Point& a, const Point& b, const Point& c);

}  // namespace stencil_runtime
