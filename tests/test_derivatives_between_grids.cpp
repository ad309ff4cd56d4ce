// nonpoly's regular patches are not polynomial, so its derivatives come from
// the stored phi and phi' of the regular curve. At a parameter no stored grid
// holds, the runtime follows the parameter's orbit under halving
// (runtime/src/quad/curve_orbit.hpp): to a stored grid (every double), or
// round a cycle (a rational with a new odd denominator, after halvings that
// remove the powers of two from it), solved there as an
// eigenvector. The oracle is the generator's own exact solve at a rate that
// does hold the parameter: tables of rates 1..24 must give what tables of
// rate 25 or 27 (or 64, for dyadic doubles) hold exactly, on every face of
// meshes with extraordinary vertices of valences 3 to 8.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "cli.hpp"
#include "quad/patch_descent.hpp"
#include "runtime_api.hpp"
#include "runtime_checks.hpp"

using namespace stencil_runtime;
using namespace test_runtime;
namespace fs = std::filesystem;

namespace {

const fs::path kMeshes = fs::path(STENCIL_SOURCE_DIR) / "meshes";

double difference(const Derivatives& a, const Derivatives& b) {
  double d = 0;
  for (std::size_t k = 0; k < 3; ++k)
    d = std::max({d, std::fabs(a.point[k] - b.point[k]), std::fabs(a.du[k] - b.du[k]), std::fabs(a.dv[k] - b.dv[k])});
  return d;
}

bool corner(long i, long j, long n) { return (i == 0 || i == n) && (j == 0 || j == n); }

// The regular patch's derivatives at (kx/(2n), ky/(2n)) from a table's stored phi and phi' (rate n), by the tensor product.
Derivatives tensor_from_table(const QuadTables& t, int n, long kx, long ky, const std::vector<Point>& q) {
  double wx[4], dx[4], wy[4], dy[4];
  t.regular_weights(n, kx, wx);
  t.regular_derivative_weights(n, kx, dx);
  t.regular_weights(n, ky, wy);
  t.regular_derivative_weights(n, ky, dy);
  Derivatives e;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i)
      for (std::size_t c = 0; c < 3; ++c) {
        const double p = q[static_cast<std::size_t>(j * 4 + i)][c];
        e.point[c] += wx[i] * wy[j] * p, e.du[c] += dx[i] * wy[j] * p, e.dv[c] += wx[i] * dy[j] * p;
      }
  return e;
}

}  // namespace

TEST_CASE("nonpoly derivatives at rationals no stored rate holds equal the exact tables of a rate that holds them",
          "[runtime][derivatives]") {
  const auto few = Tables::load(generated_table("nonpoly", "--valence 3-8 --n 24", "sgs").string());
  const auto exact = Tables::load(generated_table("nonpoly", "--valence 3-8 --n 25,27", "sgs").string());
  for (const char* name : {"cube", "chess-piece"}) {
    INFO(name);
    const Mesh mesh = read_obj((kMeshes / (std::string(name) + ".obj")).string());
    const Surface ours = surface_of(few, mesh), reference = surface_of(exact, mesh);
    const double tolerance = 1e-12 * extent(mesh);
    double worst = 0;
    std::size_t checked = 0;
    for (std::size_t f = 0; f < mesh.face_count(); f += (mesh.face_count() > 100 ? 7 : 1))
      for (long n : {25L, 27L, 50L})  // 50: an odd k/50 halves once before the cycle of 25
        for (long j = 0; j <= n; j += 3)
          for (long i = 0; i <= n; i += (n == 50 ? 1 : 2)) {
            if (corner(i, j, n)) continue;  // an extraordinary vertex has no parametric derivative
            worst = std::max(worst, difference(ours.derivatives(f, grid(i, j, n)), reference.derivatives(f, grid(i, j, n))));
            ++checked;
          }
    INFO(checked << " parameters, largest difference " << worst);
    CHECK(checked > 1000);
    CHECK(worst <= tolerance);
  }
}

TEST_CASE("nonpoly derivatives at doubles equal the exact tables of a rate that holds them", "[runtime][derivatives]") {
  // Through Surface, a double k/128 is taken as the fraction it is; rate 64 holds it at once.
  const auto few = Tables::load(generated_table("nonpoly", "--valence 3-8 --n 24", "sgs").string());
  const auto exact = Tables::load(generated_table("nonpoly", "--valence 3,5 --n 64", "sgs").string());
  const Mesh mesh = read_obj((kMeshes / "cube.obj").string());
  const Surface ours = surface_of(few, mesh), reference = surface_of(exact, mesh);
  double worst = 0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f)
    for (long j = 0; j <= 128; j += 9)
      for (long i = 0; i <= 128; i += 5) {
        if (corner(i, j, 128)) continue;
        const double u = static_cast<double>(i) / 128, v = static_cast<double>(j) / 128;
        worst = std::max(worst, difference(ours.derivatives(f, u, v), reference.derivatives(f, grid(i, j, 128))));
      }
  CHECK(worst <= 1e-12 * extent(mesh));
  // A double with all its digits: the orbit is 52 halvings long, and the
  // derivatives agree with a rational cycle's on either side of it to first order.
  const Derivatives d = ours.derivatives(2, 0.3, 0.7);
  const Derivatives rational = ours.derivatives(2, ExactParameter{Fraction::make(3, 10), Fraction::make(7, 10)});
  CHECK(difference(d, rational) <= 1e-12 * extent(mesh));
}

TEST_CASE("the regular curve's basis and derivative after halvings and round a cycle equal the exact values there",
          "[runtime][derivatives]") {
  // k/100 halves twice to a denominator of 25 (a cycle of 20 halvings), k/98 once to 49 (21): tables of rates
  // 1..24 hold neither; rates 50 and 49 hold both exactly.
  const QuadTables few = QuadTables::load_binary(generated_table("nonpoly", "--valence 3-8 --n 24", "sgs").string());
  const QuadTables exact = QuadTables::load_binary(generated_table("nonpoly", "--valence 3 --n 49,50", "sgs").string());
  const QuadPatchDescent descent(few);
  std::vector<Point> q(16);
  for (std::size_t h = 0; h < 16; ++h)  // any regular patch: the derivatives are linear in its points
    q[h] = {std::sin(1.0 + static_cast<double>(h)), std::cos(2.0 * static_cast<double>(h)), 0.1 * static_cast<double>(h * h)};
  double worst = 0;
  for (int n : {50, 49})
    for (long k = 0; k <= 2 * n; ++k) {
      std::vector<Point> points = q;
      const Derivatives d = descent.derivatives(4, points, Fraction::make(k, 2 * n), Fraction::make(1, 2));
      worst = std::max(worst, difference(d, tensor_from_table(exact, n, k, n, q)));  // y = 1/2
    }
  INFO("largest difference " << worst);
  CHECK(worst <= 1e-13);
  // Doubles take their own path (no fractions): k/128 reaches a stored grid after up to seven halvings, and
  // k/128 + 2^-60 after up to 60; rate 64 holds k/128, and 2^-60 moves a C1 basis by far less than the tolerance.
  const QuadTables exact64 = QuadTables::load_binary(generated_table("nonpoly", "--valence 3,5 --n 64", "sgs").string());
  double worst_double = 0;
  for (long k = 0; k < 128; ++k)
    for (double nudge : {0.0, std::ldexp(1.0, -60)}) {
      std::vector<Point> points = q;
      const Derivatives d = descent.derivatives(4, points, static_cast<double>(k) / 128 + nudge, 0.5);
      worst_double = std::max(worst_double, difference(d, tensor_from_table(exact64, 64, k, 64, q)));
    }
  INFO("largest difference at doubles " << worst_double);
  CHECK(worst_double <= 1e-13);
}
