#include "quad/ev_patch_derivatives.hpp"

#include "algebra/scaled_vector.hpp"
#include "base/error.hpp"
#include "curve/curve_table.hpp"
#include "curve/difference_scheme.hpp"
#include "curve/residue_solver.hpp"
#include "quad/patch_layout.hpp"
#include "quad/patch_subdivision.hpp"

namespace sg {

PatchDerivativeGrid solve_ev_patch_derivatives(const QuadScheme& scheme, int valence, long g, const CurveSolution& curve,
                                               const std::map<long, Rational>& curve_derivative) {
  if (g < 1) throw Error("rate must be at least 1, got " + std::to_string(g));
  if (curve.n != g || curve.types.size() != 1) throw Error("internal: curve solution does not match the grid");
  const PatchSubdivision sub = build_patch_subdivision(scheme, valence);
  const std::size_t m = sub.points;
  const ScaledMatrix a0 = scale_rows(sub.extraordinary_child, m);
  std::array<ScaledMatrix, 3> regular;
  for (int c = 0; c < 3; ++c) regular[c] = scale_rows(sub.regular_children[c], m);
  const TypeValues& phi = curve.types[0];
  auto dphi = [&](long k) {
    const auto it = curve_derivative.find(k);
    return it == curve_derivative.end() ? Rational(0) : it->second;
  };

  PatchDerivativeGrid out;
  out.valence = valence;
  out.grid = g;
  out.points = m;
  const std::size_t side = static_cast<std::size_t>(g + 1);
  std::vector<ScaledVector> du(side * side), dv(side * side);
  auto index = [&](long i, long j) { return static_cast<std::size_t>(j) * side + static_cast<std::size_t>(i); };
  const std::vector<std::size_t>& reflect = sub.reflection;
  auto mirrored = [&](const ScaledVector& w) {
    ScaledVector r;
    r.den = w.den;
    r.num.resize(m);
    for (std::size_t h = 0; h < m; ++h) r.num[reflect[h]] = w.num[h];
    return r;
  };
  auto doubled = [](ScaledVector w) {
    for (auto& x : w.num) x *= 2;
    w.reduce();
    return w;
  };

  // The order of ev_patch_solver: decreasing max(i, j), so (2i, 2j) is known
  // before (i, j); i <= j is computed and the reflection (which swaps u and v)
  // gives (j, i).
  for (long s = g; s >= 1; --s) {
    for (long i = 0; i <= s; ++i) {
      const long j = s;
      ScaledVector wu, wv;
      if (2 * i <= g && 2 * j <= g) {
        wu = doubled(left_multiply(du[index(2 * i, 2 * j)], a0));
        wv = doubled(left_multiply(dv[index(2 * i, 2 * j)], a0));
      } else {
        const int c = (2 * i > g) ? 2 : 1;
        const long X = 2 * i - PatchSubdivision::kOffsets[c][0] * g, Y = 2 * j - PatchSubdivision::kOffsets[c][1] * g;
        std::vector<Rational> ru(16), rv(16);
        for (int b = -1; b <= 2; ++b)
          for (int a = -1; a <= 2; ++a) {
            // d/dx of the child's stencil at X/g: 2 (chain rule) times phi' on the child's grid (g per unit).
            ru[regular_index(a, b)] = 2 * dphi(X - a * g) * phi.at(Y - b * g);
            rv[regular_index(a, b)] = 2 * phi.at(X - a * g) * dphi(Y - b * g);
          }
        wu = left_multiply(scaled_from_rationals(ru), regular[c]);
        wv = left_multiply(scaled_from_rationals(rv), regular[c]);
      }
      wu.reduce();
      wv.reduce();
      if (i != j) {
        du[index(j, i)] = mirrored(wv);
        dv[index(j, i)] = mirrored(wu);
      }
      du[index(i, j)] = std::move(wu);
      dv[index(i, j)] = std::move(wv);
    }
  }
  out.du.resize(side * side);
  out.dv.resize(side * side);
  for (std::size_t k = 1; k < side * side; ++k) {
    out.du[k] = du[k].rationals();
    out.dv[k] = dv[k].rationals();
  }
  return out;
}

PatchDerivativeGrid solve_ev_patch_derivatives(const QuadScheme& scheme, int valence, long g) {
  const DerivativeSchemes d = derivative_schemes(scheme.curve, 1);
  if (d.schemes.empty())
    throw Error(scheme.name + ": the regular curve '" + scheme.curve.name + "' has no continuous derivative (" + d.stop + ")");
  const CurveSolution curve = solve_by_residues(scheme.curve, g);
  const CurveTable table = table_with_derivatives(scheme.curve, curve, d);
  return solve_ev_patch_derivatives(scheme, valence, g, curve, table.functions[0].derivatives[0]);
}

}  // namespace sg
