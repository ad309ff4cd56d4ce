// Loop triangle patches around an extraordinary vertex, exact (valences 3, 4, 6)
// and in high precision (the others), against OpenSubdiv's Loop limit surface
// (Bfr), which shares no code with the generator.
#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <random>

#include "base/error.hpp"
#include "fan_mesh.hpp"
#include "triangle/triangle_patch.hpp"
#include "triangle/triangle_scheme_loader.hpp"

namespace {

using namespace OpenSubdiv;

// Every grid point of the patch at rate n against Bfr; returns the largest difference.
template <class T>
double compare_with_bfr(const sg::TriangleScheme& loop, int v, long n, FanMesh& mesh, Bfr::Surface<double>& surface,
                        const std::vector<double>& patch, const std::vector<double>& pos) {
  const auto grid = sg::solve_triangle_patch<T>(loop, v, n, sg::solve_regular(loop, n));
  double worst = 0;
  for (long j = 0; j <= n; ++j)
    for (long i = 0; i + j <= n; ++i) {
      const auto& w = grid.at(i, j);
      double ours[3] = {0, 0, 0};
      for (const auto& [h, x] : w) {
        const int vertex = mesh.at(grid.chart.point(h));
        for (int c = 0; c < 3; ++c) ours[c] += sg::to_double(x) * pos[3 * static_cast<std::size_t>(vertex) + c];
      }
      const double uv[2] = {double(i) / n, double(j) / n};
      double ref[3];
      surface.Evaluate(uv, patch.data(), 3, ref);
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::fabs(ours[c] - ref[c]));
    }
  return worst;
}

}  // namespace

TEST_CASE("Loop patches at valences 3..12 agree with OpenSubdiv's Loop surface", "[triangle][opensubdiv]") {
  const sg::TriangleScheme loop = sg::load_triangle_scheme("loop");
  for (int v = 3; v <= 12; ++v) {
    FanMesh mesh(v, 5);
    std::mt19937 rng(1234u + static_cast<unsigned>(v));
    std::uniform_real_distribution<double> U(-1, 1);
    std::vector<double> pos(3 * static_cast<std::size_t>(mesh.count));
    for (double& x : pos) x = U(rng);
    std::vector<int> sizes(mesh.triangles.size() / 3, 3);
    Far::TopologyDescriptor desc;
    desc.numVertices = mesh.count;
    desc.numFaces = static_cast<int>(sizes.size());
    desc.numVertsPerFace = sizes.data();
    desc.vertIndicesPerFace = mesh.triangles.data();
    Sdc::Options sdc;
    sdc.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
    using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
    std::unique_ptr<Far::TopologyRefiner> refiner(Factory::Create(desc, Factory::Options(Sdc::SCHEME_LOOP, sdc)));
    REQUIRE(refiner);
    Bfr::SurfaceFactory::Options options;
    options.SetApproxLevelSmooth(10).SetApproxLevelSharp(10);
    const Bfr::RefinerSurfaceFactory<> factory(*refiner, options);
    Bfr::Surface<double> surface;
    REQUIRE(factory.InitVertexSurface(0, &surface));  // face 0 = sector 0's (EV, e_0, e_1)
    std::vector<double> patch(static_cast<std::size_t>(surface.GetNumPatchPoints()) * 3);
    surface.PreparePatchPoints(pos.data(), 3, patch.data(), 3);
    const bool exact = loop.exact_neighbour_weight(v).has_value();
    CHECK(exact == (v == 3 || v == 4 || v == 6));
    for (long n = 1; n <= 8; ++n) {
      INFO("valence " << v << (exact ? " (exact)" : " (high precision)") << ", n = " << n);
      const double worst = exact ? compare_with_bfr<sg::Rational>(loop, v, n, mesh, surface, patch, pos)
                                 : compare_with_bfr<sg::Real>(loop, v, n, mesh, surface, patch, pos);
      REQUIRE(worst < 1e-12);
    }
  }
}

TEST_CASE("Irrational Loop valences are refused by the exact path and solved in high precision", "[triangle]") {
  const sg::TriangleScheme loop = sg::load_triangle_scheme("loop");
  REQUIRE_THROWS_WITH(sg::solve_triangle_patch<sg::Rational>(loop, 5, 3, sg::solve_regular(loop, 3)),
                      Catch::Contains("irrational"));
  REQUIRE(*loop.exact_neighbour_weight(6) == sg::Rational(1, 16));
  REQUIRE(*loop.exact_neighbour_weight(4) == sg::Rational(31, 256));
  REQUIRE(*loop.exact_neighbour_weight(3) == sg::Rational(3, 16));
  const auto patch = sg::solve_triangle_patch<sg::Real>(loop, 5, 6, sg::solve_regular(loop, 6));
  REQUIRE(patch.eigen_residual < sg::Real("1e-70"));
  REQUIRE(patch.unity_residual < sg::Real("1e-70"));
}
