#pragma once
// The part of a patch's parameter domain that a sub-patch covers: the image
// of its own unit domain, the square [0,1]^2 (quads) or the triangle X, Y >= 0,
// X + Y <= 1 (triangles), under the affine map
//   (X, Y) -> origin + X x_axis + Y y_axis.
// Quad sub-patches are squares with axes along the patch's; a triangle
// sub-patch's axes follow its kind's corner order (the descent's rotations), so
// they may point anywhere. All the maps' numbers are dyadic or triadic
// fractions of the patch, and the 2x2 inverse is exact for the quads' squares.
#include <algorithm>
#include <array>
#include <cmath>

namespace stencil_runtime {

struct SubDomain {
  bool triangle = false;
  std::array<double, 2> origin{0, 0}, x_axis{1, 0}, y_axis{0, 1};

  static SubDomain unit(bool triangle) {
    SubDomain d;
    d.triangle = triangle;
    return d;
  }
  // The longer axis: the sub-patch's size in the patch's parameters.
  double size() const { return std::max(std::hypot(x_axis[0], x_axis[1]), std::hypot(y_axis[0], y_axis[1])); }
  std::array<double, 2> at(double X, double Y) const {
    return {origin[0] + X * x_axis[0] + Y * y_axis[0], origin[1] + X * x_axis[1] + Y * y_axis[1]};
  }
  // The inverse map: (x, y) in the sub-patch's own coordinates.
  std::array<double, 2> local(double x, double y) const {
    const double det = x_axis[0] * y_axis[1] - x_axis[1] * y_axis[0];
    const double dx = x - origin[0], dy = y - origin[1];
    return {(dx * y_axis[1] - dy * y_axis[0]) / det, (dy * x_axis[0] - dx * x_axis[1]) / det};
  }
  // d(X, Y)/d(x, y): rows (dX/dx, dX/dy) and (dY/dx, dY/dy).
  std::array<double, 4> inverse_jacobian() const {
    const double det = x_axis[0] * y_axis[1] - x_axis[1] * y_axis[0];
    return {y_axis[1] / det, -y_axis[0] / det, -x_axis[1] / det, x_axis[0] / det};
  }
  // Own coordinates moved into the unit domain.
  void clamp_local(double& X, double& Y) const {
    X = std::clamp(X, 0.0, 1.0), Y = std::clamp(Y, 0.0, 1.0);
    if (triangle && X + Y > 1) {
      const double excess = 0.5 * (X + Y - 1);
      X = std::clamp(X - excess, 0.0, 1.0), Y = 1 - X;
    }
  }
  bool contains_local(double X, double Y, double slack = 0) const {
    if (X < -slack || Y < -slack) return false;
    return triangle ? X + Y <= 1 + slack : X <= 1 + slack && Y <= 1 + slack;
  }
  bool contains(double x, double y, double slack = 0) const {
    const auto l = local(x, y);
    return contains_local(l[0], l[1], slack);
  }
  // A point of the patch moved into the sub-patch's domain.
  void clamp(double& x, double& y) const {
    if (contains(x, y)) return;
    auto l = local(x, y);
    clamp_local(l[0], l[1]);
    const auto p = at(l[0], l[1]);
    x = p[0], y = p[1];
  }
  std::array<double, 2> centre() const { return triangle ? at(1.0 / 3, 1.0 / 3) : at(0.5, 0.5); }
  int corners() const { return triangle ? 3 : 4; }
  std::array<double, 2> corner(int k) const {
    static constexpr double kSquare[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    static constexpr double kTriangle[3][2] = {{0, 0}, {1, 0}, {0, 1}};
    const double* c = triangle ? kTriangle[k] : kSquare[k];
    return at(c[0], c[1]);
  }
};

}  // namespace stencil_runtime
