#pragma once
// The surface's principal frame at a foot point: the unit normal, the two
// principal directions and curvatures (signed: positive where the surface
// bends towards the normal). What SDM's error term needs (seed 003, eq. 6).
#include "stencil_runtime/closest_point.hpp"
#include "stencil_runtime/surface.hpp"

namespace stencil_runtime::fitting {

struct FootFrame {
  Point normal{0, 0, 0}, t1{0, 0, 0}, t2{0, 0, 0};
  double k1 = 0, k2 = 0;
};

// Whether the surface's scheme has exact second derivatives (Catmull-Clark,
// Loop: their regular patches are polynomial).
bool has_second_derivatives(const Surface& surface);

// The frame at `foot`. With exact second derivatives: the shape operator from
// the first and second fundamental forms. Without them (a non-polynomial
// scheme, or the foot at an extraordinary vertex): an estimate at the scale of
// an eighth of a face, from the quadric z = a x^2 + b xy + c y^2 + d x + e y
// fitted (least squares) in the foot's tangent frame to exact limit points on
// the 3 x 3 grid of spacing 1/8 nearest the foot within its (sub-)face.
// `tolerance` bounds the evaluations of the estimate (absolute).
FootFrame foot_frame(const Surface& surface, const ClosestPoint& foot, bool exact_second_derivatives, double tolerance);

}  // namespace stencil_runtime::fitting
