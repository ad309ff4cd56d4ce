#pragma once
// A limit point with its first partial derivatives along a face's (u, v)
// (FaceDomain says what they mean), and the unit normal they give.
#include <cmath>

#include "mesh.hpp"

namespace stencil_runtime {

struct Derivatives {
  Point point{0, 0, 0};
  Point du{0, 0, 0}, dv{0, 0, 0};

  // du x dv, normalised: outward for a mesh whose faces are counter-clockwise
  // seen from outside. Zero where du and dv are parallel (a degenerate mesh).
  Point normal() const {
    Point n{du[1] * dv[2] - du[2] * dv[1], du[2] * dv[0] - du[0] * dv[2], du[0] * dv[1] - du[1] * dv[0]};
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (length > 0)
      for (double& x : n) x /= length;
    return n;
  }
};

// The same with the second partial derivatives along (u, v): exact where
// the patch is polynomial there (Catmull-Clark: everywhere but the
// extraordinary vertex itself; docs/runtime.md, "Derivatives and normals").
struct SecondDerivatives : Derivatives {
  Point duu{0, 0, 0}, duv{0, 0, 0}, dvv{0, 0, 0};
};

}  // namespace stencil_runtime
