#include "fitting/foot_frame.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

#include "distance/point_ops.hpp"
#include "stencil_runtime/error.hpp"

namespace stencil_runtime::fitting {

using namespace point_ops;

namespace {

// An orthonormal tangent pair for a unit normal.
void tangent_pair(const Point& n, Point& a, Point& b) {
  const Point axis = std::abs(n[0]) < 0.6 ? Point{1, 0, 0} : Point{0, 1, 0};
  a = cross(n, axis);
  const double l = length(a);
  for (double& x : a) x /= l;
  b = cross(n, a);
}

// Principal curvatures and directions from the second fundamental form
// expressed in the orthonormal tangent pair (a, b).
FootFrame principal(const Point& normal, const Point& a, const Point& b, const Eigen::Matrix2d& second) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(second);
  FootFrame frame;
  frame.normal = normal;
  frame.k1 = eigen.eigenvalues()[0];
  frame.k2 = eigen.eigenvalues()[1];
  const Eigen::Vector2d d1 = eigen.eigenvectors().col(0), d2 = eigen.eigenvectors().col(1);
  for (int k = 0; k < 3; ++k) {
    frame.t1[k] = d1[0] * a[k] + d1[1] * b[k];
    frame.t2[k] = d2[0] * a[k] + d2[1] * b[k];
  }
  return frame;
}

FootFrame exact_frame(const SecondDerivatives& s, const Point& normal) {
  Point a, b;
  tangent_pair(normal, a, b);
  // A tangent vector t has parameter coordinates C t with C = (J^T J)^-1 J^T,
  // J = [du dv]; the second fundamental form in (a, b) is C^T II C.
  Eigen::Matrix<double, 3, 2> J;
  for (int k = 0; k < 3; ++k) J(k, 0) = s.du[k], J(k, 1) = s.dv[k];
  Eigen::Matrix<double, 3, 2> B;
  for (int k = 0; k < 3; ++k) B(k, 0) = a[k], B(k, 1) = b[k];
  const Eigen::Matrix2d C = (J.transpose() * J).ldlt().solve(J.transpose() * B);
  Eigen::Matrix2d II;
  II(0, 0) = dot(s.duu, normal);
  II(0, 1) = II(1, 0) = dot(s.duv, normal);
  II(1, 1) = dot(s.dvv, normal);
  return principal(normal, a, b, C.transpose() * II * C);
}

FootFrame estimated_frame(const Surface& surface, const ClosestPoint& foot, double tolerance) {
  constexpr double h = 1.0 / 8;
  const FaceDomain domain = surface.topology().domain(foot.face);
  // The sub-face's own coordinates and the map back to the face's.
  double su = foot.u, sv = foot.v, u0 = 0, v0 = 0, scale = 1;
  if (domain.kind == FaceDomain::Kind::QuadSubfaces) {
    const int s = domain.subface(foot.u, foot.v, su, sv);
    u0 = s % domain.u_tiles, v0 = s / domain.u_tiles, scale = 0.5;
  }
  double cu = std::clamp(std::round(su / h), 1.0, 1 / h - 1) * h;
  double cv = std::clamp(std::round(sv / h), 1.0, 1 / h - 1) * h;
  if (domain.kind == FaceDomain::Kind::Triangle)  // the 3 x 3 samples inside the triangle u + v <= 1
    while (cu + cv > 1 - 2 * h) (cu > cv ? cu : cv) -= h;
  Point a, b;
  tangent_pair(foot.normal, a, b);
  Eigen::Matrix<double, 9, 5> A;
  Eigen::Matrix<double, 9, 1> z;
  int row = 0;
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i, ++row) {
      const double u = u0 + scale * (cu + i * h), v = v0 + scale * (cv + j * h);
      const Point d = minus(surface.evaluate(foot.face, u, v, tolerance).point, foot.point);
      const double x = dot(d, a), y = dot(d, b);
      A.row(row) << x * x, x * y, y * y, x, y;
      z[row] = dot(d, foot.normal);
    }
  const Eigen::Matrix<double, 5, 1> q = A.colPivHouseholderQr().solve(z);
  Eigen::Matrix2d II;
  II << 2 * q[0], q[1], q[1], 2 * q[2];
  if (!II.allFinite()) II.setZero();
  return principal(foot.normal, a, b, II);
}

}  // namespace

bool has_second_derivatives(const Surface& surface) { return surface.topology().tables().polynomial_regular(); }

FootFrame foot_frame(const Surface& surface, const ClosestPoint& foot, bool exact_second_derivatives, double tolerance) {
  if (exact_second_derivatives) {
    try {
      return exact_frame(surface.second_derivatives(foot.face, foot.u, foot.v), foot.normal);
    } catch (const EvaluationError&) {
      // the foot is an extraordinary vertex: no parametric derivatives there
    }
  }
  return estimated_frame(surface, foot, tolerance);
}

}  // namespace stencil_runtime::fitting
