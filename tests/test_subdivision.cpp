// At n = a^j the values must equal plain subdivision of a delta sequence, j steps
// (interpolatory schemes), or j steps followed by the limit stencil (approximating).
#include <catch2/catch.hpp>

#include "curve/curve_scheme_loader.hpp"
#include "curve/residue_solver.hpp"
#include "curve_masks.hpp"
#include "independent.hpp"

using independent::Q;

namespace {
void check_against_subdivision(const std::string& name, bool interpolatory, int max_steps) {
  const independent::UniformMask m = independent::mask_of(name);
  const sg::CurveScheme s = sg::load_curve_scheme(name);
  REQUIRE(s.arity == m.arity);
  // Limit stencil (left eigenvector of the local subdivision matrix), for approximating schemes.
  const long reach = static_cast<long>(m.coeffs.size());
  const auto limit = interpolatory ? std::map<long, Q>{{0, Q(1)}} : independent::limit_stencil(m.arity, m.first, m.coeffs, -reach, reach);
  independent::Sequence p{{0, Q(1)}};
  long n = 1;
  for (int j = 1; j <= max_steps; ++j) {
    p = independent::subdivide(p, m.arity, m.first, m.coeffs);
    n *= m.arity;
    const sg::CurveSolution sol = sg::solve_by_residues(s, n);
    for (long i = p.begin()->first - reach; i <= p.rbegin()->first + reach; ++i) {
      Q value = 0;
      for (const auto& [offset, weight] : limit) {
        const auto it = p.find(i + offset);
        if (it != p.end()) value += weight * it->second;
      }
      INFO(name << " n = " << n << " x = " << Q(i, n).str());
      REQUIRE(sol.types[0].at(i) == value);
    }
  }
}
}  // namespace

TEST_CASE("interpolatory schemes at n = a^j equal plain subdivision of a delta") {
  check_against_subdivision("fourpoint", true, 6);
  check_against_subdivision("dd6", true, 6);
  check_against_subdivision("ternary-dd4", true, 4);
}

TEST_CASE("approximating schemes at n = a^j equal subdivision followed by the limit stencil") {
  check_against_subdivision("nonpoly-curve", false, 6);
  check_against_subdivision("bspline3", false, 6);
  check_against_subdivision("chaikin", false, 6);
  check_against_subdivision("ternary-bspline3", false, 4);
}
