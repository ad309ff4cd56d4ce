#include "fitting/error_model.hpp"

#include <algorithm>

#include "distance/point_ops.hpp"

namespace stencil_runtime::fitting {

namespace {

Eigen::Vector3d vec(const Point& p) { return {p[0], p[1], p[2]}; }

double tangential_weight(double d, double k) {
  const double dk = d * k;
  if (dk == 1) return 1;
  return std::clamp(dk / (dk - 1), 0.0, 1.0);
}

}  // namespace

Eigen::Matrix3d error_weight(FitMethod method, const Point& x, const ClosestPoint& foot, const FootFrame& frame) {
  if (method == FitMethod::PointDistance) return Eigen::Matrix3d::Identity();
  const Eigen::Vector3d n = vec(foot.normal);
  Eigen::Matrix3d m = n * n.transpose();
  if (method == FitMethod::TangentDistance) return m;
  const double d = point_ops::dot(point_ops::minus(x, foot.point), foot.normal);
  const Eigen::Vector3d t1 = vec(frame.t1), t2 = vec(frame.t2);
  m += tangential_weight(d, frame.k1) * t1 * t1.transpose() + tangential_weight(d, frame.k2) * t2 * t2.transpose();
  return m;
}

}  // namespace stencil_runtime::fitting
