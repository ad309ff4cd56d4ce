#include "quad/ev_tangents.hpp"

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

namespace {

std::vector<std::vector<Real>> real_matrix(const PatchSubdivision& subdivision) {
  const std::size_t m = subdivision.extraordinary_child.size();
  std::vector<std::vector<Real>> a0(m, std::vector<Real>(m, Real(0)));
  for (std::size_t r = 0; r < m; ++r)
    for (const auto& [c, w] : subdivision.extraordinary_child[r]) a0[r][c] += to_real(w);
  return a0;
}

}  // namespace

std::optional<EvTangents> sector_tangents(const QuadScheme& scheme, const BoundarySector& sector,
                                          const PatchSubdivision& subdivision, const std::vector<Rational>& limit,
                                          std::string& why) {
  if (sector.kind == SectorKind::Corner) {
    why = "a corner has no tangent plane";
    return std::nullopt;
  }
  if (sector.kind == SectorKind::Dart) {
    why = "tangent stencils at a dart are not made yet";
    return std::nullopt;
  }
  constexpr long kSamples = 8;  // the characteristic map's regularity is checked on this grid
  const PatchGrid values = solve_patch_recursion(subdivision, limit, kSamples, solve_by_residues(scheme.curve, kSamples));
  auto at = [&](long i, long j) {
    std::vector<Real> w;
    for (const Rational& x : values.at(i, j)) w.push_back(to_real(x));
    return w;
  };
  // The boundary curve's tangent at the vertex: e_k - e_0 (its left eigenvector for 1/2).
  const SectorLayout layout(sector);
  std::vector<Real> boundary(subdivision.points, Real(0));
  boundary[layout.edge(sector.faces)] = 1;
  boundary[layout.edge(0)] = -1;
  std::vector<std::vector<double>> grid;
  for (const auto& w : values.stencils) {
    grid.emplace_back();
    for (const Rational& x : w) grid.back().push_back(to_double(x));
  }
  return boundary_tangent_stencils(real_matrix(subdivision), at(kSamples, 0), at(kSamples, kSamples), boundary, grid, kSamples, why);
}

}  // namespace sg
