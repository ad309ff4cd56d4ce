#pragma once
// The closest point of the limit surface to one query point: a best-first
// branch-and-bound over the scheme's own subdivision of the candidate faces'
// patches, all faces in one queue. A sub-patch's surface lies in the convex
// hull of its control points, so a lower bound on the distance to that hull
// bounds the sub-patch; the queue is worked in order of that bound, and a
// sub-patch whose bound is not below the best distance found minus the
// tolerance is dropped. Split sub-patches have their centres evaluated; a
// centre that improves the best is polished by Gauss-Newton steps in the patch
// parameters. The search ends when nothing left could be closer by more than
// the tolerance. One FaceSearch serves one query (it holds the queue).
#include <cstddef>
#include <vector>

#include "affine_enclosure.hpp"
#include "convex_bound.hpp"
#include "family/family.hpp"

namespace stencil_runtime {

struct FaceHit {
  double distance = 0;
  std::size_t face = 0;  // prepared face
  double x = 0, y = 0;   // patch parameter
  Point point{0, 0, 0};
  double gap = 0;        // how much closer than distance - tolerance the surface might still be (0 normally)
  double evaluation = 0; // the evaluation bound of `point`
  SubPatch patch;        // the sub-patch it was found in (derivatives there are exact at its grid points)
};

// What the search keeps of every prepared face's whole patch, made once per
// set of control positions: the affine slab and the convexity bound's data
// (empty where the face's kind has none).
struct PreparedRoots {
  std::vector<int> kinds;                     // per prepared face: its patch's kind
  std::vector<AffineEnclosure::Slab> slabs;   // made where the kind has an affine enclosure
  std::vector<ConvexBound::Prepared> convex;  // made where the kind has a convexity bound
};

class FaceSearch {
 public:
  // `enclosures` and `convex`, indexed by sub-patch kind: the affine
  // enclosure and the convexity bound of kinds that have them.
  FaceSearch(const Family& family, const std::vector<Point>& prepared, const std::vector<AffineEnclosure>& enclosures,
             const std::vector<ConvexBound>& convex, const PreparedRoots& roots, double tolerance)
      : family_(family), prepared_(prepared), enclosures_(enclosures), convex_(convex), roots_(roots), tolerance_(tolerance) {}

  // A lower bound on the distance from q to the convex hull of a sub-patch's control points.
  static double hull_bound(const SubPatch& s, const Point& q);
  // The larger of that and the affine enclosure's bound where its kind has one.
  double lower_bound(const SubPatch& s, const Point& q) const;

  // A first upper bound: Gauss-Newton on prepared face `face` from (x, y); improves `best`.
  void start(std::size_t face, double x, double y, const Point& q, FaceHit& best) const;
  // Queues prepared face `face` unless its hull is provably not nearer than best - tolerance.
  void add(std::size_t face, const Point& q, const FaceHit& best);
  // Works the queue to its end; improves `best`.
  void run(const Point& q, FaceHit& best);
  // Where the best point is not yet a stationary point of the distance (its
  // sub-patch's exact derivatives sit on a grid, so Gauss-Newton stopped at
  // a grid point), follows it down into smaller sub-patches, Gauss-Newton in
  // each, until the residual is orthogonal to the surface.
  void refine(const Point& q, FaceHit& best) const;

  // The limit point and its partial derivatives in the patch parameters at
  // (x, y) of a sub-patch: exact where the family has them (Family::derivatives,
  // which may move (x, y) to its grid), else central differences of exact
  // evaluations on the whole patch (one-sided at its border).
  void derivatives(const SubPatch& s, double& x, double& y, Derivatives& out) const;

 private:
  struct Node {
    double bound;
    int depth;
    SubPatch patch;
  };
  // Gauss-Newton from (x, y) inside the sub-patch; improves `best`.
  void polish(const SubPatch& s, double x, double y, const Point& q, FaceHit& best) const;
  // The point at (x, y), or at the grid point next to it where exact
  // derivatives move it there; true when it improved best.
  bool consider(const SubPatch& s, double& x, double& y, const Point& q, FaceHit& best) const;
  bool improve(const SubPatch& s, double x, double y, const Point& point, double bound, const Point& q, FaceHit& best) const;
  // The same with a point the convexity bound's Newton found in `s`.
  void improve(const SubPatch& s, const ConvexBound::Result& r, const Point& q, FaceHit& best) const;
  // The enclosure and the convexity bound of a kind, and a face's prepared
  // whole patch; null where there is none.
  const AffineEnclosure* enclosure_of(int kind) const;
  const ConvexBound* convex_of(int kind) const;
  const ConvexBound::Prepared* prepared_root(std::size_t face) const;
  void push(double bound, int depth, SubPatch&& patch);

  const Family& family_;
  const std::vector<Point>& prepared_;
  const std::vector<AffineEnclosure>& enclosures_;
  const std::vector<ConvexBound>& convex_;
  const PreparedRoots& roots_;
  ConvexBound::Prepared scratch_;  // a deeper sub-patch's, made as it is popped
  double tolerance_;
  std::vector<Node> open_;  // a heap, smallest bound on top
};

}  // namespace stencil_runtime
