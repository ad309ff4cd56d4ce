#pragma once
// The error term of one point under PDM, TDM or SDM (seed 003, section II-D),
// as the symmetric weight M of (S - X)^T M (S - X), S the surface point at the
// point's foot parameters (linear in the control points) and X the point.
#include <Eigen/Core>

#include "fitting/foot_frame.hpp"
#include "stencil_runtime/surface_fit.hpp"

namespace stencil_runtime::fitting {

// PDM: the identity. TDM: N N^T. SDM: N N^T + a1 t1 t1^T + a2 t2 t2^T with
// a_i = d / (d - rho_i) = d k_i / (d k_i - 1), d the signed distance of X
// along N and rho_i = 1 / k_i the signed curvature radius; a_i is clamped to
// [0, 1]: below 0 (X between the foot and the centre of curvature) seed 003
// takes 0, and above 1 (X beyond the centre, where the foot cannot be a
// nearest point; only an estimated curvature gets there) we take PDM's 1.
// `frame` is read by SDM only.
Eigen::Matrix3d error_weight(FitMethod method, const Point& x, const ClosestPoint& foot, const FootFrame& frame);

}  // namespace stencil_runtime::fitting
