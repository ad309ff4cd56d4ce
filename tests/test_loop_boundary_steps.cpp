// Loop subdivision steps on triangle meshes with boundaries (issue 17's
// foundation for Loop boundaries): subdivide() against OpenSubdiv's Far
// uniform refinement with the same boundary option, vertex for vertex (matched
// as sets: Far numbers its refined vertices otherwise), on open meshes made for
// the test: triangulated grids (boundary vertices in 1, 2 and 3 faces), the
// icosahedron without one face or without a fan round a vertex, and fans of
// 1..8 faces round a boundary vertex.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "bfr_reference.hpp"
#include "bundled_meshes.hpp"
#include "open_meshes.hpp"
#include "cli.hpp"
#include "runtime_api.hpp"
#include "runtime_checks.hpp"
#include "stencil_runtime/subdivide.hpp"

using namespace stencil_runtime;
using namespace test_runtime;
using test_meshes::bundled;

namespace {

// test_meshes::open_grid (quads with uneven heights), each quad split into
// two triangles along alternating diagonals: its corners are in one or two
// faces, its other boundary vertices in two or three.
Mesh triangulated_grid(int columns, int rows) {
  const Mesh quads = test_meshes::open_grid(columns, rows);
  Mesh m;
  m.positions = quads.positions;
  for (std::size_t f = 0; f < quads.face_count(); ++f) {
    const int* q = &quads.face_vertices[4 * f];  // (i, j), (i+1, j), (i+1, j+1), (i, j+1)
    const bool flip = (f % static_cast<std::size_t>(columns) + f / static_cast<std::size_t>(columns)) % 2 == 1;
    m.face_sizes.insert(m.face_sizes.end(), {3, 3});
    if (flip) m.face_vertices.insert(m.face_vertices.end(), {q[0], q[1], q[3], q[1], q[2], q[3]});
    else m.face_vertices.insert(m.face_vertices.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
  }
  return m;
}

// k triangles round vertex 0, which is on the boundary (its first and last
// neighbours are boundary vertices in one face each when k = 1, else the fan's ends).
Mesh fan(int k) {
  Mesh m;
  m.positions.push_back({0, 0, 0.2});
  const double angle = (k == 1 ? 1.0 : 1.6) * M_PI / k;
  for (int j = 0; j <= k; ++j)
    m.positions.push_back({std::cos(angle * j), std::sin(angle * j), 0.1 * std::sin(2.0 * j + 1)});
  for (int j = 0; j < k; ++j) {
    m.face_sizes.push_back(3);
    m.face_vertices.insert(m.face_vertices.end(), {0, j + 1, j + 2});
  }
  return m;
}

// The icosahedron without the faces at vertex `v` (a hole round it), or
// without its first face when v < 0.
Mesh icosahedron_without(int v) {
  Mesh in = bundled("icosahedron"), m;
  m.positions = in.positions;
  for (std::size_t f = 0; f < in.face_count(); ++f) {
    const int* c = &in.face_vertices[3 * f];
    if (v < 0 ? f == 0 : (c[0] == v || c[1] == v || c[2] == v)) continue;
    m.face_sizes.push_back(3);
    m.face_vertices.insert(m.face_vertices.end(), c, c + 3);
  }
  if (v >= 0) {  // vertex v is in no face now: the last vertex takes its number
    const int last = static_cast<int>(m.positions.size()) - 1;
    m.positions[static_cast<std::size_t>(v)] = m.positions.back();
    m.positions.pop_back();
    for (int& x : m.face_vertices)
      if (x == last) x = v;
  }
  return m;
}

// Far's vertices after `level` uniform Loop steps with the boundary option.
std::vector<Point> far_loop_points(const Mesh& mesh, bool corners, int level) {
  bfr_reference::Creasing options;
  options.boundary_corners = corners;
  return bfr_reference::far_points(mesh.positions, mesh.face_sizes, mesh.face_vertices, bfr_reference::osd::Sdc::SCHEME_LOOP,
                                   options, level, false);
}

// Largest distance from one of `ours` to the nearest of `reference`, and back
// (both sorted by x; candidates within `window` in x), over `size`.
double set_distance(std::vector<Point> ours, std::vector<Point> reference, double size) {
  const double window = 1e-6 * size;
  auto one_way = [&](const std::vector<Point>& from, std::vector<Point> to) {
    std::sort(to.begin(), to.end());
    double worst = 0;
    for (const Point& p : from) {
      double nearest = 1e300;
      for (auto it = std::lower_bound(to.begin(), to.end(), Point{p[0] - window, -1e300, -1e300});
           it != to.end() && (*it)[0] <= p[0] + window; ++it)
        nearest = std::min(nearest, distance(p, *it));
      worst = std::max(worst, nearest);
    }
    return worst / size;
  };
  return std::max(one_way(ours, reference), one_way(reference, ours));
}

}  // namespace

TEST_CASE("Loop steps on open meshes equal OpenSubdiv's Far vertex for vertex, edge-only and edge-and-corner",
          "[runtime][boundaries][loop][opensubdiv]") {
  const auto tables = Tables::load(generated_table("loop", "--valence 3-8 --n 4", "sgt").string());
  std::vector<std::pair<std::string, Mesh>> meshes = {{"grid 5x4", triangulated_grid(5, 4)},
                                                      {"grid 1x1", triangulated_grid(1, 1)},
                                                      {"icosahedron without a face", icosahedron_without(-1)},
                                                      {"icosahedron without the faces at vertex 0", icosahedron_without(0)}};
  for (int k = 1; k <= 8; ++k) meshes.push_back({"fan of " + std::to_string(k), fan(k)});
  for (const auto& [name, mesh] : meshes)
    for (bool corners : {false, true}) {
      Mesh m = mesh;
      m.tags.boundary = corners ? BoundaryInterpolation::EdgeAndCorner : BoundaryInterpolation::EdgeOnly;
      Mesh once = subdivide(*tables, m);
      REQUIRE(once.face_count() == 4 * m.face_count());
      once.tags = m.tags;
      const Mesh twice = subdivide(*tables, once);
      INFO(name << (corners ? ", edge-and-corner" : ", edge-only"));
      CHECK(set_distance(once.positions, far_loop_points(m, corners, 1), extent(m)) < 1e-15);
      CHECK(set_distance(twice.positions, far_loop_points(m, corners, 2), extent(m)) < 1e-15);
    }
}

TEST_CASE("sqrt(3) steps refuse a mesh with a boundary, saying why", "[runtime][boundaries][sqrt3]") {
  const auto tables = Tables::load(generated_table("sqrt3", "--valence 3-8 --n 3", "sgt").string());
  CHECK_THROWS_WITH(subdivide(*tables, icosahedron_without(-1)),
                    Catch::Contains("sqrt(3), which splits no edges") && Catch::Contains("meshes with boundaries are refused"));
}
