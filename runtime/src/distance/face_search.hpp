#pragma once
// The closest point of one prepared face's patch to a query point: a
// branch-and-bound over the scheme's own subdivision of the patch. A
// sub-patch's surface lies in the convex hull of its control points, so the
// distance to their bounding box is a lower bound for it; sub-patches whose
// bound is not below the best distance found minus the tolerance are dropped,
// the others split, their centres evaluated and the promising ones polished
// by Gauss-Newton steps in the patch parameters (derivatives by central
// differences of exact evaluations). The search ends when nothing left could
// be closer by more than the tolerance.
#include <cstddef>
#include <vector>

#include "family/family.hpp"

namespace stencil_runtime {

struct FaceHit {
  double distance = 0;
  std::size_t face = 0;  // prepared face
  double x = 0, y = 0;   // patch parameter
  Point point{0, 0, 0};
  double gap = 0;        // how much closer than distance - tolerance the surface might still be (0 normally)
  double evaluation = 0; // the evaluation bound of `point`
};

class FaceSearch {
 public:
  FaceSearch(const Family& family, const std::vector<Point>& prepared, double tolerance)
      : family_(family), prepared_(prepared), tolerance_(tolerance) {}

  // Distance from q to the axis-aligned box of a sub-patch's control points.
  static double box_distance(const SubPatch& s, const Point& q);

  // Improves `best` (distance +infinity when there is none yet) with the
  // closest point of prepared face `face`; true when it did.
  bool search(std::size_t face, const Point& q, FaceHit& best) const;

  // The limit point and its partial derivatives in the patch parameters at (x, y)
  // of a sub-patch (central differences of exact evaluations, one-sided at its border).
  void derivatives(const SubPatch& s, double x, double y, Point& f, Point& du, Point& dv) const;

 private:
  // Gauss-Newton from (x, y) inside the sub-patch; improves `best`.
  void polish(const SubPatch& s, double x, double y, const Point& q, FaceHit& best) const;
  bool consider(const SubPatch& s, double x, double y, const Point& q, FaceHit& best) const;  // true when it improved best

  const Family& family_;
  const std::vector<Point>& prepared_;
  double tolerance_;
};

}  // namespace stencil_runtime
