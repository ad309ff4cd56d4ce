#include "triangle/triangle_sector.hpp"

#include <algorithm>
#include <functional>
#include <set>
#include <string>

#include "algebra/exact_linear_system.hpp"
#include "algebra/integer_division.hpp"
#include "base/error.hpp"
#include "base/limits.hpp"
#include "triangle/triangle_masks.hpp"
#include "triangle/triangle_patch.hpp"

namespace sg {

BoundaryWedge::BoundaryWedge(int faces) : k_(faces) {
  if (faces < 1 || faces > limits::kMaxValence)
    throw Error("internal: no boundary sector of " + std::to_string(faces) + " faces");
}

std::optional<WedgePoint> BoundaryWedge::canonical(int s, long a, long b) const {
  if (a == 0 && b == 0) return WedgePoint{};
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

void add(WedgeRow& row, const WedgeRow& other, const Rational& w) {
  for (const auto& [q, x] : other) row[q] += w * x;
}

class WedgeRules {
 public:
  WedgeRules(const TriangleScheme& s, const BoundaryWedge& wedge, SectorKind kind) : s_(s), wedge_(wedge), kind_(kind) {
    if (s.refinement != TriangleRefinement::Loop)
      throw Error("scheme '" + s.name + "': boundary patches exist for Loop's refinement only");
    if (!s.has_crease)
      throw Error("scheme '" + s.name + "' names no crease_curve, so it has no rule along a boundary");
    if (kind != SectorKind::Crease && kind != SectorKind::Corner)
      throw Error(std::string("internal: no triangle sector of kind ") + sector_kind_name(kind));
    w6_ = *s.exact_neighbour_weight(6);
  }

  WedgeRow refined(const WedgePoint& p) const {
    if (wedge_.phantom(p)) {
      const auto parts = wedge_.phantom_parts(p);
      WedgeRow row;
      add(row, refined(parts[0]), Rational(1));
      add(row, refined(parts[1]), Rational(1));
      add(row, refined(parts[2]), Rational(-1));
      return row;
    }
    if (p.a % 2 == 0 && p.b % 2 == 0) return vertex(WedgePoint{p.sector, p.a / 2, p.b / 2});
    for (int i = 0; i < 6; ++i) {  // the edge from q to q + d_i whose midpoint is p
      const long* d = kTriangleNeighbours[i];
      if ((p.a - d[0]) % 2 != 0 || (p.b - d[1]) % 2 != 0) continue;
      const long qa = floor_div(p.a - d[0], 2), qb = floor_div(p.b - d[1], 2);
      const WedgePoint c0 = real(p.sector, qa, qb), c1 = real(p.sector, qa + d[0], qb + d[1]);
      WedgeRow row;
      if (same_ray(c0, c1)) {
        row[c0] += Rational(1, 2), row[c1] += Rational(1, 2);
        return row;
      }
      const long* l = kTriangleNeighbours[(i + 1) % 6];
      const long* r = kTriangleNeighbours[(i + 5) % 6];
      row[c0] += s_.edge_end, row[c1] += s_.edge_end;
      row[real(p.sector, qa + l[0], qb + l[1])] += s_.edge_opposite;
      row[real(p.sector, qa + r[0], qb + r[1])] += s_.edge_opposite;
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

  WedgeRow vertex(const WedgePoint& q) const {
    WedgeRow row;
    if (q.a == 0) {  // B
      if (kind_ == SectorKind::Corner) {
        row[q] += 1;
      } else {
        row[q] += s_.crease_centre;
        row[real(0, 1, 0)] += s_.crease_neighbour;
        row[real(wedge_.faces(), 1, 0)] += s_.crease_neighbour;
      }
    } else if (wedge_.on_boundary(q)) {  // along its ray
      row[q] += s_.crease_centre;
      row[real(q.sector, q.a - 1, 0)] += s_.crease_neighbour;
      row[real(q.sector, q.a + 1, 0)] += s_.crease_neighbour;
    } else {
      row[q] += 1 - 6 * w6_;
      for (const auto& d : kTriangleNeighbours) row[real(q.sector, q.a + d[0], q.b + d[1])] += w6_;
    }
    return row;
  }

  const TriangleScheme& s_;
  const BoundaryWedge& wedge_;
  SectorKind kind_;
  Rational w6_;
};

// The three regular children of face p (frame p, refined lattice): their corners.
constexpr long kRegularChildren[3][3][2] = {{{1, 0}, {2, 0}, {2, 1}}, {{1, 1}, {2, 1}, {2, 2}}, {{1, 0}, {2, 1}, {1, 1}}};

}  // namespace

WedgeRow refined_wedge_point(const TriangleScheme& scheme, const BoundaryWedge& wedge, SectorKind kind,
                             const WedgePoint& p) {
  return WedgeRules(scheme, wedge, kind).refined(p);
}

TriangleSectorPatch solve_triangle_sector(const TriangleScheme& scheme, const BoundarySector& sector, long g,
                                          const BivariateSolution& regular) {
  const int k = sector.faces, p = sector.position;
  if (k < 1 || k > limits::kMaxValence || p < 0 || p >= k)
    throw Error("internal: no boundary sector of " + std::to_string(k) + " faces with face " + std::to_string(p));
  if (regular.n != g) throw Error("internal: the regular solution is for another grid");
  const BoundaryWedge wedge(k);
  const WedgeRules rules(scheme, wedge, sector.kind);
  std::map<WedgePoint, WedgeRow> memo;
  auto refined = [&](const WedgePoint& x) -> const WedgeRow& {
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
  for (int t = 0; t <= k; ++t) points.insert(WedgePoint{t, 1, 0});
  for (;;) {
    std::set<WedgePoint> next = points;
    for (const auto& x : points)
      for (const auto& [q, w] : refined(x)) next.insert(q);
    for (const auto& x : children)
      for (const auto& [q, w] : refined(x)) next.insert(q);
    if (next.size() == points.size()) break;
    points = std::move(next);
  }
  TriangleSectorPatch out;
  out.sector = sector;
  out.grid = g;
  out.layout.push_back(WedgePoint{});
  for (int t = 0; t <= k; ++t) out.layout.push_back(WedgePoint{t, 1, 0});
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
  auto dense = [&](const WedgeRow& row, const Rational& w, std::vector<Rational>& into) {
    for (const auto& [q, x] : row) {
      const auto it = index.find(q);
      if (it == index.end()) throw Error("internal: a refined point needs a point outside the sector's layout");
      into[it->second] += w * x;
    }
  };

  // A0 and W(0).
  std::vector<std::vector<std::pair<std::size_t, Rational>>> a0(m);
  for (std::size_t h = 0; h < m; ++h) {
    std::vector<Rational> row(m);
    dense(refined(out.layout[h]), Rational(1), row);
    for (std::size_t c = 0; c < m; ++c)
      if (row[c] != 0) a0[h].emplace_back(c, row[c]);
  }
  out.child_at_vertex = a0;
  const LinearSolution fixed = left_fixed_vector(a0);
  if (fixed.status != LinearSolution::Status::Unique)
    throw Error("scheme '" + scheme.name + "', " + sector.name() + ": the limit stencil has " + fixed.describe());

  out.stencils.assign(static_cast<std::size_t>((g + 1) * (g + 1)), {});
  std::function<const std::vector<Rational>&(long, long)> solve = [&](long i, long j) -> const std::vector<Rational>& {
    std::vector<Rational>& w = out.stencils[static_cast<std::size_t>(j * (g + 1) + i)];
    if (!w.empty()) return w;
    std::vector<Rational> result(m);
    if (i == 0 && j == 0) {
      result = fixed.values;
    } else if (2 * (i + j) <= g) {  // the child at B: the same patch, one step on
      const std::vector<Rational>& fine = solve(2 * i, 2 * j);
      for (std::size_t h = 0; h < m; ++h)
        if (fine[h] != 0)
          for (const auto& [c, x] : a0[h]) result[c] += fine[h] * x;
    } else {  // a regular child: the box spline over the refined points at 2x
      const long xa = 2 * (i + j), xb = 2 * j;  // 2x in frame p, units of 1/g
      for (long ra = floor_div(xa, g) - 2; ra <= floor_div(xa, g) + 3; ++ra)
        for (long rb = floor_div(xb, g) - 2; rb <= floor_div(xb, g) + 3; ++rb) {
          const Rational phi = regular.at(xa - g * ra, xb - g * rb);
          if (phi != 0) dense(refined(canonical(ra, rb)), phi, result);
        }
    }
    return w = std::move(result);
  };
  for (long j = 0; j <= g; ++j)
    for (long i = 0; i + j <= g; ++i) solve(i, j);
  return out;
}

std::optional<TangentStencils> triangle_sector_tangents(const TriangleSectorPatch& patch, std::string& why) {
  if (patch.sector.kind != SectorKind::Crease) {
    why = "a corner has no tangent plane";
    return std::nullopt;
  }
  const long g = patch.grid;
  if (g < 2) throw Error("internal: a sector's tangents need a grid of at least 2");
  const std::size_t m = patch.layout.size();
  std::vector<std::vector<Real>> a0(m, std::vector<Real>(m, Real(0)));
  for (std::size_t r = 0; r < m; ++r)
    for (const auto& [c, w] : patch.child_at_vertex.at(r)) a0[r][c] += to_real(w);
  auto real = [&](long i, long j) {
    std::vector<Real> w;
    for (const Rational& x : patch.at(i, j)) w.push_back(to_real(x));
    return w;
  };
  // The samples: every node, numbered j-major over the triangle; the cells: the
  // grid's up and down triangles, counter-clockwise in (u, v).
  std::vector<std::vector<double>> samples;
  std::map<std::pair<long, long>, std::size_t> number;
  for (long j = 0; j <= g; ++j)
    for (long i = 0; i + j <= g; ++i) {
      number[{i, j}] = samples.size();
      samples.emplace_back();
      for (const Rational& x : patch.at(i, j)) samples.back().push_back(to_double(x));
    }
  std::vector<std::vector<std::size_t>> cells;
  for (long j = 0; j < g; ++j)
    for (long i = 0; i + j < g; ++i) {
      cells.push_back({number[{i, j}], number[{i + 1, j}], number[{i, j + 1}]});
      if (i + j + 2 <= g) cells.push_back({number[{i + 1, j}], number[{i + 1, j + 1}], number[{i, j + 1}]});
    }
  // The boundary curve's tangent at B: e_k - e_0 (layout positions 1 and 1 + k).
  std::vector<Real> boundary(m, Real(0));
  boundary[1] = -1;
  boundary[1 + static_cast<std::size_t>(patch.sector.faces)] = 1;
  return boundary_tangent_stencils(a0, real(g, 0), real(0, g), boundary, samples, cells, why);
}

TriangleSectorDescent triangle_sector_descent(const TriangleScheme& scheme, const BoundarySector& sector,
                                              const std::vector<SectorPoint>& regular_layout) {
  constexpr long kGrid = 8;  // the characteristic map's regularity is checked on this grid
  TriangleSectorPatch patch = solve_triangle_sector(scheme, sector, kGrid, solve_regular(scheme, kGrid));
  TriangleSectorDescent out;
  out.sector = sector;
  out.limit = patch.at(0, 0);
  out.tangents = triangle_sector_tangents(patch, out.no_tangents);
  out.child_at_vertex = std::move(patch.child_at_vertex);
  out.layout = std::move(patch.layout);
  std::map<WedgePoint, std::size_t> index;
  for (std::size_t h = 0; h < out.layout.size(); ++h) index[out.layout[h]] = h;
  const BoundaryWedge wedge(sector.faces);
  const WedgeRules rules(scheme, wedge, sector.kind);
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
      std::vector<std::pair<std::size_t, Rational>> row;
      for (const auto& [x, w] : rules.refined(*fine)) {
        if (w == 0) continue;
        const auto it = index.find(x);
        if (it == index.end()) throw Error("internal: a regular cell of " + sector.name() + " needs a point outside its layout");
        row.emplace_back(it->second, w);
      }
      std::sort(row.begin(), row.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
      out.regular_children[static_cast<std::size_t>(c)].push_back(std::move(row));
    }
  }
  return out;
}

std::vector<BoundarySector> triangle_sectors(int max_faces, bool corners) {
  std::vector<BoundarySector> out;
  for (SectorKind kind : {SectorKind::Crease, SectorKind::Corner}) {
    if (kind == SectorKind::Corner && !corners) continue;
    for (int k = 1; k <= max_faces; ++k) {
      if (k == 3 && kind == SectorKind::Crease) continue;  // regular boundary patches (phantom points)
      for (int p = 0; p < k; ++p) out.push_back({kind, k, p});
    }
  }
  return out;
}

}  // namespace sg
