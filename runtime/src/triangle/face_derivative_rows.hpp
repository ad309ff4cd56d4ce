#pragma once
// Tessellation normals of a polynomial regular triangle patch (Loop's quartic
// box spline) row by row. A sample's normal from the derivative stencils costs
// two sums over the patch's control points (2 x 3 x 12 multiply-adds for Loop);
// here the face's derivative polynomials along its own (s, t) are formed once
// per face, restricted to each row of samples (t fixed) once per row, and each
// sample is a Horner step in s per derivative (2 x 3 x 3 for Loop's cubics).
//
// The face's (s, t) and the patch's (x, y) differ by the patch's rotation
// (TrianglePatch::to_patch), an affine map of determinant +1, so
// d/ds x d/dt points the same way as d/dx x d/dy: the unit normal is the same
// up to rounding. The positions stay the tables' stencil sums (every route to a
// point rounds alike); only the normals, written as floats, take this route.
#include <array>
#include <cstddef>
#include <vector>

#include "stencil_runtime/mesh.hpp"
#include "tables/monomial_jet.hpp"

namespace stencil_runtime {

class FaceDerivativeRows {
 public:
  static constexpr int kMaxDegree = MonomialJet::kMaxDegree;  // of the patch's polynomial (the table loader's limit)

  // `degree` >= 1 and `coefficients` as TriangleTables::polynomial() (per
  // control point h of the regular layout, the coefficients of x^e y^f, f =
  // 0..degree, e = 0..degree-f), for `points` control points. Throws
  // LoadError for a degree outside 1..kMaxDegree or a size that does not
  // match (the table loader has checked both).
  FaceDerivativeRows(int degree, const std::vector<double>& coefficients, std::size_t points);

  std::size_t points() const { return points_; }

  // One face: its derivative polynomials' coefficients (points) from its
  // control points, for its patch's rotation (0..2).
  class Face {
   public:
    Face(const FaceDerivativeRows& rows, int rotation, const Point* control);
    // Restricts both derivatives to the row t (a cubic in s for Loop).
    void start_row(double t);
    // d/ds and d/dt at (s, t) of the row started last (inline: once per sample).
    void at(double s, Point& ds, Point& dt) const {
      ds = row_s_[static_cast<std::size_t>(degree_)], dt = row_t_[static_cast<std::size_t>(degree_)];
      for (int e = degree_ - 1; e >= 0; --e)
        for (std::size_t c = 0; c < 3; ++c)
          ds[c] = ds[c] * s + row_s_[static_cast<std::size_t>(e)][c], dt[c] = dt[c] * s + row_t_[static_cast<std::size_t>(e)][c];
    }

   private:
    int degree_ = 0;  // of the derivatives
    std::array<Point, (kMaxDegree) * (kMaxDegree + 1) / 2> ds_{}, dt_{};  // coefficient of s^e t^f at term(e, f)
    std::array<Point, kMaxDegree> row_s_{}, row_t_{};                       // coefficient of s^e on the row
  };

  // Index of s^e t^f among the terms of total degree <= d (f-major, as TriangleTables::polynomial()).
  static std::size_t term(int e, int f, int d) { return static_cast<std::size_t>(f * (d + 1) - f * (f - 1) / 2 + e); }

 private:
  int degree_ = 0;  // of the patch's polynomial
  std::size_t points_ = 0;
  std::size_t terms_ = 0;  // of the derivatives, degree_ - 1
  // Per rotation: d/ds and d/dt of each basis function as coefficients over
  // the derivative terms, [term * points_ + h] (contiguous in h for the face sums).
  std::array<std::vector<double>, 3> ds_, dt_;
};

}  // namespace stencil_runtime
