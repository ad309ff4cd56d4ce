#include "patch_descent.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "curve_orbit.hpp"
#include "family/parameter_ops.hpp"
#include "family/recentre.hpp"

namespace stencil_runtime {

namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
// Levels of descent: a double's dyadic denominator has at most 62 bits here,
// and 2^-64 of a patch is far below any tolerance a double can express.
constexpr int kMaxLevels = 64;

double norm(const Point& a, const Point& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

// A stored rate's grid holding (x, y) exactly (both coordinates on 1/(2n) with equal parity).
bool held(const QuadTables& t, const Fraction& x, const Fraction& y, int& n, std::int64_t& a, std::int64_t& b) {
  for (int rate : t.rates()) {
    const std::int64_t g = 2 * static_cast<std::int64_t>(rate);
    if (g % x.den != 0 || g % y.den != 0) continue;
    a = x.num * (g / x.den), b = y.num * (g / y.den);
    if (((a ^ b) & 1) != 0) continue;
    n = rate;
    return true;
  }
  return false;
}
bool held(const QuadTables&, double, double, int&, std::int64_t&, std::int64_t&) { return false; }

Point combine(const double* w, const std::vector<Point>& q) {
  Point p{0, 0, 0};
  for (std::size_t h = 0; h < q.size(); ++h)
    for (int k = 0; k < 3; ++k) p[static_cast<std::size_t>(k)] += w[h] * q[h][static_cast<std::size_t>(k)];
  return p;
}

}  // namespace

QuadPatchDescent::QuadPatchDescent(const QuadTables& tables) : tables_(tables), d_(*[&] {
  if (!tables.descent())
    throw EvaluationError("these tables hold no patch subdivision (exact JSON tables from an older stencilgen): "
                          "evaluation at parameters they do not hold needs tables from this stencilgen");
  return tables.descent();
}()) {
  for (int c = 0; c < 2; ++c)
    for (int k = 0; k < 4; ++k)
      for (int j = 0; j < 4; ++j) {
        // Child c's point k - 1 is the fine point c + k - 1 = sum_j a_{c + k - 1 - 2 (j - 1)} p_{j - 1}.
        const std::int64_t i = c + (k - 1) - 2 * (j - 1) - d_.mask_first;
        half_[c][k][j] = i >= 0 && i < static_cast<std::int64_t>(d_.mask.size()) ? d_.mask[static_cast<std::size_t>(i)] : 0.0;
      }
}

void QuadPatchDescent::regular_child(std::vector<Point>& q, int cx, int cy) const {
  // Rows (x) first, then columns (y); points (i, j) at (j + 1) * 4 + (i + 1).
  Point rows[16], out[16];
  for (int j = 0; j < 4; ++j)
    for (int k = 0; k < 4; ++k) {
      Point p{0, 0, 0};
      for (int i = 0; i < 4; ++i)
        for (int c = 0; c < 3; ++c) p[static_cast<std::size_t>(c)] += half_[cx][k][i] * q[static_cast<std::size_t>(j * 4 + i)][static_cast<std::size_t>(c)];
      rows[j * 4 + k] = p;
    }
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < 4; ++i) {
      Point p{0, 0, 0};
      for (int j = 0; j < 4; ++j)
        for (int c = 0; c < 3; ++c) p[static_cast<std::size_t>(c)] += half_[cy][k][j] * rows[j * 4 + i][static_cast<std::size_t>(c)];
      out[k * 4 + i] = p;
    }
  q.assign(out, out + 16);
}

Point QuadPatchDescent::polynomial(const std::vector<Point>& q, double x, double y) const {
  double bx[4], by[4];
  for (int p = 0; p < 4; ++p) {
    double sx = 0, sy = 0;
    for (int e = d_.degree; e >= 0; --e) {
      sx = sx * x + d_.basis[static_cast<std::size_t>(p)][static_cast<std::size_t>(e)];
      sy = sy * y + d_.basis[static_cast<std::size_t>(p)][static_cast<std::size_t>(e)];
    }
    bx[p] = sx, by[p] = sy;
  }
  Point out{0, 0, 0};
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i)
      for (int c = 0; c < 3; ++c) out[static_cast<std::size_t>(c)] += bx[i] * by[j] * q[static_cast<std::size_t>(j * 4 + i)][static_cast<std::size_t>(c)];
  return out;
}

Approximation QuadPatchDescent::regular_bound(const std::vector<Point>& q, double x, double y) const {
  // The nearest node of the finest stored grid, evaluated exactly.
  const int n = tables_.rates().back();
  const long a = std::clamp(std::lround(x * n), 0L, static_cast<long>(n)), b = std::clamp(std::lround(y * n), 0L, static_cast<long>(n));
  double w[16];
  tables_.node_stencil(4, n, static_cast<int>(a), static_cast<int>(b), w);
  Approximation out;
  out.point = combine(w, q);
  out.exact = false;
  const double dx = std::fabs(x - static_cast<double>(a) / n), dy = std::fabs(y - static_cast<double>(b) / n);
  if (d_.mask_nonnegative && d_.derivative_nonnegative) {
    double du = 0, dv = 0;  // largest differences of neighbouring control points, along u and along v
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 3; ++i) {
        du = std::max(du, norm(q[static_cast<std::size_t>(j * 4 + i + 1)], q[static_cast<std::size_t>(j * 4 + i)]));
        dv = std::max(dv, norm(q[static_cast<std::size_t>((i + 1) * 4 + j)], q[static_cast<std::size_t>(i * 4 + j)]));
      }
    out.bound = dx * du + dy * dv;
  } else if (d_.mask_nonnegative) {
    for (const Point& p : q) out.bound = std::max(out.bound, norm(p, out.point));  // the limit lies in the hull
  } else {
    throw EvaluationError("this scheme's regular rules have negative weights, so evaluation between the parameters its "
                          "tables hold has no bound; give exact rationals the tables hold");
  }
  return out;
}

namespace {

// One step of an extraordinary patch's descent: the control points into the
// child holding (x, y) (the extraordinary child through A0, else a regular
// child, after which the patch is regular) and (x, y) into its coordinates.
// Returns apply()'s rounding bound.
template <class P>
double into_child(const QuadDescent::Valence& sub, int& valence, std::vector<Point>& q, P& x, P& y, std::vector<Point>& next) {
  const bool right = greater(x, 1, 2), top = greater(y, 1, 2);
  double rounding = 0;
  if (!right && !top) {
    rounding = apply(sub.ev_child, q, next);
    x = scale_minus(x, 2, 0), y = scale_minus(y, 2, 0);
  } else {
    const int c = right && !top ? 0 : (!right ? 1 : 2);  // offsets (1,0), (0,1), (1,1)
    rounding = apply(sub.regular_children[c], q, next);
    x = scale_minus(x, 2, right ? 1 : 0), y = scale_minus(y, 2, top ? 1 : 0);
    valence = 4;
  }
  q.swap(next);
  return rounding;
}

}  // namespace

template <class P>
Approximation QuadPatchDescent::evaluate(int valence, std::vector<Point>& q, P x, P y, double tolerance) const {
  double rounding = 0;
  std::vector<Point> next;
  for (int level = 0;; ++level) {
    int n = 0;
    std::int64_t a = 0, b = 0;
    if (held(tables_, x, y, n, a, b)) {  // exact from the tables
      std::array<double, limits::kMaxPatchPoints> w{};
      if ((a & 1) == 0) tables_.node_stencil(valence, n, static_cast<int>(a / 2), static_cast<int>(b / 2), w.data());
      else tables_.centre_stencil(valence, n, static_cast<int>(a / 2), static_cast<int>(b / 2), w.data());
      return {combine(w.data(), q), 0.0, true};
    }
    if (valence == 4) {
      if (d_.degree > 0) return {polynomial(q, to_real(x), to_real(y)), 0.0, true};
      Approximation approx = regular_bound(q, to_real(x), to_real(y));
      approx.bound += rounding + 4 * kEpsilon * largest_magnitude(q);
      if (approx.bound <= tolerance || level == kMaxLevels) return approx;
      const int cx = greater(x, 1, 2) ? 1 : 0, cy = greater(y, 1, 2) ? 1 : 0;
      rounding += 18 * kEpsilon * largest_magnitude(q);
      regular_child(q, cx, cy);
      x = scale_minus(x, 2, cx), y = scale_minus(y, 2, cy);
      continue;
    }
    const QuadDescent::Valence& sub = tables_.descent(valence);
    if (level == kMaxLevels) {  // within 2^-64 of the extraordinary vertex: its limit point
      if (!sub.nonnegative)
        throw EvaluationError("the " + kind_name(valence) + " has negative subdivision weights, so evaluation this close "
                              "to the extraordinary vertex has no bound");
      std::array<double, limits::kMaxPatchPoints> w{};
      tables_.node_stencil(valence, tables_.rates().front(), 0, 0, w.data());
      Approximation approx{combine(w.data(), q), 0.0, false};
      for (const Point& p : q) approx.bound = std::max(approx.bound, norm(p, approx.point));
      approx.bound += rounding;
      return approx;
    }
    rounding += into_child(sub, valence, q, x, y, next);
  }
}

void QuadPatchDescent::polynomial_basis(double t, double* w, double* dw, double* ddw) const {
  for (int p = 0; p < 4; ++p) {
    double value = 0, slope = 0, curvature = 0;
    const auto& c = d_.basis[static_cast<std::size_t>(p)];
    for (int e = d_.degree; e >= 0; --e) {
      curvature = curvature * t + 2 * slope;  // Horner for the value and two derivatives together
      slope = slope * t + value;
      value = value * t + c[static_cast<std::size_t>(e)];
    }
    w[p] = value, dw[p] = slope;
    if (ddw) ddw[p] = curvature;
  }
}

void QuadPatchDescent::regular_basis(const Fraction& t, double* w, double* dw) const {
  // A stored rate whose grid 1/(2n) holds t: a = t * 2n.
  auto held = [this](const Fraction& x, double* hw, double* hdw) {
    for (int n : tables_.rates()) {
      const std::int64_t g = 2 * static_cast<std::int64_t>(n);
      if (g % x.den != 0) continue;
      const std::int64_t a = x.num * (g / x.den);
      tables_.regular_weights(n, a, hw);
      tables_.regular_derivative_weights(n, a, hdw);
      return true;
    }
    return false;
  };
  curve_basis_by_orbit(half_, t, held, w, dw);
}

void QuadPatchDescent::regular_basis(double t, double* w, double* dw) const {
  // The same for a double, which is a dyadic fraction: only the power-of-two
  // part of a grid's denominator is tested, so that t * p is exact.
  auto held = [this](double x, double* hw, double* hdw) {
    for (int n : tables_.rates()) {
      const std::int64_t g = 2 * static_cast<std::int64_t>(n), p = g & -g;
      const double scaled = x * static_cast<double>(p);
      if (scaled != std::floor(scaled)) continue;
      const std::int64_t a = static_cast<std::int64_t>(scaled) * (g / p);
      tables_.regular_weights(n, a, hw);
      tables_.regular_derivative_weights(n, a, hdw);
      return true;
    }
    return false;
  };
  curve_basis_by_orbit(half_, t, held, w, dw);
}

namespace {

bool at_origin(const Fraction& x, const Fraction& y) { return x.num == 0 && y.num == 0; }
bool at_origin(double x, double y) { return x == 0 && y == 0; }

}  // namespace

// The tensor product over a regular patch's 4 x 4 points (j * 4 + i): value,
// first derivatives times `scale` and, given ddx and ddy, second ones times its square.
SecondDerivatives QuadPatchDescent::tensor(const std::vector<Point>& q, const double* wx, const double* wy, const double* dx,
                                           const double* dy, const double* ddx, const double* ddy, double scale) {
  const double scale2 = scale * scale;
  SecondDerivatives out;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      const Point& p = q[static_cast<std::size_t>(j * 4 + i)];
      for (std::size_t c = 0; c < 3; ++c) {
        out.point[c] += wx[i] * wy[j] * p[c];
        out.du[c] += scale * dx[i] * wy[j] * p[c];
        out.dv[c] += scale * wx[i] * dy[j] * p[c];
        if (ddx) {
          out.duu[c] += scale2 * ddx[i] * wy[j] * p[c];
          out.duv[c] += scale2 * dx[i] * dy[j] * p[c];
          out.dvv[c] += scale2 * wx[i] * ddy[j] * p[c];
        }
      }
    }
  return out;
}

template <class P>
std::array<P, 2> QuadPatchDescent::into_regular(int valence, std::vector<Point>& q, P x, P y, double& scale, Point& offset) const {
  std::vector<Point> next;
  for (int level = 0; level <= kMaxLevels; ++level) {
    if (valence == 4) return {x, y};
    if (at_origin(x, y))
      throw EvaluationError("the patch has no parametric derivative at its extraordinary vertex (" + kind_name(valence) + ")");
    recentre(q, offset);  // each level's differences rounded at their own size (family/recentre.hpp)
    into_child(tables_.descent(valence), valence, q, x, y, next);
    scale *= 2;
  }
  throw EvaluationError("the parameter is too close to the extraordinary vertex for a derivative in doubles");
}

template <class P>
PatchDerivatives QuadPatchDescent::derivatives(int valence, std::vector<Point>& q, P x0, P y0) const {
  double scale = 1;  // d(child parameter) / d(patch parameter): 2 per halving
  Point offset{0, 0, 0};
  const auto [x, y] = into_regular(valence, q, x0, y0, scale, offset);
  double wx[4], wy[4], dx[4], dy[4];
  if (d_.degree > 0) {
    polynomial_basis(to_real(x), wx, dx);
    polynomial_basis(to_real(y), wy, dy);
  } else {
    // Not polynomial: each axis's basis from the stored grids, by the orbit of
    // its parameter under halving (curve_orbit.hpp), at any parameter.
    if (!tables_.has_regular_derivatives())
      throw EvaluationError("these tables hold no derivative of the regular curve (its curve is not C1, or the tables "
                            "predate derivatives: regenerate them with this stencilgen)");
    regular_basis(x, wx, dx);
    regular_basis(y, wy, dy);
  }
  PatchDerivatives out = tensor(q, wx, wy, dx, dy, nullptr, nullptr, scale);
  for (int k = 0; k < 3; ++k) out.point[k] += offset[k];
  return out;
}

template <class P>
SecondDerivatives QuadPatchDescent::second_derivatives(int valence, std::vector<Point>& q, P x0, P y0) const {
  if (d_.degree == 0)
    throw EvaluationError("second derivatives need a scheme whose regular patches are polynomial (Catmull-Clark): this "
                          "scheme's are not, and its tables hold no phi''");
  double scale = 1;
  Point offset{0, 0, 0};
  const auto [x, y] = into_regular(valence, q, x0, y0, scale, offset);
  double wx[4], wy[4], dx[4], dy[4], ddx[4], ddy[4];
  polynomial_basis(to_real(x), wx, dx, ddx);
  polynomial_basis(to_real(y), wy, dy, ddy);
  SecondDerivatives out = tensor(q, wx, wy, dx, dy, ddx, ddy, scale);
  for (int k = 0; k < 3; ++k) out.point[k] += offset[k];
  return out;
}

void QuadPatchDescent::child(int valence, const std::vector<Point>& q, int cx, int cy, std::vector<Point>& out,
                             int& out_valence) const {
  if (valence == 4) {
    out = q;
    regular_child(out, cx, cy);
    out_valence = 4;
    return;
  }
  const QuadDescent::Valence& sub = tables_.descent(valence);
  if (cx == 0 && cy == 0) {
    apply(sub.ev_child, q, out);
    out_valence = valence;
  } else {
    apply(sub.regular_children[cx == 1 && cy == 0 ? 0 : (cx == 0 ? 1 : 2)], q, out);
    out_valence = 4;
  }
}

bool QuadPatchDescent::nonnegative() const {
  if (!d_.mask_nonnegative) return false;
  for (int v : tables_.valences())
    if (!tables_.descent(v).nonnegative) return false;
  for (const SectorKey& s : tables_.sectors())
    if (!tables_.descent(sector_kind(s)).nonnegative) return false;
  return true;
}

template Approximation QuadPatchDescent::evaluate<Fraction>(int, std::vector<Point>&, Fraction, Fraction, double) const;
template Approximation QuadPatchDescent::evaluate<double>(int, std::vector<Point>&, double, double, double) const;
template PatchDerivatives QuadPatchDescent::derivatives<Fraction>(int, std::vector<Point>&, Fraction, Fraction) const;
template PatchDerivatives QuadPatchDescent::derivatives<double>(int, std::vector<Point>&, double, double) const;
template SecondDerivatives QuadPatchDescent::second_derivatives<Fraction>(int, std::vector<Point>&, Fraction, Fraction) const;
template SecondDerivatives QuadPatchDescent::second_derivatives<double>(int, std::vector<Point>&, double, double) const;

}  // namespace stencil_runtime
