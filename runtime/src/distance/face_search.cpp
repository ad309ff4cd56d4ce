#include "face_search.hpp"
#include "distance/point_ops.hpp"
#include "family/recentre.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace stencil_runtime {

using namespace point_ops;

namespace {

// Deep enough that a sub-patch is far below any tolerance a double can express.
constexpr int kMaxDepth = 48;
// Sub-patches examined per query at most: a guard against runaway
// work (it has not been reached on the bundled meshes); what is left open then
// is reported in the gap.
constexpr std::size_t kMaxNodes = 200000;
// Gilbert steps towards the hull's nearest point per lower bound, and the
// relative gap at which they stop (measured: more steps cost more than the
// sub-patches they save).
constexpr int kGilbertSteps = 16;
constexpr double kGilbertGap = 1e-8;
// refine(): Gauss-Newton steps at most, the cosine between the residual and
// a tangent taken as orthogonal, and the smallest sub-patch it descends to.
constexpr int kRefineSteps = 64;
constexpr double kOrthogonal = 1e-12;
// The same where the tangents are differences of evaluations (sqrt(3), an
// extraordinary vertex): they are good to about 1e-9, and Newton steps on
// them stop helping there.
constexpr double kOrthogonalDifferences = 1e-8;
constexpr double kSmallest = 1e-14;
// The parameter step (relative to the sub-patch) for second derivatives by
// differences, and the smallest damping of a Newton step tried.
constexpr double kSecondStep = 1.0 / 4;
constexpr double kSmallestDamping = 1e-6;


}  // namespace

double FaceSearch::hull_bound(const SubPatch& s, const Point& q) {
  // Two lower bounds on the distance from q to the convex hull of the control
  // points: to their axis-aligned box, and a separating plane. The plane comes
  // from a few steps of Gilbert's algorithm for the hull point nearest q: x, a
  // point of the hull relative to q (first the centroid), and the support
  // point s = argmin_i x.(p_i - q) give |y| >= x.(s - q) / |x| for every hull
  // point y (relative to q); x then moves to the nearest point of the segment
  // [x, s - q]. Each step's bound is valid, the best is kept. The plane is
  // what makes the bound converge as the square of the sub-patch size on a
  // smooth surface, so that the search near a minimum stays small.
  const std::size_t n = s.points.size();
  Point lo = s.points[0], hi = s.points[0], x{0, 0, 0};
  for (const Point& p : s.points)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]), x[k] += p[k];
  double d2 = 0;
  for (int k = 0; k < 3; ++k) {
    const double e = std::max({lo[k] - q[k], 0.0, q[k] - hi[k]});
    d2 += e * e;
    x[k] = x[k] / static_cast<double>(n) - q[k];
  }
  double bound = std::sqrt(d2);
  for (int step = 0; step < kGilbertSteps; ++step) {
    const double len = length(x);
    if (!(len > bound)) break;  // the hull reaches q, or the bound is already the distance of a hull point
    std::size_t support = 0;
    double lowest = INFINITY;
    for (std::size_t i = 0; i < n; ++i) {
      const double h = dot(x, minus(s.points[i], q));
      if (h < lowest) lowest = h, support = i;
    }
    bound = std::max(bound, lowest / len);
    if (len - bound <= kGilbertGap * len) break;
    const Point d = minus(minus(s.points[support], q), x);
    const double dd = dot(d, d);
    if (!(dd > 0)) break;
    const double t = std::clamp(-dot(x, d) / dd, 0.0, 1.0);
    for (int k = 0; k < 3; ++k) x[k] += t * d[k];
  }
  return bound;
}

const AffineEnclosure* FaceSearch::enclosure_of(int kind) const {
  const std::size_t k = static_cast<std::size_t>(kind);
  return k < enclosures_.size() && !enclosures_[k].empty() ? &enclosures_[k] : nullptr;
}

const ConvexBound* FaceSearch::convex_of(int kind) const {
  const std::size_t k = static_cast<std::size_t>(kind);
  return k < convex_.size() && !convex_[k].empty() ? &convex_[k] : nullptr;
}

const ConvexBound::Prepared* FaceSearch::prepared_root(std::size_t face) const {
  return face < roots_.convex.size() && !roots_.convex[face].grid.empty() ? &roots_.convex[face] : nullptr;
}

double FaceSearch::lower_bound(const SubPatch& s, const Point& q) const {
  // Measured: the hull's bound adds nothing to the enclosure's but its cost.
  if (const AffineEnclosure* enclosure = enclosure_of(s.kind)) return enclosure->lower_bound(s.points, q);
  return hull_bound(s, q);
}

void FaceSearch::improve(const SubPatch& s, const ConvexBound::Result& r, const Point& q, FaceHit& best) const {
  const auto at = s.domain.at(r.X, r.Y);
  improve(s, at[0], at[1], r.point, 0, q, best);
}

bool FaceSearch::consider(const SubPatch& s, double& x, double& y, const Point& q, FaceHit& best) const {
  const Approximation a = family_.nearby_point(s, x, y, tolerance_ * 0.01);
  return improve(s, x, y, a.point, a.bound, q, best);
}

bool FaceSearch::improve(const SubPatch& s, double x, double y, const Point& point, double bound, const Point& q,
                         FaceHit& best) const {
  const double d = length(minus(point, q));
  if (d >= best.distance) return false;
  best.distance = d, best.face = s.face, best.x = x, best.y = y, best.point = point, best.evaluation = bound;
  best.patch = s;
  return true;
}

void FaceSearch::derivatives(const SubPatch& sub, double& x, double& y, Derivatives& out) const {
  if (family_.derivatives(sub, x, y, out)) return;  // exact (at a grid point next to (x, y) for non-polynomial schemes)
  // Central differences of exact evaluations (one-sided at the border), where
  // the family has no derivative (an extraordinary vertex, or a scheme without
  // derivatives: sqrt(3)), on the whole patch: a step relative to a deep
  // sub-patch would leave the evaluations' bounds to swamp the differences.
  SubPatch s;
  family_.root(sub.face, prepared_.data(), s);
  const double h = 1e-5;
  const auto l = s.domain.local(x, y);
  const double tol = tolerance_ * 1e-4;
  const auto value = [&](double X, double Y) {
    const auto p = s.domain.at(X, Y);
    return family_.evaluate(s, p[0], p[1], tol).point;
  };
  // The derivative along the lattice direction (a, b): central where both
  // sides are inside, else one-sided; false where neither side is (a
  // triangle's corners (1,0) and (0,1) block one axis both ways).
  const auto directional = [&](double a, double b, Point& d) {
    const bool ahead = s.domain.contains_local(l[0] + a * h, l[1] + b * h);
    const bool behind = s.domain.contains_local(l[0] - a * h, l[1] - b * h);
    if (!ahead && !behind) return false;
    const double lo = behind ? -1.0 : 0.0, hi = ahead ? 1.0 : 0.0;
    const Point fa = value(l[0] + lo * a * h, l[1] + lo * b * h), fb = value(l[0] + hi * a * h, l[1] + hi * b * h);
    for (int k = 0; k < 3; ++k) d[k] = (fb[k] - fa[k]) / ((hi - lo) * h);
    return true;
  };
  out.point = value(l[0], l[1]);
  Point dX{0, 0, 0}, dY{0, 0, 0}, diagonal{0, 0, 0};
  const bool along_x = directional(1, 0, dX), along_y = directional(0, 1, dY);
  // A blocked axis from the diagonal (1, -1), along the triangle's long edge: its derivative is dX - dY.
  if (along_x != along_y && directional(1, -1, diagonal))
    for (int k = 0; k < 3; ++k) {
      if (along_y) dX[k] = dY[k] + diagonal[k];
      else dY[k] = dX[k] - diagonal[k];
    }
  // To the patch's parameters: d/dx = dX/dx d/dX + dY/dx d/dY.
  const auto j = s.domain.inverse_jacobian();
  for (int k = 0; k < 3; ++k) {
    out.du[k] = j[0] * dX[k] + j[2] * dY[k];
    out.dv[k] = j[1] * dX[k] + j[3] * dY[k];
  }
}

void FaceSearch::polish(const SubPatch& s, double x, double y, const Point& q, FaceHit& best) const {
  double last_x = -1, last_y = -1;
  for (int step = 0; step < 12; ++step) {
    Derivatives d;
    const double ax = x, ay = y;
    derivatives(s, x, y, d);  // (x, y) may move to where the derivatives are exact
    const bool snapped = x != ax || y != ay;
    improve(s, x, y, d.point, 0, q, best);
    if (step > 0 && x == last_x && y == last_y) break;  // back on the same grid point
    last_x = x, last_y = y;
    const Point r = minus(d.point, q);
    // Gauss-Newton: (J^T J) d = -J^T r, clamped to the sub-patch.
    const double a = dot(d.du, d.du), b = dot(d.du, d.dv), c = dot(d.dv, d.dv);
    const double gu = dot(r, d.du), gv = dot(r, d.dv), det = a * c - b * b;
    if (!(det > 1e-300)) break;
    const double dx = -(c * gu - b * gv) / det, dy = -(a * gv - b * gu) / det;
    double nx = x + dx, ny = y + dy;
    s.domain.clamp(nx, ny);
    const bool small = std::fabs(nx - x) + std::fabs(ny - y) < 1e-13 * s.domain.size();
    x = nx, y = ny;
    if (small) {
      if (!snapped) consider(s, x, y, q, best);  // else the grid point is as near as it gets
      break;
    }
  }
}

namespace {

// The larger cosine between the residual q - p and the two tangents.
double tangent_cosine(const Derivatives& d, const Point& q) {
  const Point r = minus(q, d.point);
  const double lr = length(r), lu = length(d.du), lv = length(d.dv);
  if (!(lr > 0 && lu > 0 && lv > 0)) return 0;
  return std::max(std::fabs(dot(r, d.du)) / (lr * lu), std::fabs(dot(r, d.dv)) / (lr * lv));
}

}  // namespace

void FaceSearch::refine(const Point& q, FaceHit& best) const {
  if (best.patch.points.empty()) return;
  const auto stationary = [&] {  // Gauss-Newton converged where derivatives are exact anywhere?
    double x = best.x, y = best.y;
    Derivatives d;
    return family_.derivatives(best.patch, x, y, d) && x == best.x && y == best.y && tangent_cosine(d, q) <= kOrthogonal;
  };
  if (stationary()) return;
  if (const ConvexBound* convex = convex_of(best.patch.kind)) {
    // A polynomial sub-patch: Newton on it to its nearest point first (far
    // cheaper than the path below, which then has nothing left to do unless
    // the minimum lies over the sub-patch's border).
    ConvexBound::Prepared prepared;
    convex->prepare(best.patch.points, prepared, false);
    const auto l = best.patch.domain.local(best.x, best.y);
    const SubPatch s = best.patch;  // improve() replaces best.patch
    improve(s, convex->polish(prepared, q, l[0], l[1]), q, best);
    if (stationary()) return;
  }
  const auto holds = [](const SubPatch& k, double x, double y) { return k.domain.contains(x, y, 1e-14); };  // own coordinates round
  SubPatch children[kMaxSubPatchChildren];
  // The sub-patches on the path hold their control points relative to an
  // origin near them (`offsets`): deep sub-patches are tiny, and points
  // rounded at the size of the coordinates would leave derivatives (point
  // differences over the sub-patch's size) with errors of 1e-16 times the
  // coordinates over that size. Relative to their own centroid they keep
  // errors relative to their own extent; derivatives do not see the origin.
  std::vector<Point> offsets(1, Point{0, 0, 0});
  // The child of the path's end that holds (x, y) (of two or four that do, the one whose centre is nearest).
  const auto descend = [&](std::vector<SubPatch>& path, double x, double y) {
    const int n = family_.split(path.back(), children);
    int pick = 0;
    double nearest = INFINITY;
    for (int k = 0; k < n; ++k) {
      const auto c = children[k].domain.centre();
      const double e = std::fabs(c[0] - x) + std::fabs(c[1] - y) + (holds(children[k], x, y) ? 0.0 : 1.0);
      if (e < nearest) nearest = e, pick = k;
    }
    SubPatch& child = children[pick];
    Point offset = offsets.back();
    recentre(child.points, offset);
    offsets.push_back(offset);
    path.push_back(std::move(child));
  };
  // Derivatives on the path's end, the point moved back by its origin.
  // Where the family has none (sqrt(3), an extraordinary vertex): differences
  // of exact evaluations on the whole patch (derivatives()).
  bool differenced = false;  // whether the last derivatives_at() took differences
  const auto derivatives_at = [&](const std::vector<SubPatch>& path, double& x, double& y, Derivatives& out) {
    differenced = !family_.derivatives(path.back(), x, y, out);
    if (differenced) {
      derivatives(path.front(), x, y, out);  // differences on the whole patch
      return true;
    }
    for (int k = 0; k < 3; ++k) out.point[k] += offsets.back()[k];
    return true;
  };
  // The path from the face's patch down to a sub-patch around the current
  // point: as small as the one the best point was found in at first, then
  // about twice the last step (the sub-patch's stored grid, where the
  // derivatives are exact, then resolves the step to a few per cent). It is kept so that
  // the point can move up and over a sub-patch's border.
  std::vector<SubPatch> path(1);
  family_.root(best.face, prepared_.data(), path[0]);
  const auto reach = [&](double x, double y, double size) {
    while (path.size() > 1 && !holds(path.back(), x, y)) path.pop_back(), offsets.pop_back();
    while (path.back().domain.size() > size && path.back().domain.size() > kSmallest) descend(path, x, y);
  };
  double x = best.x, y = best.y;
  reach(x, y, best.patch.domain.size());
  Derivatives d;
  derivatives_at(path, x, y, d);
  bool d_differenced = differenced;
  improve(path.back(), x, y, d.point, 0, q, best);
  double t = 1;  // the damping of the Newton step
  for (int iteration = 0; iteration < kRefineSteps; ++iteration) {
    if (tangent_cosine(d, q) <= (d_differenced ? kOrthogonalDifferences : kOrthogonal)) return;
    // Newton for |S - q|^2 / 2: gradient J^T r, Hessian J^T J + sum_k r_k
    // S_k'' with the second derivatives from differences of exact first
    // derivatives a grid step away (Gauss-Newton where that is not positive).
    const SubPatch& s = path.back();
    const Point r = minus(d.point, q);
    double hxx = dot(d.du, d.du), hxy = dot(d.du, d.dv), hyy = dot(d.dv, d.dv);
    const double gu = dot(r, d.du), gv = dot(r, d.dv);
    // Points a step along x and along y, inside the sub-patch (ahead, else behind).
    const double h = kSecondStep * s.domain.size();
    double xh = x + h, yh = y, xv = x, yv = y + h;
    if (!s.domain.contains(xh, yh)) xh = x - h;
    if (!s.domain.contains(xv, yv)) yv = y - h;
    Derivatives dh, dw;
    if (s.domain.contains(xh, yh) && s.domain.contains(xv, yv) && derivatives_at(path, xh, yh, dh) &&
        derivatives_at(path, xv, yv, dw) && xh != x && yv != y && yh == y && xv == x) {
      const double ex = xh - x, ey = yv - y;
      const double suu = (dot(r, dh.du) - dot(r, d.du)) / ex, svv = (dot(r, dw.dv) - dot(r, d.dv)) / ey;
      const double suv = 0.5 * ((dot(r, dh.dv) - dot(r, d.dv)) / ex + (dot(r, dw.du) - dot(r, d.du)) / ey);
      if (hxx + suu > 0 && (hxx + suu) * (hyy + svv) - (hxy + suv) * (hxy + suv) > 0) hxx += suu, hxy += suv, hyy += svv;
    }
    const double det = hxx * hyy - hxy * hxy;
    if (!(det > 0)) return;
    const double sx = -(hyy * gu - hxy * gv) / det, sy = -(hxx * gv - hxy * gu) / det;
    // A damped step, halved until the point comes nearer.
    bool moved = false;
    for (; t > kSmallestDamping; t /= 2) {
      double nx = x + t * sx, ny = y + t * sy;
      path.front().domain.clamp(nx, ny);  // inside the patch
      const double step = std::fabs(nx - x) + std::fabs(ny - y);
      if (!(step > 0)) return;  // nothing left to move (against the patch's border, or converged in doubles)
      reach(nx, ny, 2 * step);
      Derivatives n;
      if (!derivatives_at(path, nx, ny, n)) return;
      const bool n_differenced = differenced;
      // Nearer; or, where distances no longer differ beyond the rounding of
      // the points (evaluated in sub-patches of different depths, each
      // rounding at the size of the coordinates), more nearly orthogonal.
      const double now = length(r), then = length(minus(n.point, q));
      const double rounding = 32 * std::numeric_limits<double>::epsilon() *
                              (now + std::max({std::fabs(q[0]), std::fabs(q[1]), std::fabs(q[2])}));
      const bool nearer = then < now || (then <= now + rounding && tangent_cosine(n, q) < tangent_cosine(d, q));
      if (nearer || (nx == x && ny == y)) {
        if (nx == x && ny == y) return;  // the grid does not resolve the step: as near as the tables go
        x = nx, y = ny, d = n, d_differenced = n_differenced, moved = true;
        improve(path.back(), x, y, d.point, 0, q, best);
        break;
      }
    }
    if (!moved) return;
    t = std::min(1.0, 2 * t);
  }
}

void FaceSearch::push(double bound, int depth, SubPatch&& patch) {
  open_.push_back({bound, depth, std::move(patch)});
  std::push_heap(open_.begin(), open_.end(), [](const Node& a, const Node& b) { return a.bound > b.bound; });
}

void FaceSearch::start(std::size_t face, double x, double y, const Point& q, FaceHit& best) const {
  SubPatch root;
  family_.root(face, prepared_.data(), root);
  const ConvexBound* convex = convex_of(root.kind);
  const ConvexBound::Prepared* prepared = prepared_root(face);
  if (convex && prepared) {  // a polynomial patch: Newton on its prepared polynomial
    const auto l = root.domain.local(x, y);
    improve(root, convex->polish(*prepared, q, l[0], l[1]), q, best);
    return;
  }
  polish(root, x, y, q, best);
}

void FaceSearch::add(std::size_t face, const Point& q, const FaceHit& best) {
  // Where the face's slab was made once, the patch is gathered only when the slab does not rule it out.
  const AffineEnclosure* enclosure = face < roots_.kinds.size() ? enclosure_of(roots_.kinds[face]) : nullptr;
  const double slab_bound = enclosure ? enclosure->lower_bound(roots_.slabs[face], q) : 0.0;
  if (enclosure && !(slab_bound < best.distance - tolerance_)) return;
  SubPatch root;
  family_.root(face, prepared_.data(), root);
  const double bound = enclosure ? slab_bound : lower_bound(root, q);
  if (bound < best.distance - tolerance_) push(bound, 0, std::move(root));
}

void FaceSearch::run(const Point& q, FaceHit& best) {
  const auto later = [](const Node& a, const Node& b) { return a.bound > b.bound; };
  SubPatch children[kMaxSubPatchChildren];
  double unresolved = 0;  // the largest gap left by sub-patches too deep to split
  std::size_t examined = 0;
  while (!open_.empty() && open_.front().bound < best.distance - tolerance_) {
    if (++examined > kMaxNodes) {
      unresolved = std::max(unresolved, best.distance - open_.front().bound);
      break;
    }
    std::pop_heap(open_.begin(), open_.end(), later);
    Node node = std::move(open_.back());
    open_.pop_back();
    const SubPatch& s = node.patch;
    if (const ConvexBound* convex = convex_of(s.kind)) {
      // Newton's nearest point of the sub-patch; and where the squared
      // distance is convex over it, a bound that settles the whole sub-patch.
      const ConvexBound::Prepared* prepared = node.depth == 0 ? prepared_root(s.face) : nullptr;
      if (!prepared) convex->prepare(s.points, scratch_, false), prepared = &scratch_;
      const ConvexBound::Result r = convex->bound(*prepared, q, best.distance - tolerance_);
      improve(s, r, q, best);
      if (r.bounded && r.lower >= best.distance - tolerance_) continue;
    } else {
      // The centre; where it is the nearest point so far, Gauss-Newton from there.
      auto [cx, cy] = s.domain.centre();
      if (consider(s, cx, cy, q, best)) polish(s, cx, cy, q, best);
    }
    if (node.depth == kMaxDepth) {
      unresolved = std::max(unresolved, best.distance - node.bound);
      continue;
    }
    const int n = family_.split(s, children);
    for (int c = 0; c < n; ++c) {
      const double bound = lower_bound(children[c], q);
      if (bound < best.distance - tolerance_) push(bound, node.depth + 1, std::move(children[c]));
    }
  }
  open_.clear();
  // What might still be hidden beyond the tolerance (0 when the search ran to its end).
  best.gap = std::max(best.gap, unresolved - tolerance_);
}

}  // namespace stencil_runtime
