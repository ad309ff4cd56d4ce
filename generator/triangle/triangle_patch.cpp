#include "triangle/triangle_patch.hpp"

#include <algorithm>
#include <map>

#include "algebra/limit_stencil.hpp"
#include "algebra/integer_division.hpp"
#include "base/error.hpp"
#include "triangle/triangle_masks.hpp"

namespace sg {
namespace {

std::string where(const TriangleScheme& s, int valence) {
  return "scheme '" + s.name + "', valence " + std::to_string(valence);
}

template <class T>
T magnitude(const T& x) {
  return x < 0 ? T(-x) : x;
}

}  // namespace

// Loop: after one step only the EV's own new point depends on its irregular
// rule, so every child but the EV's is regular (radius 1); the regular children
// reach 2 + 2 (open) rings. sqrt(3): after two steps the points within 2 fine
// rings of the EV depend on its rule, and the regular scaling function reaches
// 2.5 rings, so the children within 2 fine rings of the EV are not regular
// (radius 2: the wedge up to a = 2, beyond the patch itself); the regular ones
// reach 3 * 2 + 2.5 rings.
long patch_rings(const TriangleScheme& scheme) { return scheme.refinement == TriangleRefinement::Loop ? 3 : 8; }
long irregular_radius(const TriangleScheme& scheme) { return scheme.refinement == TriangleRefinement::Loop ? 1 : 2; }

int patch_regions(const TriangleScheme& scheme, int valence) { return irregular_radius(scheme) > 1 && valence != 6 ? 4 : 1; }

std::array<LatticeIndex, 3> region_corners(int region) {
  switch (region) {
    case 0: return {{{0, 0}, {1, 0}, {1, 1}}};
    case 1: return {{{1, 0}, {2, 0}, {2, 1}}};
    case 2: return {{{1, 0}, {2, 1}, {1, 1}}};
    case 3: return {{{1, 1}, {2, 1}, {2, 2}}};
    default: throw Error("internal: no patch region " + std::to_string(region));
  }
}

LatticeIndex region_point(int region, long i, long j, long g) {
  const auto c = region_corners(region);
  return {g * c[0].first + i * (c[1].first - c[0].first) + j * (c[2].first - c[0].first),
          g * c[0].second + i * (c[1].second - c[0].second) + j * (c[2].second - c[0].second)};
}

template <class T>
const SparseRow<T>& TrianglePatch<T>::at(int region, long i, long j) const {
  const auto [ya, yb] = region_point(region, i, j, grid);
  if (ya <= grid) return at(ya - yb, yb);
  const auto it = beyond.find({ya, yb});
  if (it == beyond.end() || it->second.empty())
    throw Error("internal: region " + std::to_string(region) + " point (" + std::to_string(i) + "," + std::to_string(j) +
                ")/" + std::to_string(grid) + " was not solved");
  return it->second;
}

namespace {
BivariateMask regular_mask(const TriangleScheme& scheme) {
  const Rational w = *scheme.exact_neighbour_weight(6);
  return scheme.refinement == TriangleRefinement::Loop
             ? loop_regular_mask(scheme.edge_end, scheme.edge_opposite, 1 - 6 * w, w)
             : sqrt3_composite_mask(6 * w);
}
}  // namespace

BivariateSolution solve_regular(const TriangleScheme& scheme, long g) { return solve_bivariate(regular_mask(scheme), g); }

std::pair<BivariateSolution, BivariateGradient> solve_regular_with_gradient(const TriangleScheme& scheme, long g) {
  try {
    return solve_bivariate_with_gradient(regular_mask(scheme), g);
  } catch (const Error& e) {
    throw Error("scheme '" + scheme.name + "': the regular patch has no derivative stencils (is it C1, and does it "
                "reproduce linear functions?): " + e.what());
  }
}

template <>
TriangleWeights<Rational> triangle_weights(const TriangleScheme& s, int valence) {
  const auto w = s.exact_neighbour_weight(valence);
  if (!w) throw Error(where(s, valence) + ": the vertex rule is irrational here; solve it in high precision");
  return {s.edge_end, s.edge_opposite, *w, *s.exact_neighbour_weight(6)};
}

template <>
TriangleWeights<Real> triangle_weights(const TriangleScheme& s, int valence) {
  return {to_real(s.edge_end), to_real(s.edge_opposite), s.real_neighbour_weight(valence),
          to_real(*s.exact_neighbour_weight(6))};
}

template <class T>
TrianglePatch<T> solve_triangle_patch(const TriangleScheme& scheme, int valence, long g, const BivariateSolution& regular,
                                      const std::vector<std::array<long, 3>>& band, const BivariateGradient* gradient) {
  if (g < 1) throw Error("grid must be at least 1");
  if (regular.n != g) throw Error("internal: the regular solution is on the grid " + std::to_string(regular.n));
  const std::string context = where(scheme, valence);
  const long m = scheme.dilation();
  TrianglePatch<T> out;
  out.valence = valence;
  out.grid = g;
  out.chart = SectorChart(valence, patch_rings(scheme));
  const SectorChart& chart = out.chart;
  const std::size_t size = chart.size();
  const TriangleWeights<T> weights = triangle_weights<T>(scheme, valence);
  const std::vector<SparseRow<T>> a = refinement_matrix(scheme.refinement, chart, weights);

  // The regular scaling function in T, and its support's bounding box (1/g units).
  std::map<LatticeIndex, T> phi;
  long lo_a = 0, hi_a = 0, lo_b = 0, hi_b = 0;
  for (const auto& [k, x] : regular.values) {
    if (x == 0) continue;
    if constexpr (std::is_same_v<T, Rational>) phi.emplace(k, x);
    else phi.emplace(k, to_real(x));
    lo_a = std::min(lo_a, k.first), hi_a = std::max(hi_a, k.first);
    lo_b = std::min(lo_b, k.second), hi_b = std::max(hi_b, k.second);
  }

  // f A for a sparse f, accumulated in one dense scratch row (no per-point allocation of T).
  std::vector<T> scratch(size);
  std::vector<char> touched(size, 0);
  std::vector<std::size_t> touched_list;
  auto accumulate = [&](std::size_t c, const T& x) {
    if (!touched[c]) touched[c] = 1, touched_list.push_back(c);
    scratch[c] += x;
  };
  auto collect = [&]() {
    std::sort(touched_list.begin(), touched_list.end());
    SparseRow<T> out;
    out.reserve(touched_list.size());
    for (std::size_t c : touched_list) {
      if (scratch[c] != 0) out.emplace_back(c, scratch[c]);
      scratch[c] = 0;
      touched[c] = 0;
    }
    touched_list.clear();
    return out;
  };
  auto times_a = [&](const SparseRow<T>& f) {
    T product;
    for (const auto& [r, fr] : f)
      for (const auto& [c, x] : a[r]) {
        product = fr;
        product *= x;
        accumulate(c, product);
      }
    return collect();
  };
  // The regular stencil at y = (ya, yb)/g (sector 0's frame, refined lattice),
  // of phi or (derivative stencils) of a function with phi's support.
  // max_turns: how far round the chart a point may lie (2 for the recursion's
  // regular children; the whole lattice for the regular patch itself).
  auto regular_stencil_of = [&](const std::map<LatticeIndex, T>& phi, long ya, long yb, int max_turns) {
    for (long pa = ceil_div(ya - hi_a, g); pa <= floor_div(ya - lo_a, g); ++pa)
      for (long pb = ceil_div(yb - hi_b, g); pb <= floor_div(yb - lo_b, g); ++pb) {
        const auto it = phi.find({ya - g * pa, yb - g * pb});
        if (it == phi.end()) continue;
        // A regular child reaches at most two sectors round (at y = e_1, its
        // neighbour e_2); the comparisons with OpenSubdiv and with plain
        // subdivision check that the points found are the right ones.
        const auto id = chart.index(0, pa, pb, max_turns);
        if (!id)
          throw Error("internal: " + context + ": the regular child at (" + std::to_string(ya) + "," +
                      std::to_string(yb) + ")/" + std::to_string(g) + " needs the point (" + std::to_string(pa) + "," +
                      std::to_string(pb) + ") outside the chart");
        accumulate(*id, it->second);
      }
    return collect();
  };
  auto regular_stencil = [&](long ya, long yb) { return regular_stencil_of(phi, ya, yb, 2); };

  // W at the wedge point Y / g of sector 0 (0 <= Y.b <= Y.a): W(Y) = F(m Y) A,
  // F = W again while m Y stays within the irregular radius, the regular
  // stencil beyond it. Points of the patch (Y.a <= g, patch point (Y.a - Y.b, Y.b))
  // are kept in the patch's own grid; the few beyond it that the recursion
  // passes through (sqrt(3)) in a map. A computed stencil is never empty.
  const long radius = irregular_radius(scheme) * g;
  out.stencils.assign(static_cast<std::size_t>((g + 1) * (g + 1)), {});
  std::map<LatticeIndex, SparseRow<T>>& beyond = out.beyond;
  auto stored = [&](long ya, long yb) -> SparseRow<T>& {
    return ya <= g ? out.stencils[static_cast<std::size_t>(yb * (g + 1) + ya - yb)] : beyond[{ya, yb}];
  };
  {
    // The two-ring (the first 1 + 3v points of the chart) is closed under the
    // step, so the eigenvector lives there: a small system instead of the chart's.
    const std::size_t two_ring = SectorChart(valence, 2).size();
    std::vector<SparseRow<T>> inner(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(two_ring));
    for (const auto& row : inner)
      for (const auto& [c, x] : row)
        if (c >= two_ring) throw Error("internal: " + context + ": the two-ring is not closed under the step");
    const std::vector<T> w0 = limit_stencil(inner, context);
    SparseRow<T>& origin = stored(0, 0);
    for (std::size_t c = 0; c < w0.size(); ++c)
      if (w0[c] != 0) origin.emplace_back(c, w0[c]);
  }
  auto solve = [&](auto&& self, long ya, long yb) -> const SparseRow<T>& {
    if (const SparseRow<T>& known = stored(ya, yb); !known.empty()) return known;
    const long za = m * ya, zb = m * yb;
    SparseRow<T> w = za < radius ? times_a(self(self, za, zb)) : times_a(regular_stencil(za, zb));
    return stored(ya, yb) = std::move(w);
  };
  for (long j = 0; j <= g; ++j)
    for (long i = 0; i + j <= g; ++i) solve(solve, i + j, j);
  const int regions = patch_regions(scheme, valence);
  for (const auto& [r, i, j] : band) {
    if (r < 1 || r >= regions || i < 0 || j < 0 || i + j > g)
      throw Error("internal: " + context + " has no band point (" + std::to_string(r) + ", " + std::to_string(i) + ", " +
                  std::to_string(j) + ")");
    const auto [ya, yb] = region_point(static_cast<int>(r), i, j, g);
    solve(solve, ya, yb);
  }

  if (gradient && valence == 6) {
    if (gradient->n != g) throw Error("internal: the regular gradient is on the grid " + std::to_string(gradient->n));
    // The partials have phi's support (phi is C1: both vanish on its border).
    std::map<LatticeIndex, T> along_u, along_v;
    auto convert = [](const Rational& x) {
      if constexpr (std::is_same_v<T, Rational>) return x;
      else return to_real(x);
    };
    for (const auto& [k, x] : gradient->da) {
      if (x != 0) along_u.emplace(k, convert(x));
      if (x + gradient->at(gradient->db, k.first, k.second) != 0)
        along_v.emplace(k, convert(x + gradient->at(gradient->db, k.first, k.second)));
    }
    for (const auto& [k, x] : gradient->db)
      if (x != 0 && !gradient->da.count(k)) along_v.emplace(k, convert(x));
    for (const auto& partial : {&along_u, &along_v})
      for (const auto& [k, x] : *partial)
        if (k.first < lo_a || k.first > hi_a || k.second < lo_b || k.second > hi_b)
          throw Error("internal: " + context + ": the regular gradient reaches beyond phi's support");
    out.du.resize(out.stencils.size());
    out.dv.resize(out.stencils.size());
    for (long j = 0; j <= g; ++j)
      for (long i = 0; i + j <= g; ++i) {
        const auto at = static_cast<std::size_t>(j * (g + 1) + i);
        out.du[at] = regular_stencil_of(along_u, i + j, j, 3);
        out.dv[at] = regular_stencil_of(along_v, i + j, j, 3);
      }
  }

  // Residuals (exact arithmetic must give zero).
  {
    const SparseRow<T>& w0 = out.at(0, 0);
    std::vector<T> diff(size);
    for (const auto& [c, x] : times_a(w0)) diff[c] += x;
    for (const auto& [c, x] : w0) diff[c] -= x;
    for (const T& d : diff) out.eigen_residual = std::max(out.eigen_residual, magnitude(d));
  }
  auto unity = [&](const SparseRow<T>& stencil) {
    T sum = 0;
    for (const auto& [c, w] : stencil) sum += w;
    out.unity_residual = std::max(out.unity_residual, magnitude(T(sum - 1)));
  };
  for (const SparseRow<T>& s : out.stencils)
    if (!s.empty()) unity(s);
  for (const auto& [y, s] : out.beyond) unity(s);
  if constexpr (std::is_same_v<T, Rational>)
    if (out.eigen_residual != 0 || out.unity_residual != 0)
      throw Error(context + ": exact check failed (partition of unity or the limit stencil)");
  return out;
}

template struct TrianglePatch<Rational>;
template struct TrianglePatch<Real>;
template TrianglePatch<Rational> solve_triangle_patch(const TriangleScheme&, int, long, const BivariateSolution&,
                                                      const std::vector<std::array<long, 3>>&, const BivariateGradient*);
template TrianglePatch<Real> solve_triangle_patch(const TriangleScheme&, int, long, const BivariateSolution&,
                                                  const std::vector<std::array<long, 3>>&, const BivariateGradient*);

}  // namespace sg
