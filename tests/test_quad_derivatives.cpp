// Exact d/du and d/dv stencils of quad patches (quad/ev_patch_derivatives)
// against independent computations: OpenSubdiv Bfr's derivatives of the
// Catmull-Clark limit surface (approximation level 10: every grid point other
// than the vertex lies in an exact B-spline sub-patch, see
// test_quad_opensubdiv.cpp), and, for nonpoly, central difference quotients
// of the exact value stencils at finer rates.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "bfr_reference.hpp"
#include "quad/ev_patch_derivatives.hpp"
#include "quad/ev_patch_solver.hpp"
#include "quad/quad_scheme_loader.hpp"
#include "sector_mesh.hpp"

namespace {

constexpr int kBlocks = 3;  // the patch's support reaches chart distance 2 < K

std::array<long double, 3> apply(const std::vector<sg::Rational>& w, const std::vector<std::array<double, 3>>& points,
                                 const std::vector<int>& patch_vertices) {
  std::array<long double, 3> out{0, 0, 0};
  for (std::size_t h = 0; h < w.size(); ++h) {
    const long double wh = sg::to_double(w[h]);
    const auto& p = points[static_cast<std::size_t>(patch_vertices[h])];
    for (int c = 0; c < 3; ++c) out[static_cast<std::size_t>(c)] += wh * p[static_cast<std::size_t>(c)];
  }
  return out;
}

double extent_of(const std::vector<std::array<double, 3>>& points) {
  std::array<double, 3> lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (const auto& p : points)
    for (std::size_t c = 0; c < 3; ++c) lo[c] = std::min(lo[c], p[c]), hi[c] = std::max(hi[c], p[c]);
  double e = 0;
  for (std::size_t c = 0; c < 3; ++c) e += (hi[c] - lo[c]) * (hi[c] - lo[c]);
  return std::sqrt(e);
}

}  // namespace

TEST_CASE("Catmull-Clark d/du and d/dv stencils agree with OpenSubdiv Bfr's derivatives", "[surface][opensubdiv]") {
  const sg::QuadScheme scheme = sg::load_quad_scheme("catmull-clark");
  double worst = 0;
  for (int v = 3; v <= 8; ++v) {
    INFO("valence " << v);
    const sector_mesh::SectorMesh mesh(v, kBlocks);
    const auto points = mesh.random_points(20261124u + static_cast<unsigned>(v));
    std::vector<int> sizes(mesh.faces().size(), 4), indices;
    for (const auto& f : mesh.faces()) indices.insert(indices.end(), f.begin(), f.end());
    bfr_reference::BfrLimit bfr(points, sizes, indices);
    const double extent = extent_of(points);
    for (long n = 1; n <= 8; ++n) {
      const sg::PatchDerivativeGrid d = sg::solve_ev_patch_derivatives(scheme, v, n);
      REQUIRE(d.u_at(0, 0).empty());
      for (long j = 0; j <= n; ++j)
        for (long i = 0; i <= n; ++i) {
          if (i == 0 && j == 0) continue;
          INFO("n = " << n << " (i, j) = (" << i << ", " << j << ")");
          REQUIRE(d.u_at(i, j).size() == static_cast<std::size_t>(2 * v + 8));
          const auto ref = bfr.derivatives(mesh.patch_face(), double(i) / double(n), double(j) / double(n));
          const auto du = apply(d.u_at(i, j), points, mesh.patch_vertices());
          const auto dv = apply(d.v_at(i, j), points, mesh.patch_vertices());
          for (std::size_t c = 0; c < 3; ++c) {
            const double eu = std::fabs(double(du[c]) - ref[1][c]), ev = std::fabs(double(dv[c]) - ref[2][c]);
            worst = std::max({worst, eu, ev});
            REQUIRE(eu <= 1e-10 * extent);
            REQUIRE(ev <= 1e-10 * extent);
          }
        }
    }
  }
  WARN("largest |ours - Bfr| over derivatives: " << worst);
}

TEST_CASE("nonpoly d/du and d/dv stencils are the limits of difference quotients of exact values", "[surface]") {
  const sg::QuadScheme scheme = sg::load_quad_scheme("nonpoly");
  const long g = 4;
  for (int v : {3, 5, 6}) {
    INFO("valence " << v);
    const sg::PatchDerivativeGrid d = sg::solve_ev_patch_derivatives(scheme, v, g);
    std::vector<double> errors;
    for (long k : {2L, 4L, 8L}) {  // step h = 1/(g k); points (i/g, j/g) strictly inside the patch
      const sg::PatchGrid fine = sg::solve_ev_patch(scheme, v, g * k);
      double worst = 0;
      for (long j = 1; j < g; ++j)
        for (long i = 1; i < g; ++i) {
          const long I = i * k, J = j * k;
          for (std::size_t h = 0; h < d.points; ++h) {
            const sg::Rational qu = (fine.at(I + 1, J)[h] - fine.at(I - 1, J)[h]) * sg::Rational(g * k, 2);
            const sg::Rational qv = (fine.at(I, J + 1)[h] - fine.at(I, J - 1)[h]) * sg::Rational(g * k, 2);
            worst = std::max({worst, std::fabs(sg::to_double(sg::Rational(qu - d.u_at(i, j)[h]))),
                              std::fabs(sg::to_double(sg::Rational(qv - d.v_at(i, j)[h])))});
          }
        }
      errors.push_back(worst);
    }
    INFO("largest weight error of the quotients at h = 1/8, 1/16, 1/32: " << errors[0] << " " << errors[1] << " " << errors[2]);
    REQUIRE(errors[1] <= 0.6 * errors[0]);
    REQUIRE(errors[2] <= 0.6 * errors[1]);
    REQUIRE(errors[2] < 0.02);
  }
}

TEST_CASE("derivative stencils sum to zero exactly", "[surface]") {
  // Moving every control point by the same vector moves the surface rigidly:
  // sum_h W_u = sum_h W_v = 0 at every grid point but the vertex.
  for (const std::string name : {"nonpoly", "catmull-clark"}) {
    const sg::QuadScheme scheme = sg::load_quad_scheme(name);
    for (int v = 3; v <= 7; ++v) {
      const sg::PatchDerivativeGrid d = sg::solve_ev_patch_derivatives(scheme, v, 6);
      for (std::size_t k = 1; k < d.du.size(); ++k) {
        sg::Rational su = 0, sv = 0;
        for (std::size_t h = 0; h < d.points; ++h) su += d.du[k][h], sv += d.dv[k][h];
        INFO(name << " valence " << v << " entry " << k);
        REQUIRE(su == 0);
        REQUIRE(sv == 0);
      }
    }
  }
}
