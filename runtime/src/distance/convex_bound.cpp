#include "convex_bound.hpp"
#include "distance/point_ops.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace stencil_runtime {

using namespace point_ops;

namespace {

// Newton steps at most, halvings of a step that does not come nearer, and the
// step (in the unit frame) below which Newton has converged.
constexpr int kNewtonSteps = 8;
constexpr int kHalvings = 12;
constexpr double kConverged = 1e-13;

double factorial(int n) {
  double f = 1;
  for (int k = 2; k <= n; ++k) f *= k;
  return f;
}
double binomial(int n, int k) { return k < 0 || k > n ? 0.0 : factorial(n) / (factorial(k) * factorial(n - k)); }

// The smallest eigenvalue of [[a, b], [b, c]].
double smallest_eigenvalue(double a, double b, double c) {
  return 0.5 * (a + c) - std::sqrt(0.25 * (a - c) * (a - c) + b * b);
}

// The derivatives whose Bernstein coefficients bound them: S, S_X, S_Y, S_XX, S_XY, S_YY.
constexpr int kOrder[6][2] = {{0, 0}, {1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}};

}  // namespace

ConvexBound::ConvexBound(const PolynomialPatch& patch) : triangle_(patch.triangle), degree_(patch.degree) {
  if (patch.monomials.empty() || patch.monomials.size() > kMaxTerms || patch.degree < 0 || patch.degree > kMaxDegree) return;  // none
  // Rows over the monomials become rows over the grid of X^e Y^f (Prepared::grid).
  const std::size_t side = static_cast<std::size_t>(degree_ + 1);
  std::vector<std::size_t> at;
  for (const auto& m : patch.monomials) {
    if (m[0] < 0 || m[1] < 0 || m[0] > degree_ || m[1] > degree_) return;  // none
    at.push_back(static_cast<std::size_t>(m[0]) + side * static_cast<std::size_t>(m[1]));
  }
  const auto sparse = [&](const std::vector<double>& row) {
    SparseRow out;
    for (std::size_t m = 0; m < row.size() && m < at.size(); ++m)
      if (row[m] != 0) out.push_back({at[m], row[m]});
    return out;
  };
  for (const auto& c : patch.coefficients) coefficients_.push_back(sparse(c));
  // Rows of Bernstein coefficients of S and its derivatives over the monomials.
  const int d = degree_;
  for (int k = 0; k < kOrders; ++k) {
    const int dx = kOrder[k][0], dy = kOrder[k][1];
    // The derivative of monomial (e, f): factor * X^(e-dx) Y^(f-dy).
    const auto derivative = [&](const std::array<int, 2>& m, int& e, int& f) {
      e = m[0] - dx, f = m[1] - dy;
      if (e < 0 || f < 0) return 0.0;
      return factorial(m[0]) / factorial(e) * factorial(m[1]) / factorial(f);
    };
    if (triangle_) {
      const int top = d - dx - dy;  // total degree of the derivative
      for (int j = 0; j <= top; ++j)
        for (int i = 0; i + j <= top; ++i) {
          std::vector<double> row;
          for (const auto& m : patch.monomials) {
            int e = 0, f = 0;
            const double factor = derivative(m, e, f);
            // X^e Y^f = sum over Bernstein B_ijk of (top-e-f)! i! j! / (top! (i-e)! (j-f)!).
            row.push_back(factor == 0 || i < e || j < f || e + f > top
                              ? 0.0
                              : factor * factorial(top - e - f) * factorial(i) * factorial(j) /
                                    (factorial(top) * factorial(i - e) * factorial(j - f)));
          }
          bernstein_[k].push_back(sparse(row));
        }
    } else {
      const int p = d - dx, r = d - dy;  // degrees along X and Y
      for (int l = 0; l <= r; ++l)
        for (int i = 0; i <= p; ++i) {
          std::vector<double> row;
          for (const auto& m : patch.monomials) {
            int e = 0, f = 0;
            const double factor = derivative(m, e, f);
            // X^e = sum_i C(i, e) / C(p, e) B_i^p(X), likewise Y^f.
            row.push_back(factor == 0 || e > i || f > l ? 0.0
                                                        : factor * binomial(i, e) / binomial(p, e) * binomial(l, f) / binomial(r, f));
          }
          bernstein_[k].push_back(sparse(row));
        }
    }
  }
  for (int k = 0; k < kOrders; ++k) {
    if (bernstein_[k].size() > kMaxTerms) return;  // none
    offset_[k + 1] = offset_[k] + bernstein_[k].size();
  }
  grid_size_ = side * side;  // last: empty() says whether the bound is there
}

ConvexBound::Jet ConvexBound::jet(const Point* grid, double X, double Y) const {
  // Horner along X for each power of Y (value and two derivatives together),
  // then the powers of Y: `grid` holds the coefficient of X^e Y^f at e + (d + 1) f.
  const int d = degree_;
  Jet j{};
  double yf = 1, yf1 = 0, yf2 = 0;  // Y^f, f Y^(f-1), f (f-1) Y^(f-2)
  for (int f = 0; f <= d; ++f) {
    const Point* row = grid + static_cast<std::size_t>((d + 1) * f);
    double v[3] = {0, 0, 0}, dv[3] = {0, 0, 0}, ddv[3] = {0, 0, 0};
    for (int e = d; e >= 0; --e)
      for (int k = 0; k < 3; ++k) {
        ddv[k] = ddv[k] * X + 2 * dv[k];
        dv[k] = dv[k] * X + v[k];
        v[k] = v[k] * X + row[e][k];
      }
    for (int k = 0; k < 3; ++k) {
      j.s[k] += v[k] * yf, j.x[k] += dv[k] * yf, j.xx[k] += ddv[k] * yf;
      j.y[k] += v[k] * yf1, j.xy[k] += dv[k] * yf1, j.yy[k] += v[k] * yf2;
    }
    // To f + 1: (Y^(f+1))' = (f+1) Y^f, (Y^(f+1))'' = (f+1) f Y^(f-1).
    yf2 = (f + 1) * yf1;
    yf1 = (f + 1) * yf;
    yf *= Y;
  }
  return j;
}

void ConvexBound::project(double& X, double& Y) const {
  // The nearest point of the frame (Euclidean).
  if (!triangle_) {
    X = std::clamp(X, 0.0, 1.0), Y = std::clamp(Y, 0.0, 1.0);
    return;
  }
  if (X >= 0 && Y >= 0 && X + Y <= 1) return;
  // The nearest of the three edges' nearest points.
  const double corners[3][2] = {{0, 0}, {1, 0}, {0, 1}};
  double best = INFINITY, bx = 0, by = 0;
  for (int e = 0; e < 3; ++e) {
    const double* a = corners[e];
    const double* b = corners[(e + 1) % 3];
    const double dx = b[0] - a[0], dy = b[1] - a[1];
    const double t = std::clamp(((X - a[0]) * dx + (Y - a[1]) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
    const double px = a[0] + t * dx, py = a[1] + t * dy;
    const double d = (px - X) * (px - X) + (py - Y) * (py - Y);
    if (d < best) best = d, bx = px, by = py;
  }
  X = bx, Y = by;
  if (X + Y > 1) Y = 1 - X;  // the hypotenuse's points, rounded, inside
}

void ConvexBound::prepare(const std::vector<Point>& points, Prepared& out, bool with_ranges) const {
  out.grid.assign(grid_size_, Point{0, 0, 0});
  for (std::size_t i = 0; i < points.size() && i < coefficients_.size(); ++i)
    for (const auto& [g, w] : coefficients_[i])
      for (int k = 0; k < 3; ++k) out.grid[g][k] += w * points[i][k];
  out.net.assign(offset_[kOrders], Point{0, 0, 0});
  for (int k = 0; k < kOrders; ++k)
    for (std::size_t row = 0; row < bernstein_[k].size(); ++row) {
      Point& v = out.net[offset_[k] + row];
      for (const auto& [g, w] : bernstein_[k][row])
        for (int c = 0; c < 3; ++c) v[c] += w * out.grid[g][c];
    }
  for (int k = 0; k < 3; ++k) {
    out.largest[k] = 0;
    for (std::size_t b = offset_[3 + k]; b < offset_[4 + k]; ++b) out.largest[k] = std::max(out.largest[k], length(out.net[b]));
  }
  out.low.clear(), out.high.clear();
  if (with_ranges) ranges(out.net.data(), out.low, out.high);
}

void ConvexBound::ranges(const Point* net, std::vector<double>& low, std::vector<double>& high) const {
  const std::size_t seconds = offset_[kOrders] - offset_[3];
  low.assign(seconds, INFINITY), high.assign(seconds, -INFINITY);
  for (std::size_t b = offset_[3]; b < offset_[kOrders]; ++b)
    for (std::size_t i = offset_[0]; i < offset_[1]; ++i) {
      const double e = dot(net[i], net[b]);
      low[b - offset_[3]] = std::min(low[b - offset_[3]], e);
      high[b - offset_[3]] = std::max(high[b - offset_[3]], e);
    }
}

void ConvexBound::certify(const Prepared& patch, const Jet& j, const Point& q, double enough, Result& out) const {
  out.convex = out.bounded = false, out.lower = 0;
  const Point r = minus(j.s, q);
  const Point* net = patch.net.data();
  const auto largest_from = [&](int k, const Point& from) {
    double most = 0;
    for (std::size_t b = offset_[k]; b < offset_[k + 1]; ++b) most = std::max(most, dot(minus(net[b], from), minus(net[b], from)));
    return std::sqrt(most);
  };
  const double Mxx = patch.largest[0], Mxy = patch.largest[1], Myy = patch.largest[2];
  // sigma_min(J) over the frame: J(x) - J(c) is at most the second
  // derivatives times the distance to the far side, and its columns lie in the
  // hulls of the S_X and S_Y coefficients less their values at c.
  const double ax = std::max(out.X, 1 - out.X), ay = std::max(out.Y, 1 - out.Y);
  const double du = std::min(Mxx * ax + Mxy * ay, largest_from(1, j.x));
  const double dv = std::min(Mxy * ax + Myy * ay, largest_from(2, j.y));
  const double sigma_c = std::sqrt(std::max(0.0, smallest_eigenvalue(dot(j.x, j.x), dot(j.x, j.y), dot(j.y, j.y))));
  const double sigma = sigma_c - std::sqrt(du * du + dv * dv);
  const double lambda_j = sigma > 0 ? sigma * sigma : 0.0;
  // r . Hess S = r_c . Hess S + (S(x) - S(c)) . Hess S over the frame: the
  // first between r_c dotted with the second derivatives' coefficients v, the
  // second between min_b (b - S(c)).v and max_b (b - S(c)).v over S's
  // coefficients b (a bilinear function of points of two hulls is extreme at
  // their vertices). S(c) lies in the hull of the b, so the second's range
  // holds 0: without it the smallest eigenvalue below can only be larger, and
  // where that is not positive already the sub-patch is not proved convex.
  double low[3] = {0, 0, 0}, high[3] = {0, 0, 0};
  const auto lambda_of = [&] {
    const double off = std::max(std::fabs(low[1]), std::fabs(high[1]));
    const double lambda_r = smallest_eigenvalue(low[0], off, low[2]);
    // A margin for rounding in all of the above: relative to the terms, and
    // absolute for the derivatives' coefficients, sums of points rounded at
    // the size of their coordinates (a deep sub-patch's second derivatives are
    // far smaller than that).
    const double scale = lambda_j + std::fabs(lambda_r) + sigma_c * sigma_c + (length(r) + length(j.s)) * (Mxx + Mxy + Myy);
    const double coefficients = 1024 * std::numeric_limits<double>::epsilon() * patch.magnitude;
    return lambda_j + lambda_r - 1e-12 * scale - coefficients * (length(r) + length(j.s) + sigma_c);
  };
  for (int k = 0; k < 3; ++k) {
    if (offset_[4 + k] == offset_[3 + k]) continue;
    low[k] = INFINITY, high[k] = -INFINITY;
    for (std::size_t b = offset_[3 + k]; b < offset_[4 + k]; ++b) {
      const double h = dot(r, net[b]);
      low[k] = std::min(low[k], h), high[k] = std::max(high[k], h);
    }
  }
  // Not convex already: the bound below, with a negative lambda, can reach
  // `enough` only where F(c) does.
  if (!(lambda_of() > 0) && !(0.5 * dot(r, r) > 0.5 * enough * enough)) return;
  // Made on first need (a search's own scratch patch; a patch shared between
  // threads is prepared with them, so this never writes to it).
  if (patch.low.empty() && offset_[kOrders] > offset_[3]) ranges(net, patch.low, patch.high);
  const std::vector<double>* range_low = &patch.low;
  const std::vector<double>* range_high = &patch.high;
  for (int k = 0; k < 3; ++k) {
    if (offset_[4 + k] == offset_[3 + k]) continue;
    low[k] = INFINITY, high[k] = -INFINITY;
    for (std::size_t b = offset_[3 + k]; b < offset_[4 + k]; ++b) {
      const double h = dot(r, net[b]), at_c = dot(j.s, net[b]);
      low[k] = std::min(low[k], h + (*range_low)[b - offset_[3]] - at_c);
      high[k] = std::max(high[k], h + (*range_high)[b - offset_[3]] - at_c);
    }
  }
  const double lambda = lambda_of();
  // F(x) >= F(c) + g.t + lambda/2 |t|^2 with t = x - c (g = grad F(c)), for
  // every x of the frame, whatever lambda's sign.
  const double gx = dot(r, j.x), gy = dot(r, j.y);
  double lower = 0.5 * dot(r, r);
  if (lambda > 0) {
    // Strongly convex: = F(c) + lambda/2 |x - c + g/lambda|^2 - |g|^2/(2
    // lambda), smallest at the frame's point nearest c - g/lambda.
    out.convex = true;
    double X = out.X - gx / lambda, Y = out.Y - gy / lambda;
    project(X, Y);
    const double tx = X - out.X, ty = Y - out.Y;
    lower += gx * tx + gy * ty + 0.5 * lambda * (tx * tx + ty * ty);
  } else {
    // Concave in t: smallest at a corner of the frame.
    const double corners[4][2] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
    double least = INFINITY;
    for (int k = 0; k < (triangle_ ? 3 : 4); ++k) {
      const double tx = corners[k][0] - out.X, ty = corners[k][1] - out.Y;
      least = std::min(least, gx * tx + gy * ty + 0.5 * lambda * (tx * tx + ty * ty));
    }
    lower += least;
  }
  out.bounded = true;
  // The rounding of F itself (r from points rounded at the size of the coordinates).
  const double coordinates = std::max({std::fabs(q[0]), std::fabs(q[1]), std::fabs(q[2]), std::fabs(j.s[0]), std::fabs(j.s[1]),
                                       std::fabs(j.s[2])});
  out.lower = std::max(0.0, std::sqrt(2 * std::max(0.0, lower)) - 64 * std::numeric_limits<double>::epsilon() * coordinates);
}

ConvexBound::Result ConvexBound::bound(const Prepared& patch, const Point& q, double enough) const {
  Result out;
  out.X = out.Y = triangle_ ? 1.0 / 3 : 0.5;
  Jet j = jet(patch.grid.data(), out.X, out.Y);
  certify(patch, j, q, enough, out);
  out.point = j.s, out.distance = length(minus(j.s, q));
  if (out.bounded && out.lower >= enough) return out;  // settled at the centre
  // Where F is not convex at the centre, Newton only looks for a nearer
  // point for the search's best (the sub-patch will be split anyway): a few steps.
  const bool convex_here = out.convex;
  if (newton(patch, q, convex_here ? kNewtonSteps : 2, convex_here ? kHalvings : 3, out, j)) certify(patch, j, q, enough, out);
  return out;
}

ConvexBound::Result ConvexBound::polish(const Prepared& patch, const Point& q, double X, double Y) const {
  Result out;
  out.X = X, out.Y = Y;
  project(out.X, out.Y);
  Jet j = jet(patch.grid.data(), out.X, out.Y);
  newton(patch, q, kNewtonSteps, kHalvings, out, j);
  out.point = j.s, out.distance = length(minus(j.s, q));
  return out;
}

bool ConvexBound::newton(const Prepared& patch, const Point& q, int steps, int halvings, Result& out, Jet& j) const {
  // Damped Newton on F, each step projected onto the frame.
  const Point* grid = patch.grid.data();
  Point r = minus(j.s, q);
  double F = 0.5 * dot(r, r);
  bool moved_at_all = false;
  for (int step = 0; step < steps; ++step) {
    const double gx = dot(r, j.x), gy = dot(r, j.y);
    const double a = dot(j.x, j.x), b = dot(j.x, j.y), c = dot(j.y, j.y);
    double hxx = a + dot(r, j.xx), hxy = b + dot(r, j.xy), hyy = c + dot(r, j.yy);
    if (!(hxx > 0 && hxx * hyy - hxy * hxy > 0)) hxx = a, hxy = b, hyy = c;  // Gauss-Newton where F is not convex here
    const double det = hxx * hyy - hxy * hxy;
    if (!(det > 0)) break;
    double sx = -(hyy * gx - hxy * gy) / det, sy = -(hxx * gy - hxy * gx) / det;
    // The sides the point is on that the descent would leave by (their
    // multipliers are positive) are held, and Newton runs along what is left:
    // so that Newton ends at the constrained minimum, where the bound
    // is the distance. At a corner held by two sides it is there.
    const bool hold_x = (out.X <= 0 && gx > 0) || (!triangle_ && out.X >= 1 && gx < 0);
    const bool hold_y = (out.Y <= 0 && gy > 0) || (!triangle_ && out.Y >= 1 && gy < 0);
    const bool hold_h = triangle_ && out.X + out.Y >= 1 - 4 * std::numeric_limits<double>::epsilon() && gx + gy < 0;  // project() rounds
    if (int(hold_x) + int(hold_y) + int(hold_h) >= 2) break;
    if (hold_x) sx = 0, sy = hyy > 0 ? -gy / hyy : 0.0;
    if (hold_y) sy = 0, sx = hxx > 0 ? -gx / hxx : 0.0;
    if (hold_h) {  // along the hypotenuse, direction (1, -1)
      const double h = hxx - 2 * hxy + hyy;
      const double along = h > 0 ? -(gx - gy) / h : 0.0;
      sx = along, sy = -along;
    }
    bool moved = false;
    double t = 1;
    for (int halving = 0; halving <= halvings; ++halving, t *= 0.5) {
      double X = out.X + t * sx, Y = out.Y + t * sy;
      project(X, Y);
      if (X == out.X && Y == out.Y) break;
      const Jet n = jet(grid, X, Y);
      const Point nr = minus(n.s, q);
      const double nF = 0.5 * dot(nr, nr);
      // Nearer; or, where F no longer changes beyond its rounding, with a
      // gradient at least halved (near the minimum F resolves the point only
      // to the square root of its precision, the gradient to its precision).
      const double ngx = dot(nr, n.x), ngy = dot(nr, n.y);
      const bool flatter = nF <= F * (1 + 8 * std::numeric_limits<double>::epsilon()) &&
                           ngx * ngx + ngy * ngy < 0.25 * (gx * gx + gy * gy);
      if (nF < F || flatter) {
        moved = std::fabs(X - out.X) + std::fabs(Y - out.Y) > kConverged;
        moved_at_all = true;
        out.X = X, out.Y = Y, j = n, r = nr, F = nF;
        break;
      }
    }
    if (!moved) break;
  }
  out.point = j.s, out.distance = std::sqrt(2 * F);
  return moved_at_all;
}

}  // namespace stencil_runtime
