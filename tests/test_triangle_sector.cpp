// Loop patches at boundary vertices (generator/triangle/triangle_sector.hpp)
// against OpenSubdiv's Loop limit surface (Bfr), which shares no code with the
// generator: a wedge of k faces round the vertex, cut from the triangular
// lattice, with random positions; every grid node's stencil, gathered by
// vertex, equals Bfr's.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <random>

#include "bfr_reference.hpp"
#include "base/error.hpp"
#include "triangle/triangle_patch.hpp"
#include "triangle/triangle_scheme_loader.hpp"
#include "triangle/triangle_sector.hpp"

namespace {

// The wedge's real points within `rings` of B, as a triangle mesh.
struct WedgeMesh {
  std::map<sg::WedgePoint, int> vertex;
  std::vector<int> sizes, indices;
  std::map<int, int> patch_face;  // position p -> face (B, e_p, e_{p+1})

  WedgeMesh(const sg::BoundaryWedge& wedge, long rings) {
    const int k = wedge.faces();
    auto id = [&](int s, long a, long b) {
      const auto q = wedge.canonical(s, a, b);
      REQUIRE(q);
      REQUIRE(!wedge.phantom(*q));
      return vertex.emplace(*q, static_cast<int>(vertex.size())).first->second;
    };
    auto face = [&](int s, long a0, long b0, long a1, long b1, long a2, long b2) {
      indices.push_back(id(s, a0, b0)), indices.push_back(id(s, a1, b1)), indices.push_back(id(s, a2, b2));
      sizes.push_back(3);
    };
    for (int s = 0; s < k; ++s)
      for (long a = 0; a < rings; ++a)
        for (long b = 0; b <= a; ++b) {
          if (a == 0) patch_face[s] = static_cast<int>(sizes.size());
          face(s, a, b, a + 1, b, a + 1, b + 1);                   // up
          if (b + 1 <= a) face(s, a, b, a + 1, b + 1, a, b + 1);  // down
        }
  }
};

double worst_difference(const sg::TriangleScheme& loop, const sg::BoundarySector& sector, long n, bool corner_tag) {
  const sg::BoundaryWedge wedge(sector.faces);
  WedgeMesh mesh(wedge, 5);
  std::mt19937 rng(77u + 31u * static_cast<unsigned>(sector.faces) + static_cast<unsigned>(sector.position));
  std::uniform_real_distribution<double> U(-1, 1);
  std::vector<std::array<double, 3>> positions(mesh.vertex.size());
  for (auto& p : positions) p = {U(rng), U(rng), U(rng)};
  bfr_reference::Creasing creasing;
  if (corner_tag) creasing.corners = {0}, creasing.corner_sharpness = {10.0f};  // B is vertex 0
  bfr_reference::BfrLimit bfr(positions, mesh.sizes, mesh.indices, OpenSubdiv::Sdc::SCHEME_LOOP, {}, creasing);
  const auto patch = sg::solve_triangle_sector(loop, sector, n, sg::solve_regular(loop, n));
  const int face = mesh.patch_face.at(sector.position);
  double worst = 0;
  for (long j = 0; j <= n; ++j)
    for (long i = 0; i + j <= n; ++i) {
      std::map<int, double> ours;
      const auto& w = patch.at(i, j);
      for (std::size_t h = 0; h < w.size(); ++h)
        if (w[h] != 0) ours[mesh.vertex.at(patch.layout[h])] += sg::to_double(w[h]);
      auto ref = bfr.stencil(face, double(i) / n, double(j) / n);
      for (const auto& [v, x] : ours) ref[v] -= x;
      for (const auto& [v, x] : ref) worst = std::max(worst, std::fabs(x));
    }
  return worst;
}

}  // namespace

TEST_CASE("Loop boundary sectors of 1..8 faces equal Bfr at rates 1..8", "[triangle][sector][opensubdiv]") {
  const sg::TriangleScheme loop = sg::load_triangle_scheme("loop");
  for (int k = 1; k <= 8; ++k)
    for (int p = 0; p < k; ++p)
      for (long n : {1L, 2L, 3L, 5L, 8L}) {
        INFO("k = " << k << ", p = " << p << ", n = " << n);
        CHECK(worst_difference(loop, {sg::SectorKind::Crease, k, p}, n, false) < 1e-13);
      }
}

TEST_CASE("Loop corner sectors of 1..8 faces equal Bfr with a sharp corner", "[triangle][sector][opensubdiv]") {
  const sg::TriangleScheme loop = sg::load_triangle_scheme("loop");
  for (int k = 1; k <= 8; ++k)
    for (int p = 0; p < k; ++p)
      for (long n : {1L, 4L, 7L}) {
        INFO("k = " << k << ", p = " << p << ", n = " << n);
        CHECK(worst_difference(loop, {sg::SectorKind::Corner, k, p}, n, true) < 1e-13);
      }
}
