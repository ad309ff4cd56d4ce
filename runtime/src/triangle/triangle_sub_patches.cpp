// Sub-patches of triangle patches, for closest points (family.hpp): the
// patch's control points carried down the tables' cells, each cell a triangle
// of the patch's parameters.
#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

#include "family/stencil_sum.hpp"
#include "loop_split.hpp"
#include "tables/sparse_rows.hpp"
#include "triangle_family.hpp"
#include "triangle_steps.hpp"

namespace stencil_runtime {

namespace {

// Corner k (0, 1, 2) of cell `cell` of the m^2 split, in the parent kind's
// coordinates, in the cell's own corner order (the order the descent's
// cell_of() maps to (0,0), (1,0), (0,1)): up cell (a, b) has corners (a, b),
// (a+1, b), (a, b+1), down cell (a, b) has (a+1, b), (a+1, b+1), (a, b+1),
// all over m; cells are numbered as in docs/table-format.md.
std::array<double, 2> cell_corner(int m, int cell, int k) {
  const int ups = m * (m + 1) / 2;
  const bool down = cell >= ups;
  int index = down ? cell - ups : cell, width = down ? m - 1 : m, b = 0;
  while (index >= width) index -= width, --width, ++b;
  const int a = index;
  static constexpr int kUp[3][2] = {{0, 0}, {1, 0}, {0, 1}};
  static constexpr int kDown[3][2] = {{1, 0}, {1, 1}, {0, 1}};
  const int* c = down ? kDown[k] : kUp[k];
  return {static_cast<double>(a + c[0]) / m, static_cast<double>(b + c[1]) / m};
}

// The point (a/g, b/g) of the unit triangle nearest (X, Y) among the grid's
// nodes and centres (a = b mod 3: the points the triangle tables store at
// rate g/3); false where none is (never, for g >= 3).
bool nearest_grid_point(double X, double Y, std::int64_t g, std::int64_t& a, std::int64_t& b) {
  const double G = static_cast<double>(g);
  const auto a0 = static_cast<std::int64_t>(std::floor(X * G)), b0 = static_cast<std::int64_t>(std::floor(Y * G));
  double best = INFINITY;
  for (std::int64_t i = a0 - 1; i <= a0 + 2; ++i)
    for (std::int64_t j = b0 - 1; j <= b0 + 2; ++j) {
      if (i < 0 || j < 0 || i + j > g || ((i - j) % 3 + 3) % 3 != 0) continue;
      const double dx = static_cast<double>(i) / G - X, dy = static_cast<double>(j) / G - Y;
      if (dx * dx + dy * dy < best) best = dx * dx + dy * dy, a = i, b = j;
    }
  return best < INFINITY;
}

}  // namespace

bool TriangleFamily::hull_bounds() const {
  checked_descent();
  // A boundary sector's points bound its surface with the box appended
  // (append_sector_box), where its child at B has no negative weight.
  for (const TrianglePatch& patch : patches_)
    if (TriangleTables::is_sector_code(patch.valence) && !std::isfinite(tables_.sector_spread(patch.valence))) return false;
  return tables_.children_nonnegative();
}

namespace {

// After a boundary sector's layout points: the eight corners of their box
// widened by `spread` times its extent on each side, which holds the
// sector's surface (TriangleTables::sector_spread).
void append_sector_box(std::vector<Point>& points, double spread) {
  Point lo = points.front(), hi = lo;
  for (const Point& p : points)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  for (int k = 0; k < 3; ++k) {
    // Rounding: the points are sums of a few dozen products; widen by a little more than it can add.
    const double extent = hi[k] - lo[k], slack = 1e-12 * (std::fabs(lo[k]) + std::fabs(hi[k]) + extent);
    lo[k] -= spread * extent + slack, hi[k] += spread * extent + slack;
  }
  for (int c = 0; c < 8; ++c) points.push_back({(c & 1) ? hi[0] : lo[0], (c & 2) ? hi[1] : lo[1], (c & 4) ? hi[2] : lo[2]});
}

}  // namespace

std::vector<Point> TriangleFamily::layout_points(const SubPatch& in, int& valence, int& region) const {
  kind_parts(in.kind, valence, region);
  std::vector<Point> points = in.points;
  if (TriangleTables::is_sector_code(valence)) points.resize(tables_.layout(valence).size());  // without the box
  return points;
}

void TriangleFamily::node_points(const TrianglePatch& patch, const Point* prepared, std::vector<Point>& out) const {
  gather_points(patch.points, prepared, out);
  if (TriangleTables::is_sector_code(patch.valence)) append_sector_box(out, tables_.sector_spread(patch.valence));
}

void TriangleFamily::root(std::size_t prepared_face, const Point* prepared, SubPatch& out) const {
  const TrianglePatch& patch = patches_[prepared_face];
  out.face = prepared_face;
  out.node = prepared_face;
  out.positions = prepared;
  out.kind = refined(prepared_face) ? kRefinedKind : kind_of(patch.valence, patch.region);
  node_points(patch, prepared, out.points);
  out.domain = SubDomain::unit(true);
}

namespace {

// Patch coordinates (x, y) to its face's (u, v): the inverse of TrianglePatch::to_patch.
void from_patch(int rotation, double x, double y, double& u, double& v) {
  switch (rotation) {
    case 0: u = x, v = y; break;
    case 1: u = 1 - x - y, v = x; break;
    default: u = y, v = 1 - x - y; break;
  }
}

// A tree node's own coordinates (its patch's, when turned) as seen through its parent's domain.
SubDomain child_domain(const SubDomain& parent, int c, int rotation) {
  return mapped_domain(parent, [&](double X, double Y) {
    double u = 0, v = 0;
    from_patch(rotation, X, Y, u, v);
    loop_parent(c, u, v);
    return std::array<double, 2>{u, v};
  });
}

}  // namespace

SubPatch TriangleFamily::leaf_patch(const SubPatch& in, double x, double y) const {
  auto [X, Y] = in.domain.local(x, y);
  in.domain.clamp_local(X, Y);
  std::size_t node = in.node;
  SubDomain domain = in.domain;
  while (refined(node)) {  // as locate_any's descent of the tree
    const auto [c, child] = loop_child(X, Y);
    X = child[0], Y = child[1];
    node = tree_.child(node, c);
    domain = child_domain(domain, c, refined(node) ? 0 : patches_[node].rotation);
  }
  SubPatch out;
  const TrianglePatch& patch = patches_[node];
  out.face = in.face;
  out.node = node;
  out.positions = in.positions;
  out.kind = kind_of(patch.valence, patch.region);
  node_points(patch, in.positions, out.points);
  into_frame_of(in, patches_[in.node].points[0], out.points);
  out.domain = domain;
  return out;
}

int TriangleFamily::split(const SubPatch& in, SubPatch* children) const {
  if (in.kind == kRefinedKind) {  // the node's four children, leaves with their patches
    for (int c = 0; c < 4; ++c) {
      SubPatch& out = children[c];
      const std::size_t child = tree_.child(in.node, c);
      const TrianglePatch& patch = patches_[child];
      out.face = in.face;
      out.node = child;
      out.positions = in.positions;
      out.kind = refined(child) ? kRefinedKind : kind_of(patch.valence, patch.region);
      node_points(patch, in.positions, out.points);
      into_frame_of(in, patches_[in.node].points[0], out.points);
      out.domain = child_domain(in.domain, c, refined(child) ? 0 : patch.rotation);
    }
    return 4;
  }
  checked_descent();
  const int m = tables_.dilation();
  int valence = 0, region = 0;
  kind_parts(in.kind, valence, region);
  const std::vector<TriangleChild>& cells = tables_.children(valence, region);
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const TriangleChild& cell = cells[c];
    SubPatch& out = children[c];
    apply(cell.rows, in.points, out.points);  // the rows' columns are the layout's: a sector's box is not read
    if (TriangleTables::is_sector_code(cell.valence)) append_sector_box(out.points, tables_.sector_spread(cell.valence));
    out.face = in.face;
    out.node = in.node;
    out.positions = in.positions;
    out.kind = kind_of(cell.valence, cell.region);
    // The kind's corner k is the cell's corner rotation + k.
    std::array<std::array<double, 2>, 3> corner;
    for (int k = 0; k < 3; ++k) {
      const auto local = cell_corner(m, static_cast<int>(c), (cell.rotation + k) % 3);
      corner[static_cast<std::size_t>(k)] = in.domain.at(local[0], local[1]);
    }
    out.domain = SubDomain::unit(true);
    out.domain.origin = corner[0];
    out.domain.x_axis = {corner[1][0] - corner[0][0], corner[1][1] - corner[0][1]};
    out.domain.y_axis = {corner[2][0] - corner[0][0], corner[2][1] - corner[0][1]};
  }
  return static_cast<int>(cells.size());
}

Approximation TriangleFamily::evaluate(const SubPatch& in, double x, double y, double tolerance) const {
  if (in.kind == kRefinedKind) return evaluate(leaf_patch(in, x, y), x, y, tolerance);
  int valence = 0, region = 0;
  std::vector<Point> points = layout_points(in, valence, region);
  auto l = in.domain.local(x, y);
  in.domain.clamp_local(l[0], l[1]);
  // Exact fractions where the doubles are (the descent then lands on the
  // tables' grids exactly). sqrt(3)'s steps scale by 3 and never shrink a
  // binary fraction's denominator: unless a stored grid holds it already, its
  // descent in fractions would only be slower.
  const auto fx = exact_fraction(l[0]), fy = exact_fraction(l[1]);
  bool reachable = fx && fy;
  if (reachable && tables_.dilation() == 3)
    reachable = std::any_of(tables_.rates().begin(), tables_.rates().end(), [&](int n) {
      return (3 * static_cast<std::int64_t>(n)) % fx->den == 0 && (3 * static_cast<std::int64_t>(n)) % fy->den == 0;
    });
  if (reachable) {
    try {
      return checked_descent().evaluate(valence, region, points, *fx, *fy, tolerance);
    } catch (const ParameterOverflow&) {
      points = layout_points(in, valence, region);
    }
  }
  return checked_descent().evaluate(valence, region, points, l[0], l[1], tolerance);
}

bool TriangleFamily::derivatives(const SubPatch& in, double& x, double& y, Derivatives& out) const {
  if (in.kind == kRefinedKind) return derivatives(leaf_patch(in, x, y), x, y, out);
  const TrianglePatchDescent& descent = checked_descent();
  auto l = in.domain.local(x, y);
  const bool inside = in.domain.contains_local(l[0], l[1]);
  in.domain.clamp_local(l[0], l[1]);
  int valence = 0, region = 0;
  std::vector<Point> points = layout_points(in, valence, region);
  // The own coordinates carry their derivatives along the patch's (x, y), so the result is along those.
  const auto j = in.domain.inverse_jacobian();
  if (tables_.polynomial_degree() <= 0) {
    // sqrt(3): the regular patch's derivative stencils are stored on the grids
    // 1/(3n), at nodes and centres, and the descent's steps (x 3) keep a point
    // of the finest grid on it: the nearest such point of the sub-patch.
    const std::int64_t g = 3 * static_cast<std::int64_t>(*std::max_element(tables_.rates().begin(), tables_.rates().end()));
    const double *wu = nullptr, *wv = nullptr;
    if (!tables_.grid(6, static_cast<int>(g / 3)).derivative_weights(TriangleTables::GridPoint::Node, 0, 0, wu, wv))
      return false;  // tables from before version 6
    std::int64_t a = 0, b = 0;
    if (!nearest_grid_point(l[0], l[1], g, a, b)) return false;
    if (valence != 6 && a == 0 && b == 0) return false;  // the extraordinary vertex: no parametric derivative
    try {
      out = descent.derivatives(valence, region, points, ExactDual{Fraction::make(a, g), j[0], j[1]},
                                ExactDual{Fraction::make(b, g), j[2], j[3]});
    } catch (const EvaluationError&) {
      return false;
    }
    const auto p = in.domain.at(static_cast<double>(a) / static_cast<double>(g), static_cast<double>(b) / static_cast<double>(g));
    x = p[0], y = p[1];
    return true;
  }
  if (valence != 6 && l[0] == 0 && l[1] == 0) return false;  // the extraordinary vertex: no parametric derivative
  try {
    out = descent.derivatives(valence, region, points, Dual{l[0], j[0], j[1]}, Dual{l[1], j[2], j[3]});
  } catch (const EvaluationError&) {  // within 2^-64 of the extraordinary vertex
    return false;
  }
  if (!inside) {  // (x, y) moves only where it was outside (the round trip through own coordinates rounds)
    const auto p = in.domain.at(l[0], l[1]);
    x = p[0], y = p[1];
  }
  return true;
}

FaceParameterReal TriangleFamily::original(std::size_t face, double x, double y) const {
  // Patch coordinates back to the node's own (the inverse of TrianglePatch::to_patch).
  double u = 0, v = 0;
  from_patch(patches_[face].rotation, x, y, u, v);
  // Up the levels refined round semi-sharp features to the prepared face.
  while (face >= topology_.faces()) {
    loop_parent(tree_.which(face), u, v);
    face = tree_.parent[face];
  }
  // Up the hierarchy: each child's parameter to its parent's (the inverse of loop_child() or ternary_child()).
  for (std::size_t level = hierarchy_.levels.size(); level-- > 0;) {
    const FaceHierarchy::Level& l = hierarchy_.levels[level];
    const auto& offsets = l.child_offsets;
    const std::size_t parent = static_cast<std::size_t>(std::upper_bound(offsets.begin(), offsets.end(), face) - offsets.begin()) - 1;
    const int c = static_cast<int>(face - offsets[parent]);
    if (l.scale == 3) {
      const TernaryCell& cell = ternary_cells()[static_cast<std::size_t>(c)];
      const double X = cell.down ? cell.a + 1 - v : u + cell.a;
      const double Y = cell.down ? u + v + cell.b : v + cell.b;
      u = X / 3, v = Y / 3;
    } else {
      loop_parent(c, u, v);
    }
    face = parent;
  }
  // The steps up round: a point on a border may land a few ulps outside (a
  // closest point came back at v = -2.8e-17, which evaluation then refused).
  domain(face).clamp(u, v);
  return {face, u, v};
}

const PolynomialPatch* TriangleFamily::polynomial_patch(int kind) const {
  if (kind != kind_of(6, 0) || !descent_ || tables_.polynomial_degree() <= 0 || !tables_.children_nonnegative()) return nullptr;
  std::call_once(polynomial_once_, [this] {
    // The regular patch's basis as stored (TriangleTables::polynomial): per
    // point h of the regular layout, the coefficients of u^e v^f, f = 0..d,
    // e = 0..d-f; a regular sub-patch has the same form over its own unit triangle.
    const int d = tables_.polynomial_degree();
    auto out = std::make_unique<PolynomialPatch>();
    out->triangle = true;
    out->degree = d;
    for (int f = 0; f <= d; ++f)
      for (int e = 0; e + f <= d; ++e) out->monomials.push_back({e, f});
    const std::size_t terms = out->monomials.size(), count = tables_.layout(6, 0).size();
    const std::vector<double>& coefficients = tables_.polynomial();
    for (std::size_t h = 0; h < count; ++h)
      out->coefficients.emplace_back(coefficients.begin() + static_cast<std::ptrdiff_t>(h * terms),
                                     coefficients.begin() + static_cast<std::ptrdiff_t>((h + 1) * terms));
    polynomial_ = std::move(out);
  });
  return polynomial_.get();
}

const AffineParameters* TriangleFamily::affine_parameters(int kind) const {
  if (kind != kind_of(6, 0) || !descent_ || !tables_.children_nonnegative()) return nullptr;
  std::call_once(affine_once_, [this] {
    // The regular patch's basis phi_h reproduces affine functions when the
    // scheme has linear precision: sum_h phi_h(x) g_h = x for the control
    // points' lattice positions g_h. Those are found by least squares over
    // every stored sample of the regular patch (its basis is locally linearly
    // independent), and the reproduction then checked at every sample: the
    // largest deviation is the residual (a scheme without it gets none).
    const int n = tables_.rates().back();
    const TriangleTables::Grid grid = tables_.grid(6, n, 0);
    const std::size_t count = tables_.layout(6, 0).size();
    std::vector<std::array<double, 2>> at;
    std::vector<const double*> rows;
    const double g = 3.0 * n;
    for (long j = 0; j <= n; ++j)
      for (long i = 0; i + j <= n; ++i) {
        rows.push_back(grid.weights(TriangleTables::GridPoint::Node, i, j)), at.push_back({i / double(n), j / double(n)});
        if (i + j <= n - 1)
          rows.push_back(grid.weights(TriangleTables::GridPoint::Up, i, j)), at.push_back({(3 * i + 1) / g, (3 * j + 1) / g});
        if (i + j <= n - 2)
          rows.push_back(grid.weights(TriangleTables::GridPoint::Down, i, j)), at.push_back({(3 * i + 2) / g, (3 * j + 2) / g});
      }
    Eigen::MatrixXd phi(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(count));
    Eigen::MatrixXd target(static_cast<Eigen::Index>(rows.size()), 2);
    for (std::size_t r = 0; r < rows.size(); ++r) {
      for (std::size_t h = 0; h < count; ++h) phi(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(h)) = rows[r][h];
      target(static_cast<Eigen::Index>(r), 0) = at[r][0], target(static_cast<Eigen::Index>(r), 1) = at[r][1];
    }
    if (phi.rows() < phi.cols()) return;
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(phi);
    if (qr.rank() < phi.cols()) return;  // the samples do not determine the positions
    const Eigen::MatrixXd positions = qr.solve(target);
    const Eigen::MatrixXd deviation = phi * positions - target;
    const Eigen::VectorXd sums = phi.rowwise().sum();
    const double residual = std::max(deviation.cwiseAbs().maxCoeff(), (sums.array() - 1).abs().maxCoeff());
    if (!(residual < 1e-9)) return;  // no linear precision
    auto out = std::make_unique<AffineParameters>();
    out->triangle = true;
    out->residual = residual;
    for (std::size_t h = 0; h < count; ++h)
      out->at.push_back({positions(static_cast<Eigen::Index>(h), 0), positions(static_cast<Eigen::Index>(h), 1)});
    affine_ = std::move(out);
  });
  return affine_.get();
}

}  // namespace stencil_runtime
