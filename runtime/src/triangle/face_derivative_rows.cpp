#include "face_derivative_rows.hpp"

#include <string>

#include "stencil_runtime/error.hpp"

namespace stencil_runtime {

namespace {

constexpr int kSide = FaceDerivativeRows::kMaxDegree + 1;
// A polynomial in (s, t) of degree < kSide: [e][f] is the coefficient of s^e t^f.
using Dense = std::array<std::array<double, kSide>, kSide>;

Dense product(const Dense& a, const Dense& b) {
  Dense out{};
  for (int e = 0; e < kSide; ++e)
    for (int f = 0; e + f < kSide; ++f) {
      const double x = a[static_cast<std::size_t>(e)][static_cast<std::size_t>(f)];
      if (x == 0) continue;
      for (int g = 0; e + g < kSide; ++g)
        for (int k = 0; e + g + f + k < kSide; ++k)
          out[static_cast<std::size_t>(e + g)][static_cast<std::size_t>(f + k)] +=
              x * b[static_cast<std::size_t>(g)][static_cast<std::size_t>(k)];
    }
  return out;
}

Dense affine(double constant, double s, double t) {
  Dense out{};
  out[0][0] = constant, out[1][0] = s, out[0][1] = t;
  return out;
}

// The patch's (x, y) as functions of the face's (s, t) (TrianglePatch::to_patch).
void patch_coordinates(int rotation, Dense& x, Dense& y) {
  switch (rotation) {
    case 0: x = affine(0, 1, 0), y = affine(0, 0, 1); break;
    case 1: x = affine(0, 0, 1), y = affine(1, -1, -1); break;
    default: x = affine(1, -1, -1), y = affine(0, 1, 0); break;
  }
}

}  // namespace

FaceDerivativeRows::FaceDerivativeRows(int degree, const std::vector<double>& coefficients, std::size_t points)
    : degree_(degree), points_(points) {
  if (degree < 1 || degree > kMaxDegree)
    throw LoadError("regular polynomial of degree " + std::to_string(degree) + " (1.." +
                                std::to_string(kMaxDegree) + " are evaluated row by row)");
  const auto terms = static_cast<std::size_t>((degree + 1) * (degree + 2) / 2);
  if (coefficients.size() != terms * points) throw LoadError("regular polynomial of the wrong size");
  const int d = degree - 1;  // of the derivatives
  terms_ = static_cast<std::size_t>((d + 1) * (d + 2) / 2);
  for (int rotation = 0; rotation < 3; ++rotation) {
    Dense x, y;
    patch_coordinates(rotation, x, y);
    // x^e y^f as polynomials in (s, t), for e + f <= degree.
    std::array<Dense, kSide> xp{}, yp{};
    xp[0][0][0] = yp[0][0][0] = 1;
    for (int e = 1; e <= degree; ++e)
      xp[static_cast<std::size_t>(e)] = product(xp[static_cast<std::size_t>(e - 1)], x),
      yp[static_cast<std::size_t>(e)] = product(yp[static_cast<std::size_t>(e - 1)], y);
    std::vector<Dense> monomial(terms);
    for (int f = 0; f <= degree; ++f)
      for (int e = 0; e + f <= degree; ++e)
        monomial[term(e, f, degree)] = product(xp[static_cast<std::size_t>(e)], yp[static_cast<std::size_t>(f)]);
    std::vector<double>& ds = ds_[static_cast<std::size_t>(rotation)];
    std::vector<double>& dt = dt_[static_cast<std::size_t>(rotation)];
    ds.assign(terms_ * points, 0.0);
    dt.assign(terms_ * points, 0.0);
    for (std::size_t h = 0; h < points; ++h) {
      Dense basis{};  // control point h's basis function over the face
      for (std::size_t k = 0; k < terms; ++k) {
        const double c = coefficients[h * terms + k];
        for (int e = 0; e <= degree; ++e)
          for (int f = 0; e + f <= degree; ++f)
            basis[static_cast<std::size_t>(e)][static_cast<std::size_t>(f)] +=
                c * monomial[k][static_cast<std::size_t>(e)][static_cast<std::size_t>(f)];
      }
      for (int f = 0; f <= d; ++f)
        for (int e = 0; e + f <= d; ++e) {
          const std::size_t at = term(e, f, d) * points + h;
          ds[at] = (e + 1) * basis[static_cast<std::size_t>(e + 1)][static_cast<std::size_t>(f)];
          dt[at] = (f + 1) * basis[static_cast<std::size_t>(e)][static_cast<std::size_t>(f + 1)];
        }
    }
  }
}

FaceDerivativeRows::Face::Face(const FaceDerivativeRows& rows, int rotation, const Point* control)
    : degree_(rows.degree_ - 1) {
  const std::size_t m = rows.points_;
  const double* ws = rows.ds_[static_cast<std::size_t>(rotation)].data();
  const double* wt = rows.dt_[static_cast<std::size_t>(rotation)].data();
  for (std::size_t k = 0; k < rows.terms_; ++k, ws += m, wt += m) {
    double sx = 0, sy = 0, sz = 0, tx = 0, ty = 0, tz = 0;
    for (std::size_t h = 0; h < m; ++h) {
      const Point& q = control[h];
      sx += ws[h] * q[0], sy += ws[h] * q[1], sz += ws[h] * q[2];
      tx += wt[h] * q[0], ty += wt[h] * q[1], tz += wt[h] * q[2];
    }
    ds_[k] = {sx, sy, sz}, dt_[k] = {tx, ty, tz};
  }
}

void FaceDerivativeRows::Face::start_row(double t) {
  // Coefficient of s^e: sum over f of the term's coefficient times t^f (Horner in t).
  for (int e = 0; e <= degree_; ++e) {
    Point rs{0, 0, 0}, rt{0, 0, 0};
    for (int f = degree_ - e; f >= 0; --f) {
      const std::size_t k = term(e, f, degree_);
      for (std::size_t c = 0; c < 3; ++c) rs[c] = rs[c] * t + ds_[k][c], rt[c] = rt[c] * t + dt_[k][c];
    }
    row_s_[static_cast<std::size_t>(e)] = rs, row_t_[static_cast<std::size_t>(e)] = rt;
  }
}

}  // namespace stencil_runtime
