#include "triangle/triangle_children.hpp"

#include <array>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <type_traits>

#include "algebra/exact_linear_system.hpp"
#include "base/error.hpp"
#include "triangle/triangle_patch.hpp"
#include "triangle/triangle_refinement.hpp"

namespace sg {
namespace {

using Vec = std::array<long, 2>;

// The 60-degree turn of the lattice (e_k -> e_{k+1}) in a sector's frame:
// (1,0) -> (1,1) -> (0,1) -> (-1,0) -> ...
Vec turn(Vec x, int times) {
  for (int t = 0; t < ((times % 6) + 6) % 6; ++t) x = {x[0] - x[1], x[0]};
  return x;
}

struct Cell {
  std::array<Vec, 3> corners;  // in 1/m units of the patch's (u, v)
};

std::vector<Cell> cells(long m) {
  std::vector<Cell> out;
  for (long b = 0; b < m; ++b)
    for (long a = 0; a + b < m; ++a) out.push_back({{{{a, b}, {a + 1, b}, {a, b + 1}}}});
  for (long b = 0; b + 1 < m; ++b)
    for (long a = 0; a + b + 1 < m; ++a) out.push_back({{{{a + 1, b}, {a + 1, b + 1}, {a, b + 1}}}});
  return out;
}

const std::vector<std::vector<SectorPoint>>& layouts_of(const TriangleLayouts& layouts, int valence) {
  for (const auto& [v, regions] : layouts)
    if (v == valence) return regions;
  throw Error("internal: no layout for valence " + std::to_string(valence));
}

template <class T>
std::vector<TriangleChild> children_in(const TriangleScheme& scheme, int valence, int region, const TriangleLayouts& layouts,
                                       std::vector<SectorPoint>* missing) {
  const long m = scheme.dilation();
  const std::string context = "scheme '" + scheme.name + "', valence " + std::to_string(valence) + ", region " + std::to_string(region);
  const SectorChart chart(valence, 4 * patch_rings(scheme));
  const TriangleWeights<T> weights = triangle_weights<T>(scheme, valence);
  const std::vector<SectorPoint>& parent = layouts_of(layouts, valence).at(static_cast<std::size_t>(region));
  std::map<std::size_t, std::size_t> position;  // chart id -> position in the parent's layout
  for (std::size_t h = 0; h < parent.size(); ++h) position.emplace(chart.index(parent[h]), h);

  const auto c = region_corners(region);
  const Vec c0{c[0].first, c[0].second}, du{c[1].first - c[0].first, c[1].second - c[0].second},
      dv{c[2].first - c[0].first, c[2].second - c[0].second};
  const int kinds = valence == 6 ? 0 : patch_regions(scheme, valence);
  const long near = irregular_radius(scheme);  // refined rings within which cells are not regular

  std::vector<TriangleChild> out;
  for (const Cell& cell : cells(m)) {
    std::array<Vec, 3> k;  // the cell's corners on the refined lattice, sector 0's frame
    for (int i = 0; i < 3; ++i) {
      const Vec& p = cell.corners[static_cast<std::size_t>(i)];
      k[static_cast<std::size_t>(i)] = {m * c0[0] + p[0] * du[0] + p[1] * dv[0], m * c0[1] + p[0] * du[1] + p[1] * dv[1]};
    }
    TriangleChild child;
    bool matched = false;
    bool is_near = kinds > 0;
    for (const Vec& x : k) is_near = is_near && x[0] <= near;  // corners in the closed wedge: ring = a
    for (int r = 0; is_near && r < kinds && !matched; ++r) {
      const auto rc = region_corners(r);
      for (int rot = 0; rot < 3 && !matched; ++rot) {
        bool same = true;
        for (int i = 0; i < 3; ++i) {
          const Vec& x = k[static_cast<std::size_t>((rot + i) % 3)];
          same = same && x[0] == rc[static_cast<std::size_t>(i)].first && x[1] == rc[static_cast<std::size_t>(i)].second;
        }
        if (same) child.valence = valence, child.region = r, child.rotation = rot, matched = true;
      }
    }
    if (is_near && !matched) throw Error("internal: " + context + ": a cell near the EV is no region");
    int direction = 0;  // regular: the turn that carries e_0 to the cell's first edge
    if (!matched) {
      const Vec d{k[1][0] - k[0][0], k[1][1] - k[0][1]};
      while (direction < 6 && turn({1, 0}, direction) != d) ++direction;
      const Vec e{k[2][0] - k[0][0], k[2][1] - k[0][1]};
      if (direction == 6 || turn(d, 1) != e) throw Error("internal: " + context + ": a cell is not a lattice triangle");
      child.valence = 6, child.region = 0, child.rotation = 0;
    }
    const std::vector<SectorPoint>& kind = layouts_of(layouts, child.valence).at(static_cast<std::size_t>(child.region));
    for (const SectorPoint& q : kind) {
      SectorPoint fine = q;  // the EV's patch and the band: the same chart point, refined
      if (!matched) {
        const Vec x = turn(turn({q.a, q.b}, q.sector), direction);
        // Round a regular vertex any path is the same; round the EV, at most two
        // sectors (as the patch solver's regular children).
        const auto p = chart.canonical(0, k[0][0] + x[0], k[0][1] + x[1], valence == 6 ? 6 : 2);
        if (!p) throw Error("internal: " + context + ": a regular child's point is too far round the EV");
        fine = *p;
      }
      std::vector<std::pair<std::size_t, double>> row;
      std::vector<std::pair<std::size_t, Real>> real_row;
      for (const auto& [id, w] : refined_point(scheme.refinement, chart, weights, fine)) {
        const auto at = position.find(id);
        if (at == position.end()) {
          if (!missing) throw Error("internal: " + context + ": a child needs a point outside the patch's layout");
          missing->push_back(chart.point(id));
          continue;
        }
        if (w < 0) child.nonnegative = false;
        row.emplace_back(at->second, to_double(w));
        if constexpr (std::is_same_v<T, Rational>) real_row.emplace_back(at->second, to_real(w));
        else real_row.emplace_back(at->second, w);
      }
      child.rows.push_back(std::move(row));
      child.real_rows.push_back(std::move(real_row));
    }
    out.push_back(std::move(child));
  }
  return out;
}

}  // namespace

std::vector<TriangleChild> triangle_children(const TriangleScheme& scheme, int valence, int region,
                                             const TriangleLayouts& layouts, std::vector<SectorPoint>* missing) {
  if (scheme.exact_neighbour_weight(valence)) return children_in<Rational>(scheme, valence, region, layouts, missing);
  return children_in<Real>(scheme, valence, region, layouts, missing);
}

void close_layouts(const TriangleScheme& scheme, TriangleLayouts& layouts) {
  for (bool changed = true; changed;) {
    changed = false;
    for (auto& [v, regions] : layouts)
      for (std::size_t r = 0; r < regions.size(); ++r) {
        std::vector<SectorPoint> missing;
        triangle_children(scheme, v, static_cast<int>(r), layouts, &missing);
        if (missing.empty()) continue;
        // Keep chart order (ring a, then sector, then b), as the binary writes it.
        std::map<std::tuple<long, int, long>, SectorPoint> ordered;
        for (const SectorPoint& p : regions[r]) ordered.emplace(std::tuple{p.a, p.sector, p.b}, p);
        for (const SectorPoint& p : missing) ordered.emplace(std::tuple{p.a, p.sector, p.b}, p);
        regions[r].clear();
        for (const auto& [key, p] : ordered) regions[r].push_back(p);
        changed = true;
      }
  }
}

namespace {

constexpr long kPolynomialGrid = 12;  // holds the nodes of degrees 1, 2, 3, 4 and 6

TrianglePatch<Rational> regular_patch_on_polynomial_grid(const TriangleScheme& scheme) {
  return solve_triangle_patch<Rational>(scheme, 6, kPolynomialGrid, solve_regular(scheme, kPolynomialGrid));
}

// The interpolating polynomials of `patch` (the regular patch on the grid
// kPolynomialGrid) over `layout`, or degree 0.
RegularPolynomial interpolate_regular_patch(const TrianglePatch<Rational>& patch, const std::vector<SectorPoint>& layout) {
  constexpr long g = kPolynomialGrid;
  // values[h][(i, j)]: point h's weight at (i/g, j/g)
  std::map<std::size_t, std::size_t> position;
  for (std::size_t h = 0; h < layout.size(); ++h) position.emplace(patch.chart.index(layout[h]), h);
  std::vector<std::map<std::pair<long, long>, Rational>> values(layout.size());
  for (long j = 0; j <= g; ++j)
    for (long i = 0; i + j <= g; ++i)
      for (const auto& [id, w] : patch.at(i, j)) {
        const auto at = position.find(id);
        if (at == position.end()) return {};  // the layout does not cover the patch: no basis to give
        values[at->second][{i, j}] = w;
      }
  for (int d = 1; d <= 6; ++d) {
    RegularPolynomial out;
    out.degree = d;
    const std::size_t unknowns = static_cast<std::size_t>((d + 1) * (d + 2) / 2);
    bool all = true;
    for (std::size_t h = 0; h < layout.size() && all; ++h) {
      ExactLinearSystem system(unknowns);
      for (long j = 0; j <= g; ++j)
        for (long i = 0; i + j <= g; ++i) {
          std::vector<std::pair<std::size_t, Rational>> row;
          const Rational u(i, g), v(j, g);
          std::size_t col = 0;
          Rational vf = 1;
          for (int f = 0; f <= d; ++f, vf *= v) {
            Rational term = vf;
            for (int e = 0; e + f <= d; ++e, term *= u) row.emplace_back(col++, term);
          }
          const auto it = values[h].find({i, j});
          system.add_equation(row, it == values[h].end() ? Rational(0) : it->second);
        }
      const LinearSolution s = system.solve();
      if (s.status != LinearSolution::Status::Unique) {
        all = false;
        break;
      }
      std::vector<double> c;
      for (const Rational& x : s.values) c.push_back(to_double(x));
      out.coefficients.push_back(std::move(c));
    }
    if (all) return out;
  }
  return {};
}

}  // namespace

bool regular_basis_is_polynomial(const TriangleScheme& scheme) {
  // Every chart point the regular patch's stencils use, as the layout.
  const TrianglePatch<Rational> patch = regular_patch_on_polynomial_grid(scheme);
  std::set<std::size_t> used;
  for (const auto& stencil : patch.stencils)
    for (const auto& [id, w] : stencil) used.insert(id);
  std::vector<SectorPoint> layout;
  for (std::size_t id : used) layout.push_back(patch.chart.point(id));
  return interpolate_regular_patch(patch, layout).degree > 0;
}

RegularPolynomial regular_polynomial(const TriangleScheme& scheme, const std::vector<SectorPoint>& layout) {
  return interpolate_regular_patch(regular_patch_on_polynomial_grid(scheme), layout);
}

}  // namespace sg
