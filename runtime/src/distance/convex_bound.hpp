#pragma once
// A second-order bound on the distance from a point q to a polynomial
// sub-patch (docs/runtime.md, "Closest points"). With F(x) = |S(x) - q|^2 / 2
// over the sub-patch's unit frame (square or triangle),
//   Hess F = J^T J + sum_k r_k Hess S_k,   r = S - q.
// Around any point c of the frame, with r = r_c + (S(x) - S(c)), for every x:
//  - sigma_min(J(x)) >= sigma_min(J(c)) - |J(x) - J(c)|, where J moves by at
//    most the second derivatives' largest Bernstein coefficient times the
//    distance to the frame's far side, and its columns stay in the hulls of
//    S_X's and S_Y's Bernstein coefficients;
//  - r_c . Hess S(x) has entries between the least and greatest of r_c
//    dotted with the Bernstein coefficients v of S_XX, S_XY, S_YY (a
//    polynomial lies in the hull of its Bernstein coefficients), and
//    (S(x) - S(c)) . Hess S(x) between those of (b - S(c)) . v over S's own
//    coefficients b (a bilinear function of points of two hulls is extreme
//    at their vertices);
//  - the smallest eigenvalue of a symmetric 2x2 matrix grows with its
//    diagonal and falls with the size of its off-diagonal.
// So Hess F >= lambda I over the whole frame, and F(x) >= F(c) + g.(x - c) +
// lambda/2 |x - c|^2 (g = grad F(c)). Where lambda > 0, F is strongly convex
// and the minimum of the right side over the frame is a bound that equals
// the distance when c is the constrained minimiser (Newton's point); where
// lambda <= 0, the right side is concave and its minimum is at a corner of
// the frame, still a bound. Unlike the affine slab, whose slack falls as the
// square of the sub-patch's size (so that 1e-9 of the diagonal takes about
// eleven levels of subdivision around the nearest point), this bound is tight
// at any size where the squared distance is convex, which holds near every
// point nearer than the surface's focal points.
#include <array>
#include <utility>
#include <vector>

#include "family/family.hpp"

namespace stencil_runtime {

class ConvexBound {
 public:
  ConvexBound() = default;  // none: bound() is never asked
  explicit ConvexBound(const PolynomialPatch& patch);

  bool empty() const { return grid_size_ == 0; }

  // What bound() needs of one sub-patch that does not depend on the query
  // point: its polynomial, the Bernstein coefficients of S and of its first
  // and second derivatives, and per second-derivative coefficient v the range
  // of b.v over S's coefficients b. Made once per face patch (its control
  // points fixed) or per sub-patch.
  struct Prepared {
    std::vector<Point> grid;             // the coefficient of X^e Y^f at e + (degree + 1) f (zero where none)
    std::vector<Point> net;              // per order (S, S_X, S_Y, S_XX, S_XY, S_YY), per Bernstein coefficient
    // Per second-derivative coefficient; empty until certify() first needs
    // them, unless prepared with them (as a patch shared between threads must be).
    mutable std::vector<double> low, high;
    double largest[3] = {0, 0, 0};       // the largest |S_XX|, |S_XY|, |S_YY| coefficient
    double magnitude = 0;                // the largest coordinate of the control points (for rounding margins)
  };
  // `with_ranges`: also the ranges (else certify() makes them when it needs them).
  void prepare(const std::vector<Point>& points, Prepared& out, bool with_ranges = true) const;

  struct Result {
    double X = 0, Y = 0;     // the sub-patch's own coordinates of `point`
    Point point{0, 0, 0};    // a point of the surface (the nearest Newton found, or the centre)
    double distance = 0;     // |point - q|
    bool convex = false;     // whether F was proved strongly convex over the sub-patch
    bool bounded = false;    // whether `lower` is a bound (always where convex)
    double lower = 0;        // a lower bound on the distance from q to the sub-patch's surface
  };
  // The bound at the frame's centre; where that does not reach `enough`,
  // Newton's nearest point and the bound there. Where F is not proved convex
  // the second-order bound still holds with a negative lambda (its minimum is
  // then at a corner of the frame): it is made where it could reach `enough`.
  Result bound(const Prepared& patch, const Point& q, double enough) const;
  // Newton from (X, Y) of the frame to the sub-patch's point nearest q (no bound).
  Result polish(const Prepared& patch, const Point& q, double X, double Y) const;

 private:
  struct Jet {
    Point s, x, y, xx, xy, yy;
  };
  Jet jet(const Point* grid, double X, double Y) const;
  void project(double& X, double& Y) const;
  // Damped Newton on F from out's (X, Y) with its jet j, both updated; whether it moved.
  bool newton(const Prepared& patch, const Point& q, int steps, int halvings, Result& out, Jet& j) const;
  // The certificate at (X, Y) with its jet there: sets out.convex and out.lower.
  void certify(const Prepared& patch, const Jet& j, const Point& q, double enough, Result& out) const;
  // The ranges of b.v over S's coefficients b, per second-derivative coefficient v.
  void ranges(const Point* net, std::vector<double>& low, std::vector<double>& high) const;

  // Sizes the bound works on the stack with (larger patches get none).
  static constexpr std::size_t kMaxTerms = 64;
  static constexpr int kMaxDegree = 7;
  static constexpr int kOrders = 6;  // S, S_X, S_Y, S_XX, S_XY, S_YY
  using SparseRow = std::vector<std::pair<std::size_t, double>>;

  bool triangle_ = false;
  int degree_ = 0;
  std::size_t grid_size_ = 0;            // (degree + 1)^2; 0: no bound
  std::vector<SparseRow> coefficients_;  // per control point: (grid index, coefficient)
  // The Bernstein coefficients of each order over the frame, each a row of
  // weights over Prepared::grid; where each order's start in Prepared::net.
  std::vector<SparseRow> bernstein_[kOrders];
  std::size_t offset_[kOrders + 1] = {};
};

}  // namespace stencil_runtime
