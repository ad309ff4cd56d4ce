#include "quad/ev_tangents.hpp"

#include "algebra/slit_fold.hpp"
#include "curve/residue_solver.hpp"
#include "quad/ev_patch_solver.hpp"

namespace sg {

std::optional<EvTangents> ev_tangents(const QuadScheme& scheme, int valence, const PatchSubdivision& subdivision,
                                      std::string& why) {
  const std::size_t m = subdivision.extraordinary_child.size();
  std::vector<std::vector<Real>> a0(m, std::vector<Real>(m, Real(0)));
  for (std::size_t r = 0; r < m; ++r)
    for (const auto& [c, w] : subdivision.extraordinary_child[r]) a0[r][c] += to_real(w);
  // The value stencils at the far ends of the patch's u and v edges: (1, 0) and (0, 1).
  const PatchGrid values = solve_ev_patch(scheme, valence, 1);
  auto end = [&](long i, long j) {
    std::vector<Real> w;
    for (const Rational& x : values.at(i, j)) w.push_back(to_real(x));
    return w;
  };
  return tangent_stencils(a0, end(1, 0), end(0, 1), why);
}

std::optional<EvTangents> sector_tangents(const QuadScheme& scheme, const BoundarySector& sector,
                                          const PatchSubdivision& subdivision, const std::vector<Rational>& limit,
                                          std::string& why) {
  if (sector.kind == SectorKind::Corner || sector.kind == SectorKind::Cone) {
    why = sector.kind == SectorKind::Corner ? "a corner has no tangent plane" : "a cone point has no tangent plane";
    return std::nullopt;
  }
  constexpr long kSamples = 8;  // the characteristic map's regularity is checked on this grid
  const PatchGrid values = solve_patch_recursion(subdivision, limit, kSamples, solve_by_residues(scheme.curve, kSamples));
  const SectorLayout layout(sector);
  const std::size_t m = subdivision.points;
  // A dart's e_k is e_0 again (the two sides of its slit): its tangent plane
  // is that of the patch with e_k folded into e_0 (algebra/slit_fold.hpp),
  // with no boundary curve to contain.
  const bool dart = sector.kind == SectorKind::Dart;
  std::vector<std::size_t> twin(m);
  for (std::size_t h = 0; h < m; ++h) twin[h] = dart && h == layout.edge(sector.faces) ? layout.edge(0) : h;
  const SlitFold fold(twin);
  std::vector<std::vector<double>> grid;
  for (const auto& w : values.stencils) {
    grid.emplace_back();
    for (const Real& x : fold.weights(w)) grid.back().push_back(to_double(x));
  }
  // A boundary's curve tangent at the vertex: e_k - e_0 (its left eigenvector for 1/2).
  std::vector<Real> boundary;
  if (!dart) {
    boundary.assign(m, Real(0));
    boundary[layout.edge(sector.faces)] = 1;
    boundary[layout.edge(0)] = -1;
  }
  auto t = boundary_tangent_stencils(fold.matrix(subdivision.extraordinary_child), fold.weights(values.at(kSamples, 0)),
                                     fold.weights(values.at(kSamples, kSamples)), boundary, grid, kSamples, why);
  if (t)
    for (std::vector<Real>* s : {&t->u, &t->v}) *s = fold.spread(*s);
  return t;
}

}  // namespace sg
