#include "quad/direct_patch_solver.hpp"

#include "algebra/exact_linear_system.hpp"
#include "base/error.hpp"
#include "quad/patch_subdivision.hpp"

namespace sg {

PatchGrid solve_ev_patch_directly(const QuadScheme& scheme, int valence, long n) {
  if (n < 1) throw Error("rate must be at least 1, got " + std::to_string(n));
  const PatchSubdivision sub = build_patch_subdivision(scheme, valence);
  const std::size_t m = sub.points;
  const long side = n + 1, reg_side = 4 * n - 1;  // regular unknowns: grid indices -2n < k, l < 2n
  const std::size_t patch_unknowns = m * static_cast<std::size_t>(side * side);
  auto B = [&](std::size_t h, long i, long j) { return h * static_cast<std::size_t>(side * side) + static_cast<std::size_t>(j * side + i); };
  auto inside = [&](long k) { return k > -2 * n && k < 2 * n; };
  auto Phi = [&](long k, long l) {
    return patch_unknowns + static_cast<std::size_t>((l + 2 * n - 1) * reg_side + (k + 2 * n - 1));
  };
  ExactLinearSystem system(patch_unknowns + static_cast<std::size_t>(reg_side * reg_side));
  using Eq = std::vector<std::pair<std::size_t, Rational>>;

  // Patch basis functions: B_h(x) = sum_r S[r][h] B1_r(x), the level-1 basis at x.
  for (long j = 0; j <= n; ++j)
    for (long i = 0; i <= n; ++i) {
      std::vector<Eq> eqs(m);
      for (std::size_t h = 0; h < m; ++h) eqs[h].emplace_back(B(h, i, j), Rational(-1));
      if (2 * i <= n && 2 * j <= n) {
        for (std::size_t r = 0; r < m; ++r)
          for (const auto& [h, w] : sub.extraordinary_child[r]) eqs[h].emplace_back(B(r, 2 * i, 2 * j), w);
      } else {
        const int c = 2 * i > n ? (2 * j > n ? 2 : 0) : 1;
        const long X = 2 * i - PatchSubdivision::kOffsets[c][0] * n, Y = 2 * j - PatchSubdivision::kOffsets[c][1] * n;
        for (int b = -1; b <= 2; ++b)
          for (int a = -1; a <= 2; ++a) {
            const long k = X - a * n, l = Y - b * n;
            if (!inside(k) || !inside(l)) continue;
            for (const auto& [h, w] : sub.regular_children[c][regular_index(a, b)]) eqs[h].emplace_back(Phi(k, l), w);
          }
      }
      for (const Eq& eq : eqs) system.add_equation(eq, 0);
      Eq unity;
      for (std::size_t h = 0; h < m; ++h) unity.emplace_back(B(h, i, j), Rational(1));
      system.add_equation(unity, 1);
    }

  // Regular basis: Phi(x) = sum_{a,b} s_a s_b Phi(2x - (a,b)), and partition of unity per residue.
  const auto& terms = scheme.curve.types.at(0).terms;
  for (long l = -2 * n + 1; l < 2 * n; ++l)
    for (long k = -2 * n + 1; k < 2 * n; ++k) {
      Eq eq{{Phi(k, l), Rational(-1)}};
      for (const Term& ta : terms)
        for (const Term& tb : terms) {
          const long kk = 2 * k - ta.shift * n, ll = 2 * l - tb.shift * n;
          if (inside(kk) && inside(ll)) eq.emplace_back(Phi(kk, ll), ta.coeff * tb.coeff);
        }
      system.add_equation(eq, 0);
    }
  for (long r2 = 0; r2 < n; ++r2)
    for (long r1 = 0; r1 < n; ++r1) {
      Eq eq;
      for (long q = -2; q <= 2; ++q)
        for (long p = -2; p <= 2; ++p)
          if (inside(r1 + p * n) && inside(r2 + q * n)) eq.emplace_back(Phi(r1 + p * n, r2 + q * n), Rational(1));
      system.add_equation(eq, 1);
    }

  const LinearSolution sol = system.solve();
  if (sol.status != LinearSolution::Status::Unique)
    throw Error(scheme.name + ", valence " + std::to_string(valence) + ", n = " + std::to_string(n) +
                ": the full system of scaling relations has " + sol.describe());
  PatchGrid out;
  out.valence = valence;
  out.grid = n;
  out.points = m;
  for (long j = 0; j <= n; ++j)
    for (long i = 0; i <= n; ++i) {
      std::vector<Rational> w(m);
      for (std::size_t h = 0; h < m; ++h) w[h] = sol.values[B(h, i, j)];
      out.scaled.push_back(scaled_from_rationals(w));
      out.scaled.back().reduce();
      out.stencils.push_back(std::move(w));
    }
  return out;
}

}  // namespace sg
