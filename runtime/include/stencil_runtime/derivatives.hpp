#pragma once
// A limit point with its first partial derivatives along a face's (u, v)
// (FaceDomain says what they mean), and the unit normal they give.
#include <cmath>

#include "mesh.hpp"

namespace stencil_runtime {

// `a` divided by its largest component's magnitude (zero stays zero): the
// direction is kept, and products of two such vectors neither underflow nor
// overflow, whatever the mesh's size.
inline Point scaled_to_unit_max(const Point& a) {
  const double m = std::fmax(std::fabs(a[0]), std::fmax(std::fabs(a[1]), std::fabs(a[2])));
  return m > 0 ? Point{a[0] / m, a[1] / m, a[2] / m} : a;
}

// du x dv, normalised: outward for a mesh whose faces are counter-clockwise
// seen from outside. Zero where du and dv are parallel (a degenerate mesh).
// Tangents of a tiny mesh (coordinates of 1e-80, say) have a cross product
// whose squared length underflows: those are scaled first
// (scaled_to_unit_max), which changes the direction by nothing but rounding.
inline Point unit_cross(const Point& du, const Point& dv) {
  auto cross = [](const Point& a, const Point& b) {
    return Point{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  };
  Point n = cross(du, dv);
  double squared = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
  if (squared < 1e-280) {  // or zero: far above the denormals, where digits go
    n = cross(scaled_to_unit_max(du), scaled_to_unit_max(dv));
    squared = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
  }
  const double length = std::sqrt(squared);
  if (length > 0)
    for (double& x : n) x /= length;
  return n;
}

struct Derivatives {
  Point point{0, 0, 0};
  Point du{0, 0, 0}, dv{0, 0, 0};

  // du x dv, normalised (unit_cross).
  Point normal() const { return unit_cross(du, dv); }
};

// The same with the second partial derivatives along (u, v): exact where
// the patch is polynomial there (Catmull-Clark: everywhere but the
// extraordinary vertex itself; docs/runtime.md, "Derivatives and normals").
struct SecondDerivatives : Derivatives {
  Point duu{0, 0, 0}, duv{0, 0, 0}, dvv{0, 0, 0};
};

}  // namespace stencil_runtime
