#include "triangle_descent.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "family/parameter_ops.hpp"
#include "family/recentre.hpp"
#include "tables/monomial_jet.hpp"

namespace stencil_runtime {

namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
// Levels of descent: 2^-64 (Loop) or 3^-64 (sqrt(3)) of a patch is far below
// any tolerance a double can express.
constexpr int kMaxLevels = 64;

double norm(const Point& a, const Point& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

Point combine(const double* w, const std::vector<Point>& q) {
  Point p{0, 0, 0};
  for (std::size_t h = 0; h < q.size(); ++h)
    for (std::size_t k = 0; k < 3; ++k) p[k] += w[h] * q[h][k];
  return p;
}

// The stored grid holding (x, y) exactly: the smallest rate n whose 1/(3n)
// grid holds both coordinates as a node (both = 0 mod 3), an up centre (1) or a down centre (2).
bool held(const TriangleTables& t, const Fraction& x, const Fraction& y, int& n, std::int64_t& a, std::int64_t& b) {
  for (int rate : t.rates()) {
    const std::int64_t g = 3 * static_cast<std::int64_t>(rate);
    if (g % x.den != 0 || g % y.den != 0) continue;
    a = x.num * (g / x.den), b = y.num * (g / y.den);
    if (a % 3 != b % 3) continue;
    n = rate;
    return true;
  }
  return false;
}
bool held(const TriangleTables&, double, double, int&, std::int64_t&, std::int64_t&) { return false; }

// floor(m x), clamped to [0, hi].
template <class P>
int scaled_floor(const P& x, int m, int hi) {
  int a = 0;
  while (a < hi && compare(multiply(x, m), integer<P>(a + 1)) >= 0) ++a;
  return a;
}

// The cell of the m^2 split (docs/table-format.md) that holds (x, y); x, y
// become the cell's own parameter.
template <class P>
int cell_of(P& x, P& y, int m) {
  const int a = scaled_floor(x, m, m - 1);
  const int b = scaled_floor(y, m, m - 1 - a);
  const P fx = scale_minus(x, m, a), fy = scale_minus(y, m, b);
  if (a + b <= m - 2 && compare(add(fx, fy), integer<P>(1)) > 0) {  // the down cell (a, b)
    x = subtract(add(fx, fy), integer<P>(1));
    y = from(1, fx);
    return m * (m + 1) / 2 + b * (m - 1) - b * (b - 1) / 2 + a;
  }
  x = fx, y = fy;
  return b * m - b * (b - 1) / 2 + a;
}

// A cell's parameter in the parameter of its kind (the cell's corner `rotation` at the kind's corner 0).
template <class P>
void to_kind(P& x, P& y, int rotation) {
  const P w = subtract(subtract(integer<P>(1), x), y);
  if (rotation == 1) x = y, y = w;
  else if (rotation == 2) y = x, x = w;
}

}  // namespace

TrianglePatchDescent::TrianglePatchDescent(const TriangleTables& tables) : tables_(tables) {
  if (!tables.has_descent())
    throw EvaluationError("these triangle tables hold no patch subdivision (version 2 .sgt from an older stencilgen): "
                          "evaluation at parameters they do not hold needs tables from this stencilgen");
}

Point TrianglePatchDescent::polynomial(const std::vector<Point>& q, double x, double y) const {
  const int d = tables_.polynomial_degree();
  const std::size_t terms = static_cast<std::size_t>((d + 1) * (d + 2) / 2);
  const MonomialJet m(d, x, y);
  const std::vector<double>& c = tables_.polynomial();
  Point out{0, 0, 0};
  for (std::size_t h = 0; h < q.size(); ++h) {
    double w = 0;
    for (std::size_t k = 0; k < terms; ++k) w += c[h * terms + k] * m.value[k];
    for (std::size_t k = 0; k < 3; ++k) out[k] += w * q[h][k];
  }
  return out;
}

Approximation TrianglePatchDescent::nearest_sample(int valence, int region, const std::vector<Point>& q, double x,
                                                   double y, double& sx, double& sy) const {
  // The finest grid's node, up centre and down centre nearest to (x, y), evaluated exactly.
  const int n = tables_.rates().back();
  const TriangleTables::Grid grid = tables_.grid(valence, n, region);
  const long i0 = std::clamp(static_cast<long>(std::floor(x * n)), 0L, static_cast<long>(n - 1));
  const long j0 = std::clamp(static_cast<long>(std::floor(y * n)), 0L, static_cast<long>(n - 1) - i0);
  struct Candidate {
    TriangleTables::GridPoint kind;
    long i, j;
    double x, y;
  };
  const double g = 3.0 * n;
  Candidate best{TriangleTables::GridPoint::Up, i0, j0, (3 * i0 + 1) / g, (3 * j0 + 1) / g};
  const auto squared = [&](const Candidate& c) { return (c.x - x) * (c.x - x) + (c.y - y) * (c.y - y); };
  auto consider = [&](const Candidate& c) {
    if (squared(c) < squared(best)) best = c;
  };
  if (i0 + j0 <= n - 2) consider({TriangleTables::GridPoint::Down, i0, j0, (3 * i0 + 2) / g, (3 * j0 + 2) / g});
  for (long dj = 0; dj <= 1; ++dj)
    for (long di = 0; di <= 1; ++di)
      if (i0 + di + j0 + dj <= n)
        consider({TriangleTables::GridPoint::Node, i0 + di, j0 + dj, static_cast<double>(i0 + di) / n, static_cast<double>(j0 + dj) / n});
  Approximation out;
  out.exact = false;
  out.point = combine(grid.weights(best.kind, best.i, best.j), q);
  // The limit over the patch lies in the hull of its control points (every weight is non-negative).
  for (const Point& p : q) out.bound = std::max(out.bound, norm(p, out.point));
  sx = best.x, sy = best.y;
  return out;
}

double TrianglePatchDescent::common_cell_bound(int valence, int region, std::vector<Point> q, double x, double y, double sx,
                                               double sy, const Point& at, double bound) const {
  const int m = tables_.dilation();
  // A few levels below the grid's spacing are enough: x and s part within them.
  int levels = 2;
  for (long g = 3L * tables_.rates().back(); g > 1; g /= m) ++levels;
  std::vector<Point> next;
  double rounding = 0;
  for (int level = 0; level < levels; ++level) {
    double cx = x, cy = y;
    const int c = cell_of(cx, cy, m);
    // s in the same cell's coordinates (the cell's affine map), inside its closure?
    double tx = sx, ty = sy;
    const int a = c < m * (m + 1) / 2 ? 0 : 1;  // 1: a down cell
    {
      int idx = a ? c - m * (m + 1) / 2 : c, row = 0, width = a ? m - 1 : m;
      while (idx >= width) idx -= width, --width, ++row;
      const double fx = m * sx - idx, fy = m * sy - row;
      if (a) tx = fx + fy - 1, ty = 1 - fx;
      else tx = fx, ty = fy;
    }
    constexpr double slack = 1e-12;
    if (tx < -slack || ty < -slack || tx + ty > 1 + slack) break;
    const TriangleChild& child = tables_.children(valence, region)[static_cast<std::size_t>(c)];
    rounding += apply(child.rows, q, next);
    to_kind(cx, cy, child.rotation);
    to_kind(tx, ty, child.rotation);
    valence = child.valence, region = child.region;
    q.swap(next);
    x = cx, y = cy, sx = tx, sy = ty;
    double hull = 0;
    for (const Point& p : q) hull = std::max(hull, norm(p, at));
    bound = std::min(bound, hull + rounding + 4 * kEpsilon * largest_magnitude(q));
  }
  return bound;
}

template <class P>
Approximation TrianglePatchDescent::evaluate(int valence, int region, std::vector<Point>& q, P x, P y, double tolerance) const {
  const int m = tables_.dilation();
  double rounding = 0;
  std::vector<Point> next;
  for (int level = 0;; ++level) {
    int n = 0;
    std::int64_t a = 0, b = 0;
    if (held(tables_, x, y, n, a, b)) {  // exact from the tables
      const auto kind = static_cast<TriangleTables::GridPoint>(a % 3);
      return {combine(tables_.grid(valence, n, region).weights(kind, a / 3, b / 3), q), 0.0, true};
    }
    const bool polynomial_scheme = tables_.polynomial_degree() > 0;
    if (valence == 6 && polynomial_scheme) return {polynomial(q, to_real(x), to_real(y)), 0.0, true};
    // A polynomial scheme descends until the cell is regular, and stops with a
    // bound only within m^-64 of the EV.
    if (!polynomial_scheme || level == kMaxLevels) {
      if (!tables_.children_nonnegative())
      throw EvaluationError("this scheme's subdivision has negative weights, so evaluation between the parameters its "
                            "tables hold has no bound; give exact rationals the tables hold");
      // The bound below is max_j |P_j - f(s)|, at least half of max_j |P_j - P_0|: while that
      // exceeds twice the tolerance the cell is too large, and the sample need not be evaluated.
      double spread = 0;
      for (const Point& p : q) spread = std::max(spread, norm(p, q[0]));
      if (spread <= 2 * tolerance || level == kMaxLevels) {
        double sx = 0, sy = 0;
        Approximation approx = nearest_sample(valence, region, q, to_real(x), to_real(y), sx, sy);
        approx.bound += rounding + 4 * kEpsilon * largest_magnitude(q);
        if (approx.bound <= tolerance || level == kMaxLevels) {
          approx.bound = common_cell_bound(valence, region, q, to_real(x), to_real(y), sx, sy, approx.point, approx.bound - rounding) + rounding;
          return approx;
        }
      }
    }
    const int c = cell_of(x, y, m);
    const TriangleChild& child = tables_.children(valence, region)[static_cast<std::size_t>(c)];
    rounding += apply(child.rows, q, next);
    to_kind(x, y, child.rotation);
    valence = child.valence, region = child.region;
    q.swap(next);
  }
}

void TrianglePatchDescent::require_polynomial() const {
  if (tables_.polynomial_degree() <= 0)
    throw EvaluationError("this triangle scheme's regular patch is not a polynomial (sqrt(3)): its derivatives are "
                          "exact at the parameters its tables hold (exact rationals), and it has no second derivatives "
                          "here; at other real parameters it has none");
}

template <class P>
void TrianglePatchDescent::descend_to_regular(int& valence, int& region, std::vector<Point>& q, P& x, P& y, Point& offset) const {
  const int m = tables_.dilation();
  std::vector<Point> next;
  for (int level = 0; valence != 6; ++level) {
    if (level == kMaxLevels)
      throw EvaluationError("the parameter is an extraordinary vertex (or within 2^-64 of one): no parametric "
                            "derivative there");
    recentre(q, offset);  // each level's differences rounded at their own size (family/recentre.hpp)
    const int c = cell_of(x, y, m);
    const TriangleChild& child = tables_.children(valence, region)[static_cast<std::size_t>(c)];
    apply(child.rows, q, next);
    to_kind(x, y, child.rotation);
    valence = child.valence, region = child.region;
    q.swap(next);
  }
}

SecondDerivatives TrianglePatchDescent::regular_derivatives(const std::vector<Point>& q, const Dual& x, const Dual& y) const {
  // The regular cell's polynomial and its partials in the cell's (X, Y), then
  // the chain rule through the affine map (u, v) -> (X, Y): X_u = x.du, X_v =
  // x.dv, Y_u = y.du, Y_v = y.dv, and no second-order terms.
  const int d = tables_.polynomial_degree();
  const std::size_t terms = static_cast<std::size_t>((d + 1) * (d + 2) / 2);
  const std::vector<double>& coefficients = tables_.polynomial();
  const MonomialJet m(d, x.value, y.value);
  const double xu = x.du, xv = x.dv, yu = y.du, yv = y.dv;
  SecondDerivatives out;
  for (std::size_t h = 0; h < q.size(); ++h) {
    double w = 0, wx = 0, wy = 0, wxx = 0, wxy = 0, wyy = 0;
    for (std::size_t k = 0; k < terms; ++k) {
      const double c = coefficients[h * terms + k];
      w += c * m.value[k], wx += c * m.dx[k], wy += c * m.dy[k];
      wxx += c * m.dxx[k], wxy += c * m.dxy[k], wyy += c * m.dyy[k];
    }
    const double wu = wx * xu + wy * yu, wv = wx * xv + wy * yv;
    const double wuu = wxx * xu * xu + 2 * wxy * xu * yu + wyy * yu * yu;
    const double wuv = wxx * xu * xv + wxy * (xu * yv + xv * yu) + wyy * yu * yv;
    const double wvv = wxx * xv * xv + 2 * wxy * xv * yv + wyy * yv * yv;
    for (std::size_t k = 0; k < 3; ++k) {
      out.point[k] += w * q[h][k];
      out.du[k] += wu * q[h][k];
      out.dv[k] += wv * q[h][k];
      out.duu[k] += wuu * q[h][k];
      out.duv[k] += wuv * q[h][k];
      out.dvv[k] += wvv * q[h][k];
    }
  }
  return out;
}

Derivatives TrianglePatchDescent::derivatives(int valence, int region, std::vector<Point>& q, Dual x, Dual y) const {
  return second_derivatives(valence, region, q, x, y);  // computed together
}

SecondDerivatives TrianglePatchDescent::second_derivatives(int valence, int region, std::vector<Point>& q, Dual x, Dual y) const {
  require_polynomial();
  Point offset{0, 0, 0};
  descend_to_regular(valence, region, q, x, y, offset);
  SecondDerivatives out = regular_derivatives(q, x, y);
  for (std::size_t k = 0; k < 3; ++k) out.point[k] += offset[k];
  return out;
}

Derivatives TrianglePatchDescent::derivatives(int valence, int region, std::vector<Point>& q, ExactDual x, ExactDual y) const {
  if (tables_.polynomial_degree() > 0)
    return derivatives(valence, region, q, Dual{to_real(x), x.du, x.dv}, Dual{to_real(y), y.du, y.dv});
  std::string at("(");  // appended: GCC 12 warns falsely (-Wrestrict) on "(" + string here
  at += x.value.str(), at += ", ", at += y.value.str(), at += ")";
  Point offset{0, 0, 0};
  descend_to_regular(valence, region, q, x, y, offset);
  int n = 0;
  std::int64_t a = 0, b = 0;
  if (!held(tables_, x.value, y.value, n, a, b))
    throw OffGridDerivative("the patch parameter " + at + " reaches the regular point (" + x.value.str() + ", " +
                          y.value.str() + "), which no stored rate holds: this scheme's derivatives (sqrt(3)) are exact "
                          "only at parameters on the grids of its tables' rates");
  const TriangleTables::Grid grid = tables_.grid(6, n, 0);
  const auto kind = static_cast<TriangleTables::GridPoint>(a % 3);
  const double *wu = nullptr, *wv = nullptr;
  if (!grid.derivative_weights(kind, a / 3, b / 3, wu, wv))
    throw EvaluationError("these sqrt(3) tables hold no derivative stencils (.sgt from before version 6): regenerate "
                          "them with this stencilgen");
  // Along the regular cell's (X, Y), then the chain rule through the affine
  // map (u, v) -> (X, Y) that the duals carry.
  const Point dX = combine(wu, q), dY = combine(wv, q);
  Derivatives out;
  out.point = combine(grid.weights(kind, a / 3, b / 3), q);
  for (std::size_t k = 0; k < 3; ++k) {
    out.point[k] += offset[k];
    out.du[k] = x.du * dX[k] + y.du * dY[k];
    out.dv[k] = x.dv * dX[k] + y.dv * dY[k];
  }
  return out;
}

template Approximation TrianglePatchDescent::evaluate<Fraction>(int, int, std::vector<Point>&, Fraction, Fraction, double) const;
template Approximation TrianglePatchDescent::evaluate<double>(int, int, std::vector<Point>&, double, double, double) const;

}  // namespace stencil_runtime
