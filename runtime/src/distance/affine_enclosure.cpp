#include "affine_enclosure.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

namespace stencil_runtime {

namespace {

Point minus(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double length(const Point& a) { return std::sqrt(dot(a, a)); }

}  // namespace

AffineEnclosure::AffineEnclosure(const AffineParameters& parameters) : at_(parameters.at), residual_(parameters.residual) {
  // Least squares: [o u v] = P^T G (G^T G)^-1, G's rows (1, g_i). The weights
  // of point i in (o, u, v) are row i of G (G^T G)^-1.
  const Eigen::Index n = static_cast<Eigen::Index>(at_.size());
  Eigen::MatrixXd g(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) g.row(i) << 1, at_[static_cast<std::size_t>(i)][0], at_[static_cast<std::size_t>(i)][1];
  const Eigen::Matrix3d normal = g.transpose() * g;
  const Eigen::MatrixXd weights = g * normal.inverse();
  fit_.resize(at_.size());
  for (Eigen::Index i = 0; i < n; ++i) fit_[static_cast<std::size_t>(i)] = {weights(i, 0), weights(i, 1), weights(i, 2)};
}

double AffineEnclosure::lower_bound(const std::vector<Point>& points, const Point& q) const {
  Point o{0, 0, 0}, u{0, 0, 0}, v{0, 0, 0};
  double magnitude = 0;
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      o[k] += fit_[i][0] * points[i][k], u[k] += fit_[i][1] * points[i][k], v[k] += fit_[i][2] * points[i][k];
      magnitude = std::max(magnitude, std::fabs(points[i][k]));
    }
  double spread = 0;  // max_i |P_i - L(g_i)|
  for (std::size_t i = 0; i < points.size(); ++i) {
    Point e{};
    for (int k = 0; k < 3; ++k) e[k] = points[i][k] - (o[k] + at_[i][0] * u[k] + at_[i][1] * v[k]);
    spread = std::max(spread, length(e));
  }
  // The reproduction's residual moves L(x) by at most (|u| + |v| + |o|) times
  // it; the arithmetic here rounds by a few units in the last place of the points.
  spread += residual_ * (length(u) + length(v) + length(o)) + 64 * std::numeric_limits<double>::epsilon() * magnitude;
  const Point a = o, b{o[0] + u[0], o[1] + u[1], o[2] + u[2]}, d{o[0] + v[0], o[1] + v[1], o[2] + v[2]},
              c{b[0] + v[0], b[1] + v[1], b[2] + v[2]};
  const double to_square = std::min(point_triangle_distance(q, a, b, c), point_triangle_distance(q, a, c, d));
  return to_square - spread;
}

double point_triangle_distance(const Point& q, const Point& a, const Point& b, const Point& c) {
  // The nearest point by the triangle's Voronoi regions (vertices, edges, interior).
  const Point ab = minus(b, a), ac = minus(c, a), ap = minus(q, a);
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return length(ap);
  const Point bp = minus(q, b);
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return length(bp);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double t = d1 / (d1 - d3);
    return length(minus(ap, Point{t * ab[0], t * ab[1], t * ab[2]}));
  }
  const Point cp = minus(q, c);
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return length(cp);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double t = d2 / (d2 - d6);
    return length(minus(ap, Point{t * ac[0], t * ac[1], t * ac[2]}));
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    const Point bc = minus(c, b);
    return length(minus(bp, Point{t * bc[0], t * bc[1], t * bc[2]}));
  }
  const double denominator = va + vb + vc;
  if (!(std::fabs(denominator) > 0)) return std::min({length(ap), length(bp), length(cp)});  // degenerate
  const double v = vb / denominator, w = vc / denominator;
  const Point nearest{a[0] + ab[0] * v + ac[0] * w, a[1] + ab[1] * v + ac[1] * w, a[2] + ab[2] * v + ac[2] * w};
  return length(minus(q, nearest));
}

}  // namespace stencil_runtime
