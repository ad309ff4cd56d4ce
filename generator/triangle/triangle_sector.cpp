#include "triangle/triangle_sector.hpp"

#include <algorithm>
#include <functional>
#include <set>
#include <string>
#include <type_traits>

#include "algebra/limit_stencil.hpp"
#include "algebra/slit_fold.hpp"
#include "algebra/integer_division.hpp"
#include "base/error.hpp"
#include "base/limits.hpp"
#include "triangle/triangle_masks.hpp"
#include "triangle/triangle_patch.hpp"

namespace sg {

BoundaryWedge::BoundaryWedge(int faces, bool closed) : k_(faces), closed_(closed) {
  if (faces < (closed ? 3 : 1) || faces > limits::kMaxValence)
    throw Error("internal: no boundary sector of " + std::to_string(faces) + " faces");
}

std::optional<WedgePoint> BoundaryWedge::canonical(int s, long a, long b) const {
  if (a == 0 && b == 0) return WedgePoint{};
  if (closed_) {  // at most three turns bring a point into its wedge
    for (int turn = 0; turn <= 6; ++turn) {
      s = ((s % k_) + k_) % k_;
      if (a >= 1 && b >= 0 && b < a) return WedgePoint{s, a, b};
      if (b < 0) {
        into_previous_frame(a, b);
        --s;
      } else {
        into_next_frame(a, b);
        ++s;
      }
    }
    return std::nullopt;
  }
  // Each turn goes one way only (clockwise while b < 0, else counter-clockwise),
  // so six turns bring any point round to where it lies or past the rays.
  for (int turn = 0; turn <= 6; ++turn) {
    if (s < 0 || s > k_) return std::nullopt;
    if (s == k_) {  // ray k and the phantom row beyond it; the rest of frame k is outside
      if (a >= 1 && (b == 0 || b == 1)) return WedgePoint{s, a, b};
      if (b >= 0) return std::nullopt;
    } else if (a >= 1 && b >= 0 && b < a) {
      return WedgePoint{s, a, b};
    } else if (s == 0 && b < 0) {  // below ray 0: the phantom row only
      if (b == -1 && a >= 0) return WedgePoint{0, a, -1};
      return std::nullopt;
    }
    if (b < 0) {  // clockwise into frame s-1
      into_previous_frame(a, b);
      --s;
    } else {  // counter-clockwise into frame s+1
      into_next_frame(a, b);
      ++s;
    }
  }
  return std::nullopt;
}

std::array<WedgePoint, 3> BoundaryWedge::phantom_parts(const WedgePoint& p) const {
  auto real = [&](int s, long a, long b) {
    const auto q = canonical(s, a, b);
    if (!q || phantom(*q)) throw Error("internal: a phantom's part is not a real point");
    return *q;
  };
  if (p.sector == 0 && p.b == -1)  // across (a,0)-(a+1,0) from the up triangle with apex (a+1,1)
    return {real(0, p.a, 0), real(0, p.a + 1, 0), real(0, p.a + 1, 1)};
  if (p.sector == k_ && p.b == 1)  // across (a-1,0)-(a,0) from the down triangle with apex (a-1,-1)
    return {real(k_, p.a - 1, 0), real(k_, p.a, 0), real(k_, p.a - 1, -1)};
  throw Error("internal: not a phantom point");
}

namespace {

template <class T>
using Row = std::map<WedgePoint, T>;  // weights over (real) points

template <class T>
void add(Row<T>& row, const Row<T>& other, const T& w) {
  for (const auto& [q, x] : other) row[q] += w * x;
}

template <class T>
T convert(const Rational& x) {
  if constexpr (std::is_same_v<T, Rational>) return x;
  else return to_real(x);
}

Real as_real(const Rational& x) { return to_real(x); }
const Real& as_real(const Real& x) { return x; }

template <class T>
T magnitude(const T& x) {
  return x < 0 ? T(-x) : x;
}

// Loop's one step on the wedge chart, in T.
template <class T>
class WedgeRules {
 public:
  WedgeRules(const TriangleScheme& s, const BoundaryWedge& wedge, SectorKind kind) : s_(s), wedge_(wedge), kind_(kind) {
    if (s.refinement != TriangleRefinement::Loop)
      throw Error("scheme '" + s.name + "': boundary patches exist for Loop's refinement only");
    if (!s.has_crease)
      throw Error("scheme '" + s.name + "' names no crease_curve, so it has no rule along a boundary");
    if ((kind == SectorKind::Cone) != wedge.closed())
      throw Error(std::string("internal: a triangle sector of kind ") + sector_kind_name(kind) + " on the wrong chart");
    if (kind == SectorKind::Dart && wedge.faces() < 3)
      throw Error("internal: a dart of valence " + std::to_string(wedge.faces()));
    edge_end_ = convert<T>(s.edge_end), edge_opposite_ = convert<T>(s.edge_opposite);
    crease_centre_ = convert<T>(s.crease_centre), crease_neighbour_ = convert<T>(s.crease_neighbour);
    w6_ = convert<T>(*s.exact_neighbour_weight(6));
    if (kind == SectorKind::Dart) {
      if constexpr (std::is_same_v<T, Rational>) {
        const auto w = s.exact_neighbour_weight(wedge.faces());
        if (!w)
          throw Error("scheme '" + s.name + "', valence " + std::to_string(wedge.faces()) +
                      ": the smooth rule at a dart is irrational; solve it in high precision");
        dart_ = *w;
      } else {
        dart_ = s.real_neighbour_weight(wedge.faces());
      }
    }
  }

  Row<T> refined(const WedgePoint& p) const {
    if (wedge_.phantom(p)) {
      const auto parts = wedge_.phantom_parts(p);
      Row<T> row;
      add(row, refined(parts[0]), T(1));
      add(row, refined(parts[1]), T(1));
      add(row, refined(parts[2]), T(-1));
      return row;
    }
    if (p.a % 2 == 0 && p.b % 2 == 0) return vertex(WedgePoint{p.sector, p.a / 2, p.b / 2});
    for (int i = 0; i < 6; ++i) {  // the edge from q to q + d_i whose midpoint is p
      const long* d = kTriangleNeighbours[i];
      if ((p.a - d[0]) % 2 != 0 || (p.b - d[1]) % 2 != 0) continue;
      const long qa = floor_div(p.a - d[0], 2), qb = floor_div(p.b - d[1], 2);
      const WedgePoint c0 = real(p.sector, qa, qb), c1 = real(p.sector, qa + d[0], qb + d[1]);
      Row<T> row;
      if (same_ray(c0, c1)) {  // a boundary edge, or a side of a dart's slit
        row[c0] += T(Rational(1, 2)), row[c1] += T(Rational(1, 2));
        return row;
      }
      const long* l = kTriangleNeighbours[(i + 1) % 6];
      const long* r = kTriangleNeighbours[(i + 5) % 6];
      row[c0] += edge_end_, row[c1] += edge_end_;
      row[real(p.sector, qa + l[0], qb + l[1])] += edge_opposite_;
      row[real(p.sector, qa + r[0], qb + r[1])] += edge_opposite_;
      return row;
    }
    throw Error("internal: no Loop rule for a refined wedge point");
  }

 private:
  WedgePoint real(int s, long a, long b) const {
    const auto q = wedge_.canonical(s, a, b);
    if (!q || wedge_.phantom(*q))
      throw Error("internal: a boundary sector's rule needs a point beyond the boundary");
    return *q;
  }

  // Both on ray 0 or both on ray k (B is on both).
  bool same_ray(const WedgePoint& x, const WedgePoint& y) const {
    if (!wedge_.on_boundary(x) || !wedge_.on_boundary(y)) return false;
    if (x.a == 0 || y.a == 0) return true;
    return x.sector == y.sector;
  }

  Row<T> vertex(const WedgePoint& q) const {
    Row<T> row;
    const int k = wedge_.faces();
    if (q.a == 0) {  // B
      if (kind_ == SectorKind::Corner || kind_ == SectorKind::Cone) {
        row[q] += T(1);
      } else if (kind_ == SectorKind::Dart) {  // the smooth rule at valence k: e_k is e_0 again, seen once
        row[q] += T(1) - T(k) * dart_;
        for (int j = 0; j < k; ++j) row[real(j, 1, 0)] += dart_;
      } else {
        row[q] += crease_centre_;
        row[real(0, 1, 0)] += crease_neighbour_;
        row[real(k, 1, 0)] += crease_neighbour_;
      }
    } else if (wedge_.on_boundary(q)) {  // along its ray
      row[q] += crease_centre_;
      row[real(q.sector, q.a - 1, 0)] += crease_neighbour_;
      row[real(q.sector, q.a + 1, 0)] += crease_neighbour_;
    } else {
      row[q] += T(1) - T(6) * w6_;
      for (const auto& d : kTriangleNeighbours) row[real(q.sector, q.a + d[0], q.b + d[1])] += w6_;
    }
    return row;
  }

  const TriangleScheme& s_;
  const BoundaryWedge& wedge_;
  SectorKind kind_;
  T edge_end_, edge_opposite_, crease_centre_, crease_neighbour_, w6_, dart_ = 0;
};

// The three regular children of face p (frame p, refined lattice): their corners.
constexpr long kRegularChildren[3][3][2] = {{{1, 0}, {2, 0}, {2, 1}}, {{1, 1}, {2, 1}, {2, 2}}, {{1, 0}, {2, 1}, {1, 1}}};

}  // namespace

bool exact_triangle_sector(const TriangleScheme& scheme, const BoundarySector& sector) {
  return sector.kind != SectorKind::Dart || scheme.exact_neighbour_weight(sector.faces).has_value();
}

template <class T>
TriangleSectorPatch<T> solve_triangle_sector(const TriangleScheme& scheme, const BoundarySector& sector, long g,
                                             const BivariateSolution& regular) {
  const int k = sector.faces, p = sector.position;
  if (k < 1 || k > limits::kMaxValence || p < 0 || p >= k)
    throw Error("internal: no boundary sector of " + std::to_string(k) + " faces with face " + std::to_string(p));
  if (regular.n != g) throw Error("internal: the regular solution is for another grid");
  const bool cone = sector.kind == SectorKind::Cone;
  if (cone && p != 0) throw Error("internal: a cone point's patch is made for position 0 only");
  const BoundaryWedge wedge(k, cone);
  const int rays = cone ? k - 1 : k;  // e_0..e_rays
  const WedgeRules<T> rules(scheme, wedge, sector.kind);
  std::map<WedgePoint, Row<T>> memo;
  auto refined = [&](const WedgePoint& x) -> const Row<T>& {
    auto it = memo.find(x);
    if (it == memo.end()) it = memo.emplace(x, rules.refined(x)).first;
    return it->second;
  };
  auto canonical = [&](long a, long b) {
    const auto q = wedge.canonical(p, a, b);
    if (!q) throw Error("internal: the sector's patch reaches beyond the phantom rows");
    return *q;
  };

  // The control points: whatever the refined points of the child at B and of
  // the regular children's 12 need, until nothing new is needed.
  std::set<WedgePoint> children;
  for (const auto& child : kRegularChildren)
    for (const auto& c : child) {
      children.insert(canonical(c[0], c[1]));
      for (const auto& d : kTriangleNeighbours) children.insert(canonical(c[0] + d[0], c[1] + d[1]));
    }
  std::set<WedgePoint> points{WedgePoint{}};
  for (int t = 0; t <= rays; ++t) points.insert(WedgePoint{t, 1, 0});
  for (;;) {
    std::set<WedgePoint> next = points;
    for (const auto& x : points)
      for (const auto& [q, w] : refined(x)) next.insert(q);
    for (const auto& x : children)
      for (const auto& [q, w] : refined(x)) next.insert(q);
    if (next.size() == points.size()) break;
    points = std::move(next);
  }
  TriangleSectorPatch<T> out;
  out.sector = sector;
  out.grid = g;
  out.layout.push_back(WedgePoint{});
  for (int t = 0; t <= rays; ++t) out.layout.push_back(WedgePoint{t, 1, 0});
  std::vector<WedgePoint> rest;
  for (const auto& x : points)
    if (x.a >= 2 || (x.a == 1 && x.b != 0)) rest.push_back(x);
  std::sort(rest.begin(), rest.end(), [](const WedgePoint& x, const WedgePoint& y) {
    return std::tie(x.a, x.sector, x.b) < std::tie(y.a, y.sector, y.b);
  });
  out.layout.insert(out.layout.end(), rest.begin(), rest.end());
  std::map<WedgePoint, std::size_t> index;
  for (std::size_t h = 0; h < out.layout.size(); ++h) index[out.layout[h]] = h;
  const std::size_t m = out.layout.size();
  auto dense = [&](const Row<T>& row, const T& w, std::vector<T>& into) {
    for (const auto& [q, x] : row) {
      const auto it = index.find(q);
      if (it == index.end()) throw Error("internal: a refined point needs a point outside the sector's layout");
      into[it->second] += w * x;
    }
  };

  // A0 and W(0).
  std::vector<std::vector<std::pair<std::size_t, T>>> a0(m);
  for (std::size_t h = 0; h < m; ++h) {
    std::vector<T> row(m, T(0));
    dense(refined(out.layout[h]), T(1), row);
    for (std::size_t c = 0; c < m; ++c)
      if (row[c] != 0) a0[h].emplace_back(c, row[c]);
  }
  out.child_at_vertex = a0;
  const std::vector<T> fixed = limit_stencil(a0, "scheme '" + scheme.name + "', " + sector.name());
  {
    std::vector<T> diff = fixed;
    for (T& x : diff) x = -x;
    for (std::size_t h = 0; h < m; ++h)
      for (const auto& [c, x] : a0[h]) diff[c] += fixed[h] * x;
    for (const T& d : diff) out.eigen_residual = std::max(out.eigen_residual, magnitude(d));
    if constexpr (std::is_same_v<T, Rational>)
      if (out.eigen_residual != 0) throw Error("internal: " + sector.name() + ": the exact limit stencil is not fixed");
  }

  out.stencils.assign(static_cast<std::size_t>((g + 1) * (g + 1)), {});
  std::function<const std::vector<T>&(long, long)> solve = [&](long i, long j) -> const std::vector<T>& {
    std::vector<T>& w = out.stencils[static_cast<std::size_t>(j * (g + 1) + i)];
    if (!w.empty()) return w;
    std::vector<T> result(m, T(0));
    if (i == 0 && j == 0) {
      result = fixed;
    } else if (2 * (i + j) <= g) {  // the child at B: the same patch, one step on
      const std::vector<T>& fine = solve(2 * i, 2 * j);
      for (std::size_t h = 0; h < m; ++h)
        if (fine[h] != 0)
          for (const auto& [c, x] : a0[h]) result[c] += fine[h] * x;
    } else {  // a regular child: the box spline over the refined points at 2x
      const long xa = 2 * (i + j), xb = 2 * j;  // 2x in frame p, units of 1/g
      for (long ra = floor_div(xa, g) - 2; ra <= floor_div(xa, g) + 3; ++ra)
        for (long rb = floor_div(xb, g) - 2; rb <= floor_div(xb, g) + 3; ++rb) {
          const Rational phi = regular.at(xa - g * ra, xb - g * rb);
          if (phi != 0) dense(refined(canonical(ra, rb)), convert<T>(phi), result);
        }
    }
    return w = std::move(result);
  };
  for (long j = 0; j <= g; ++j)
    for (long i = 0; i + j <= g; ++i) solve(i, j);
  return out;
}

template <class T>
std::optional<TangentStencils> triangle_sector_tangents(const TriangleSectorPatch<T>& patch, std::string& why) {
  const SectorKind kind = patch.sector.kind;
  if (kind != SectorKind::Crease && kind != SectorKind::Dart) {
    why = kind == SectorKind::Cone ? "a cone point has no tangent plane" : "a corner has no tangent plane";
    return std::nullopt;
  }
  const long g = patch.grid;
  if (g < 2) throw Error("internal: a sector's tangents need a grid of at least 2");
  const std::size_t m = patch.layout.size();
  const int k = patch.sector.faces;
  // A dart's slit folded shut (algebra/slit_fold.hpp): each point on ray k
  // onto its twin on ray 0 where the layout holds both (a point of ray k whose
  // twin the layout lacks stands for itself).
  const bool dart = kind == SectorKind::Dart;
  std::map<WedgePoint, std::size_t> index;
  for (std::size_t h = 0; h < m; ++h) index[patch.layout[h]] = h;
  std::vector<std::size_t> twin(m);
  for (std::size_t h = 0; h < m; ++h) {
    const WedgePoint& q = patch.layout[h];
    const auto it = dart && q.sector == k && q.b == 0 ? index.find(WedgePoint{0, q.a, 0}) : index.end();
    twin[h] = it == index.end() ? h : it->second;
  }
  const SlitFold fold(twin);
  // The samples: every node, numbered j-major over the triangle; the cells: the
  // grid's up and down triangles, counter-clockwise in (u, v).
  std::vector<std::vector<double>> samples;
  std::map<std::pair<long, long>, std::size_t> number;
  for (long j = 0; j <= g; ++j)
    for (long i = 0; i + j <= g; ++i) {
      number[{i, j}] = samples.size();
      samples.emplace_back();
      for (const Real& x : fold.weights(patch.at(i, j))) samples.back().push_back(to_double(x));
    }
  std::vector<std::vector<std::size_t>> cells;
  for (long j = 0; j < g; ++j)
    for (long i = 0; i + j < g; ++i) {
      cells.push_back({number[{i, j}], number[{i + 1, j}], number[{i, j + 1}]});
      if (i + j + 2 <= g) cells.push_back({number[{i + 1, j}], number[{i + 1, j + 1}], number[{i, j + 1}]});
    }
  // The boundary curve's tangent at B: e_k - e_0 (layout positions 1 and 1 + k); none at a dart.
  std::vector<Real> boundary;
  if (!dart) {
    boundary.assign(m, Real(0));
    boundary[1] = -1;
    boundary[1 + static_cast<std::size_t>(k)] = 1;
  }
  auto t = boundary_tangent_stencils(fold.matrix(patch.child_at_vertex), fold.weights(patch.at(g, 0)), fold.weights(patch.at(0, g)),
                                     boundary, samples, cells, why);
  if (t)  // back onto the layout: weight on ray 0, none on its copies
    for (std::vector<Real>* s : {&t->u, &t->v}) *s = fold.spread(*s);
  return t;
}

namespace {

SectorWeight weight_of(const Rational& x) { return {as_real(x), to_string(x)}; }
SectorWeight weight_of(const Real& x) { return {x, to_string(x, 40)}; }

template <class T>
TriangleSectorDescent sector_descent(const TriangleScheme& scheme, const BoundarySector& sector,
                                     const std::vector<SectorPoint>& regular_layout) {
  constexpr long kGrid = 8;  // the characteristic map's regularity is checked on this grid
  TriangleSectorPatch<T> patch = solve_triangle_sector<T>(scheme, sector, kGrid, solve_regular(scheme, kGrid));
  TriangleSectorDescent out;
  out.sector = sector;
  out.exact = std::is_same_v<T, Rational>;
  out.eigen_residual = as_real(patch.eigen_residual);
  for (const T& x : patch.at(0, 0)) out.limit.push_back(weight_of(x));
  out.tangents = triangle_sector_tangents(patch, out.no_tangents);
  for (const auto& row : patch.child_at_vertex) {
    out.child_at_vertex.emplace_back();
    for (const auto& [c, w] : row) out.child_at_vertex.back().emplace_back(c, weight_of(w));
  }
  out.layout = std::move(patch.layout);
  std::map<WedgePoint, std::size_t> index;
  for (std::size_t h = 0; h < out.layout.size(); ++h) index[out.layout[h]] = h;
  const BoundaryWedge wedge(sector.faces, sector.kind == SectorKind::Cone);
  const WedgeRules<T> rules(scheme, wedge, sector.kind);
  for (int c = 0; c < 3; ++c) {
    const long(&corner)[3][2] = kRegularChildren[c];
    for (const SectorPoint& q : regular_layout) {
      long a = q.a, b = q.b;  // into the kind's frame: q.sector turns of 60 degrees
      for (int t = 0; t < ((q.sector % 6) + 6) % 6; ++t) into_previous_frame(a, b);
      // The kind's frame on the cell: X = corner 1 - corner 0, Y = corner 2 - corner 1.
      const long fa = corner[0][0] + a * (corner[1][0] - corner[0][0]) + b * (corner[2][0] - corner[1][0]);
      const long fb = corner[0][1] + a * (corner[1][1] - corner[0][1]) + b * (corner[2][1] - corner[1][1]);
      const auto fine = wedge.canonical(sector.position, fa, fb);
      if (!fine) throw Error("internal: a regular cell of " + sector.name() + " reaches beyond the phantom rows");
      std::vector<std::pair<std::size_t, SectorWeight>> row;
      for (const auto& [x, w] : rules.refined(*fine)) {
        if (w == 0) continue;
        const auto it = index.find(x);
        if (it == index.end()) throw Error("internal: a regular cell of " + sector.name() + " needs a point outside its layout");
        row.emplace_back(it->second, weight_of(w));
      }
      std::sort(row.begin(), row.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
      out.regular_children[static_cast<std::size_t>(c)].push_back(std::move(row));
    }
  }
  return out;
}

}  // namespace

TriangleSectorDescent triangle_sector_descent(const TriangleScheme& scheme, const BoundarySector& sector,
                                              const std::vector<SectorPoint>& regular_layout) {
  return exact_triangle_sector(scheme, sector) ? sector_descent<Rational>(scheme, sector, regular_layout)
                                               : sector_descent<Real>(scheme, sector, regular_layout);
}

std::vector<BoundarySector> triangle_sectors(int max_faces, bool sharp) {
  std::vector<BoundarySector> out;
  for (SectorKind kind : {SectorKind::Crease, SectorKind::Corner, SectorKind::Dart, SectorKind::Cone}) {
    if (kind != SectorKind::Crease && !sharp) continue;
    const bool ring = kind == SectorKind::Dart || kind == SectorKind::Cone;
    for (int k = ring ? 3 : 1; k <= max_faces; ++k) {
      if (k == 3 && kind == SectorKind::Crease) continue;  // regular boundary patches (phantom points)
      for (int p = 0; p < (kind == SectorKind::Cone ? 1 : k); ++p) out.push_back({kind, k, p});
    }
  }
  return out;
}

template struct TriangleSectorPatch<Rational>;
template struct TriangleSectorPatch<Real>;
template TriangleSectorPatch<Rational> solve_triangle_sector(const TriangleScheme&, const BoundarySector&, long,
                                                             const BivariateSolution&);
template TriangleSectorPatch<Real> solve_triangle_sector(const TriangleScheme&, const BoundarySector&, long,
                                                         const BivariateSolution&);
template std::optional<TangentStencils> triangle_sector_tangents(const TriangleSectorPatch<Rational>&, std::string&);
template std::optional<TangentStencils> triangle_sector_tangents(const TriangleSectorPatch<Real>&, std::string&);

}  // namespace sg
