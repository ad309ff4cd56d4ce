#include "quad/ev_patch_solver.hpp"

#include "algebra/exact_linear_system.hpp"
#include "base/error.hpp"
#include "curve/residue_solver.hpp"
#include "quad/patch_subdivision.hpp"

namespace sg {

std::vector<Rational> limit_stencil(const PatchSubdivision& sub, const std::string& what) {
  LinearSolution sol = left_fixed_vector(sub.extraordinary_child);
  if (sol.status != LinearSolution::Status::Unique)
    throw Error(what + ": the limit stencil of the extraordinary vertex (left eigenvector for eigenvalue 1) has " +
                sol.describe());
  return sol.values;
}

PatchGrid solve_patch_recursion(const PatchSubdivision& sub, const std::vector<Rational>& limit, long g,
                                const CurveSolution& curve) {
  if (g < 1) throw Error("rate must be at least 1, got " + std::to_string(g));
  if (curve.n != g || curve.types.size() != 1) throw Error("internal: curve solution does not match the grid");
  const std::size_t m = sub.points;
  if (limit.size() != m) throw Error("internal: the limit stencil does not match the patch");
  const ScaledMatrix a0 = scale_rows(sub.extraordinary_child, m);
  std::array<ScaledMatrix, 3> regular;
  for (int c = 0; c < 3; ++c) regular[c] = scale_rows(sub.regular_children[c], m);
  const ScaledVector phi = scaled_from_rationals(curve.types[0].values);  // phi(k/g) = phi.num[k - first] / phi.den
  const GridRange range = curve.types[0].range;
  auto phi_num = [&](long k) -> const Integer& {
    static const Integer zero = 0;
    return range.contains(k) ? phi.num[static_cast<std::size_t>(k - range.first)] : zero;
  };

  PatchGrid out;
  out.grid = g;
  out.points = m;
  const std::size_t side = static_cast<std::size_t>(g + 1);
  out.scaled.resize(side * side);
  auto index = [&](long i, long j) { return static_cast<std::size_t>(j) * side + static_cast<std::size_t>(i); };
  const std::vector<std::size_t>& reflect = sub.reflection;
  const bool symmetric = !reflect.empty();

  auto solve_point = [&](long i, long j) {
    ScaledVector w;
    if (2 * i <= g && 2 * j <= g) {
      w = left_multiply(out.scaled[index(2 * i, 2 * j)], a0);
    } else {
      const int c = 2 * i > g ? (2 * j > g ? 2 : 0) : 1;  // child (1,1), (1,0) or (0,1)
      const long X = 2 * i - PatchSubdivision::kOffsets[c][0] * g, Y = 2 * j - PatchSubdivision::kOffsets[c][1] * g;
      ScaledVector r;
      r.num.resize(16);
      r.den = phi.den * phi.den;
      for (int b = -1; b <= 2; ++b)
        for (int a = -1; a <= 2; ++a) r.num[regular_index(a, b)] = phi_num(X - a * g) * phi_num(Y - b * g);
      w = left_multiply(r, regular[c]);
    }
    w.reduce();
    return w;
  };
  // Decreasing max(i,j): W(2i,2j) is known before W(i,j). With a reflection
  // only i <= j is computed; it gives the rest.
  for (long s = g; s >= 1; --s) {
    for (long i = 0; i <= s; ++i) {
      const long j = s;
      ScaledVector w = solve_point(i, j);
      if (symmetric && i != j) {
        ScaledVector mirrored;
        mirrored.den = w.den;
        mirrored.num.resize(m);
        for (std::size_t h = 0; h < m; ++h) mirrored.num[reflect[h]] = w.num[h];
        out.scaled[index(j, i)] = std::move(mirrored);
      } else if (!symmetric && i != j) {
        out.scaled[index(j, i)] = solve_point(j, i);
      }
      out.scaled[index(i, j)] = std::move(w);
    }
  }
  ScaledVector at_zero = scaled_from_rationals(limit);
  at_zero.reduce();
  out.scaled[index(0, 0)] = at_zero;

  out.stencils.reserve(out.scaled.size());
  for (const auto& w : out.scaled) out.stencils.push_back(w.rationals());
  return out;
}

PatchGrid solve_ev_patch(const QuadScheme& scheme, int valence, long g, const CurveSolution& curve) {
  const PatchSubdivision sub = build_patch_subdivision(scheme, valence);
  PatchGrid out = solve_patch_recursion(sub, limit_stencil(sub, scheme.name + ", valence " + std::to_string(valence)), g, curve);
  out.valence = valence;
  return out;
}

PatchGrid solve_ev_patch(const QuadScheme& scheme, int valence, long g) {
  return solve_ev_patch(scheme, valence, g, solve_by_residues(scheme.curve, g));
}

PatchGrid solve_sector_patch(const QuadScheme& scheme, const BoundarySector& sector, long g, const CurveSolution& curve) {
  const PatchSubdivision sub = build_sector_subdivision(scheme, sector);
  PatchGrid out = solve_patch_recursion(sub, limit_stencil(sub, scheme.name + ", " + sector.name()), g, curve);
  out.valence = 0;
  return out;
}

PatchGrid solve_sector_patch(const QuadScheme& scheme, const BoundarySector& sector, long g) {
  return solve_sector_patch(scheme, sector, g, solve_by_residues(scheme.curve, g));
}

}  // namespace sg
