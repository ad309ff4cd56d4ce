#include "face_search.hpp"

#include <algorithm>
#include <cmath>
#include <queue>

namespace stencil_runtime {

namespace {

// Deep enough that a sub-patch is far below any tolerance a double can express.
constexpr int kMaxDepth = 48;
// Sub-patches examined per face and query at most: a guard against runaway
// work (it has not been reached on the bundled meshes); what is left open then
// is reported in the gap.
constexpr std::size_t kMaxNodes = 200000;

Point minus(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double length(const Point& a) { return std::sqrt(dot(a, a)); }

struct Node {
  double bound;
  int depth;
  SubPatch patch;
  bool operator<(const Node& o) const { return bound > o.bound; }  // smallest bound first
};

}  // namespace

double FaceSearch::box_distance(const SubPatch& s, const Point& q) {
  // Two lower bounds on the distance from q to the convex hull of the control
  // points: to their axis-aligned box, and the hull's extent towards q along
  // the direction u from q to the points' centroid (every hull point x has
  // |x - q| >= u.(x - q) >= min_i u.(p_i - q)). The second is what makes the
  // bound converge as the square of the sub-patch size on a smooth surface, so
  // that the search near a minimum stays small.
  Point lo = s.points[0], hi = s.points[0], c{0, 0, 0};
  for (const Point& p : s.points)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]), c[k] += p[k];
  double d2 = 0;
  for (int k = 0; k < 3; ++k) {
    const double e = std::max({lo[k] - q[k], 0.0, q[k] - hi[k]});
    d2 += e * e;
  }
  const double box = std::sqrt(d2);
  Point u = minus(c, Point{q[0] * s.points.size(), q[1] * s.points.size(), q[2] * s.points.size()});
  const double len = length(u);
  if (!(len > 0)) return box;
  for (double& x : u) x /= len;
  double support = INFINITY;
  for (const Point& p : s.points) support = std::min(support, dot(u, minus(p, q)));
  return std::max(box, support);
}

bool FaceSearch::consider(const SubPatch& s, double x, double y, const Point& q, FaceHit& best) const {
  const Approximation a = family_.evaluate(s, x, y, tolerance_ * 0.01);
  const double d = length(minus(a.point, q));
  if (d >= best.distance) return false;
  best = {d, s.face, x, y, a.point, best.gap, a.bound};
  return true;
}

void FaceSearch::derivatives(const SubPatch& s, double x, double y, Point& f, Point& du, Point& dv) const {
  const double h = s.size * 1e-5;
  const double x1 = s.x0 + s.size, y1 = s.y0 + s.size;
  const double xa = std::max(s.x0, x - h), xb = std::min(x1, x + h), ya = std::max(s.y0, y - h), yb = std::min(y1, y + h);
  const double tol = tolerance_ * 1e-4;
  f = family_.evaluate(s, x, y, tol).point;
  const Point fxa = family_.evaluate(s, xa, y, tol).point, fxb = family_.evaluate(s, xb, y, tol).point;
  const Point fya = family_.evaluate(s, x, ya, tol).point, fyb = family_.evaluate(s, x, yb, tol).point;
  for (int k = 0; k < 3; ++k) {
    du[k] = (fxb[k] - fxa[k]) / (xb - xa);
    dv[k] = (fyb[k] - fya[k]) / (yb - ya);
  }
}

void FaceSearch::polish(const SubPatch& s, double x, double y, const Point& q, FaceHit& best) const {
  for (int step = 0; step < 12; ++step) {
    Point f{}, du{}, dv{};
    derivatives(s, x, y, f, du, dv);
    const Point r = minus(f, q);
    // Gauss-Newton: (J^T J) d = -J^T r, clamped to the sub-patch.
    const double a = dot(du, du), b = dot(du, dv), c = dot(dv, dv);
    const double gu = dot(r, du), gv = dot(r, dv), det = a * c - b * b;
    if (!(det > 1e-300)) break;
    const double dx = -(c * gu - b * gv) / det, dy = -(a * gv - b * gu) / det;
    const double nx = std::clamp(x + dx, s.x0, s.x0 + s.size), ny = std::clamp(y + dy, s.y0, s.y0 + s.size);
    const bool small = std::fabs(nx - x) + std::fabs(ny - y) < 1e-13 * s.size;
    x = nx, y = ny;
    if (small) break;
  }
  consider(s, x, y, q, best);
}

bool FaceSearch::search(std::size_t face, const Point& q, FaceHit& best) const {
  const double before = best.distance;
  std::priority_queue<Node> open;
  Node root{0, 0, {}};
  family_.root(face, prepared_.data(), root.patch);
  root.bound = box_distance(root.patch, q);
  if (root.bound >= best.distance - tolerance_) return false;
  open.push(std::move(root));
  SubPatch children[4];
  double unresolved = 0;  // the largest gap left by sub-patches too deep to split
  std::size_t examined = 0;
  while (!open.empty() && open.top().bound < best.distance - tolerance_) {
    if (++examined > kMaxNodes) {
      unresolved = std::max(unresolved, best.distance - open.top().bound);
      break;
    }
    Node node = open.top();
    open.pop();
    const SubPatch& s = node.patch;
    const double cx = s.x0 + 0.5 * s.size, cy = s.y0 + 0.5 * s.size;
    // The centre; where it is the nearest point so far, Gauss-Newton from there.
    if (consider(s, cx, cy, q, best)) polish(s, cx, cy, q, best);
    if (node.depth == kMaxDepth) {
      unresolved = std::max(unresolved, best.distance - node.bound);
      continue;
    }
    const int n = family_.split(s, children);
    for (int c = 0; c < n; ++c) {
      const double bound = box_distance(children[c], q);
      if (bound < best.distance - tolerance_) open.push({bound, node.depth + 1, std::move(children[c])});
    }
  }
  // What this face might still hide beyond the tolerance (0 when the search ran to its end).
  best.gap = std::max(best.gap, unresolved - tolerance_);
  return best.distance < before;
}

}  // namespace stencil_runtime
