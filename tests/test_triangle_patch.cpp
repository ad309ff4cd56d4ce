// Loop triangle patches around an extraordinary vertex (issue 4, in progress:
// the valences whose weights are rational) against OpenSubdiv's Loop limit
// surface (Bfr), and partition of unity.
#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <random>

#include "error.hpp"
#include "triangle_patch.hpp"

namespace {

using namespace OpenSubdiv;

// v triangular sectors of side K around the EV. Sector s holds (a, b),
// 0 <= b <= a <= K, with (a, 0) on the ray of e_s and (a, a) on the ray of
// e_{s+1}; (a, a) of sector s is (a, 0) of sector s+1.
struct FanMesh {
  int v, K;
  std::map<std::array<int, 3>, int> id;  // (sector, a, b) -> vertex
  int count = 0;
  std::vector<int> triangles;
  FanMesh(int valence, int rings) : v(valence), K(rings) {
    for (int s = 0; s < v; ++s)
      for (int a = 0; a <= K; ++a)
        for (int b = 0; b <= a; ++b) vertex(s, a, b);
    for (int s = 0; s < v; ++s)
      for (int a = 0; a < K; ++a)
        for (int b = 0; b <= a; ++b) {
          triangles.insert(triangles.end(), {vertex(s, a, b), vertex(s, a + 1, b), vertex(s, a + 1, b + 1)});
          if (b + 1 <= a) triangles.insert(triangles.end(), {vertex(s, a, b), vertex(s, a + 1, b + 1), vertex(s, a, b + 1)});
        }
  }
  int vertex(int s, int a, int b) {
    s = ((s % v) + v) % v;
    if (a == 0) return key({0, 0, 0});
    if (b == a) return vertex(s + 1, a, 0);
    return key({s, a, b});
  }
  int key(std::array<int, 3> k) {
    const auto it = id.find(k);
    if (it != id.end()) return it->second;
    id[k] = count;
    return count++;
  }
  // Chart point of the patch (sector 0, lattice of triangle_masks.hpp) -> vertex.
  int chart(int x, int y) {
    if (y >= 0 && y <= x) return vertex(0, x, y);              // sector 0: (a, b) = (x, y)
    if (x <= y && x >= 0) return vertex(1, y, y - x);          // sector 1: chart (a - b, a)
    return vertex(v - 1, x - y, x);                            // sector v-1: chart (b, b - a)
  }
  std::vector<int> patch_points() {
    std::vector<int> p{chart(0, 0)};
    for (int k = 0; k < v; ++k) p.push_back(vertex(k, 1, 0));
    for (auto [x, y] : {std::pair{1, -1}, {2, 0}, {2, 1}, {2, 2}, {1, 2}}) p.push_back(chart(x, y));
    return p;
  }
};

}  // namespace

TEST_CASE("Loop patches at valences 3, 4 and 6 agree with OpenSubdiv's Loop surface", "[triangle][opensubdiv]") {
  for (int v : {3, 4, 6}) {
    FanMesh mesh(v, 4);
    REQUIRE(mesh.chart(1, 1) == mesh.vertex(1, 1, 0));  // e_1
    REQUIRE(mesh.chart(0, 1) == mesh.vertex(2, 1, 0));  // e_2
    REQUIRE(mesh.chart(0, -1) == mesh.vertex(v - 1, 1, 0));
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
    const std::vector<int> points = mesh.patch_points();
    for (long n = 1; n <= 8; ++n) {
      const sg::TrianglePatchGrid grid = sg::solve_loop_patch(v, n);
      for (long j = 0; j <= n; ++j)
        for (long i = 0; i + j <= n; ++i) {
          const auto& w = grid.at(i, j);
          REQUIRE(w.size() == points.size());
          sg::Rational sum = 0;
          double ours[3] = {0, 0, 0};
          for (std::size_t h = 0; h < w.size(); ++h) {
            sum += w[h];
            for (int c = 0; c < 3; ++c) ours[c] += sg::to_double(w[h]) * pos[3 * static_cast<std::size_t>(points[h]) + c];
          }
          REQUIRE(sum == 1);
          const double uv[2] = {double(i) / n, double(j) / n};
          double ref[3];
          surface.Evaluate(uv, patch.data(), 3, ref);
          INFO("valence " << v << " n = " << n << " (" << i << "," << j << ")");
          for (int c = 0; c < 3; ++c) REQUIRE(std::fabs(ours[c] - ref[c]) < 1e-12);
        }
    }
  }
}

TEST_CASE("Loop valences with irrational weights are refused by name until the high-precision path exists", "[triangle]") {
  REQUIRE_THROWS_WITH(sg::solve_loop_patch(5, 3), Catch::Contains("valence 5 are irrational"));
  REQUIRE(sg::loop_beta(6) == sg::Rational(1, 16));
  REQUIRE(sg::loop_beta(4) == sg::Rational(31, 256));
  REQUIRE(sg::loop_beta(3) == sg::Rational(3, 16));
}
