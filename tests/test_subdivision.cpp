// At n = a^j the values must equal plain subdivision of a delta sequence, j steps
// (interpolatory schemes), or j steps followed by the limit stencil (approximating).
#include <catch2/catch.hpp>

#include "curve/curve_scheme_loader.hpp"
#include "curve/residue_solver.hpp"
#include "independent.hpp"

using independent::Q;

namespace {
struct UniformMask {
  long arity, first;
  std::vector<Q> coeffs;
};
// The mask as stated in the scheme's description, written out here independently.
UniformMask mask_of(const std::string& name) {
  if (name == "fourpoint") return {2, -3, {Q(-1, 16), 0, Q(9, 16), 1, Q(9, 16), 0, Q(-1, 16)}};
  if (name == "dd6") return {2, -5, {Q(3, 256), 0, Q(-25, 256), 0, Q(150, 256), 1, Q(150, 256), 0, Q(-25, 256), 0, Q(3, 256)}};
  if (name == "ternary-dd4") return {3, -5, {Q(-4, 81), Q(-5, 81), 0, Q(30, 81), Q(60, 81), 1, Q(60, 81), Q(30, 81), 0, Q(-5, 81), Q(-4, 81)}};
  if (name == "nonpoly-curve") return {2, -2, {Q(1, 6), Q(1, 2), Q(2, 3), Q(1, 2), Q(1, 6)}};
  if (name == "bspline3") return {2, -2, {Q(1, 8), Q(1, 2), Q(3, 4), Q(1, 2), Q(1, 8)}};
  if (name == "chaikin") return {2, -2, {Q(1, 4), Q(3, 4), Q(3, 4), Q(1, 4)}};
  if (name == "ternary-bspline3") return {3, -4, {Q(1, 27), Q(4, 27), Q(10, 27), Q(16, 27), Q(19, 27), Q(16, 27), Q(10, 27), Q(4, 27), Q(1, 27)}};
  throw std::runtime_error("no mask for " + name);
}

void check_against_subdivision(const std::string& name, bool interpolatory, int max_steps) {
  const UniformMask m = mask_of(name);
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
