#include "affine_enclosure.hpp"
#include "distance/point_ops.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

namespace stencil_runtime {

using namespace point_ops;

AffineEnclosure::AffineEnclosure(const AffineParameters& parameters)
    : at_(parameters.at), residual_(parameters.residual), triangle_(parameters.triangle) {
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

namespace {

double point_segment_distance(const Point& q, const Point& a, const Point& b) {
  const Point ab = minus(b, a), aq = minus(q, a);
  const double len2 = dot(ab, ab);
  const double t = len2 > 0 ? std::clamp(dot(aq, ab) / len2, 0.0, 1.0) : 0.0;
  return length(minus(aq, Point{t * ab[0], t * ab[1], t * ab[2]}));
}

}  // namespace

AffineEnclosure::Slab AffineEnclosure::slab(const std::vector<Point>& points) const {
  Slab out;
  Point o{0, 0, 0}, u{0, 0, 0}, v{0, 0, 0};
  double magnitude = 0;
  const std::size_t n = points.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point& p = points[i];
    const auto& w = fit_[i];
    for (int k = 0; k < 3; ++k) o[k] += w[0] * p[k], u[k] += w[1] * p[k], v[k] += w[2] * p[k];
    magnitude = std::max({magnitude, std::fabs(p[0]), std::fabs(p[1]), std::fabs(p[2])});
  }
  // The residuals E_i = P_i - L(g_i), split along the parallelogram's unit
  // normal m (their range [low, high]) and across it (the largest length).
  // The surface lies in L([0,1]^2) + hull(E_i), so in the slab of the
  // parallelogram grown by `across` in its plane and by [low, high] along m.
  const Point m0 = cross(u, v);
  const double m_len = length(m0);
  out.flat = m_len > 1e-12 * (length(u) * length(v));
  out.m = out.flat ? Point{m0[0] / m_len, m0[1] / m_len, m0[2] / m_len} : Point{0, 0, 0};
  double low = 0, high = 0, across2 = 0;
  for (std::size_t i = 0; i < n; ++i) {
    Point e{};
    for (int k = 0; k < 3; ++k) e[k] = points[i][k] - (o[k] + at_[i][0] * u[k] + at_[i][1] * v[k]);
    const double h = dot(e, out.m);
    low = std::min(low, h), high = std::max(high, h);
    across2 = std::max(across2, dot(e, e) - h * h);
  }
  // The reproduction's residual moves L(x) by at most (|u| + |v| + |o|) times
  // it; the arithmetic here rounds by a few units in the last place of the points.
  const double slack = residual_ * (length(u) + length(v) + length(o)) + 64 * std::numeric_limits<double>::epsilon() * magnitude;
  out.across = std::sqrt(std::max(across2, 0.0)) + slack;
  out.low = low - slack, out.high = high + slack;
  out.o = o, out.u = u, out.v = v;
  out.uu = dot(u, u), out.uv = dot(u, v), out.vv = dot(v, v);
  return out;
}

std::array<Point, 2> AffineEnclosure::box(const Slab& slab) const {
  // The image's corners, each grown by the in-plane spread (a ball of radius
  // `across`) and by the normal range; where L is degenerate, by the ball
  // lower_bound() takes then.
  const double along = slab.flat ? 0.0 : std::hypot(slab.across, std::max(-slab.low, slab.high));
  std::array<Point, 2> out{Point{INFINITY, INFINITY, INFINITY}, Point{-INFINITY, -INFINITY, -INFINITY}};
  const int corners = triangle_ ? 3 : 4;
  const double cu[4] = {0, 1, 0, 1}, cv[4] = {0, 0, 1, 1};
  for (int c = 0; c < corners; ++c)
    for (int k = 0; k < 3; ++k) {
      const double p = slab.o[k] + cu[c] * slab.u[k] + cv[c] * slab.v[k];
      const double lo = std::min(slab.low * slab.m[k], slab.high * slab.m[k]), hi = std::max(slab.low * slab.m[k], slab.high * slab.m[k]);
      out[0][k] = std::min(out[0][k], p + lo - slab.across - along);
      out[1][k] = std::max(out[1][k], p + hi + slab.across + along);
    }
  return out;
}

double AffineEnclosure::lower_bound(const Slab& slab, const Point& q) const {
  const Point &o = slab.o, &u = slab.u, &v = slab.v, &m = slab.m;
  // L's image of the unit domain: the parallelogram a b c d, or the triangle a b d.
  const Point a = o, b{o[0] + u[0], o[1] + u[1], o[2] + u[2]}, d{o[0] + v[0], o[1] + v[1], o[2] + v[2]},
              c{b[0] + v[0], b[1] + v[1], b[2] + v[2]};
  if (!slab.flat) {  // a degenerate image: the ball around it
    const double spread = std::hypot(slab.across, std::max(-slab.low, slab.high));
    const double image = triangle_ ? point_triangle_distance(q, a, b, d)
                                   : std::min(point_triangle_distance(q, a, b, c), point_triangle_distance(q, a, c, d));
    return image - spread;
  }
  // q's height above the plane, and its foot's distance in the plane from the parallelogram.
  const Point w = minus(q, o);
  const double height = dot(w, m);
  const double upwards = height > slab.high ? height - slab.high : (height < slab.low ? slab.low - height : 0.0);
  const Point foot{q[0] - height * m[0], q[1] - height * m[1], q[2] - height * m[2]};
  const double fu = dot(minus(foot, o), u), fv = dot(minus(foot, o), v);
  const double det = slab.uu * slab.vv - slab.uv * slab.uv;
  const double s = (slab.vv * fu - slab.uv * fv) / det, t = (slab.uu * fv - slab.uv * fu) / det;
  double in_plane = 0;
  if (triangle_) {
    if (!(s >= 0 && t >= 0 && s + t <= 1))
      in_plane = std::min({point_segment_distance(foot, a, b), point_segment_distance(foot, b, d), point_segment_distance(foot, d, a)});
  } else if (!(s >= 0 && s <= 1 && t >= 0 && t <= 1)) {
    in_plane = std::min({point_segment_distance(foot, a, b), point_segment_distance(foot, b, c), point_segment_distance(foot, c, d),
                         point_segment_distance(foot, d, a)});
  }
  const double sideways = std::max(in_plane - slab.across, 0.0);
  return std::sqrt(sideways * sideways + upwards * upwards);
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
