// Loop meshes whose boundary vertices are in other than three faces, and
// corners (the tables' boundary sectors, triangle/sector_patch.hpp), against
// OpenSubdiv's Bfr with the same boundary option and tags: open triangulated
// grids (corners in one and two faces), fans of 1..8 faces round one vertex, a
// tube whose rims have vertices in two and four faces, an icosahedron with
// faces removed (boundary vertices in four faces, valence 5 inside), corners
// tagged infinitely sharp on a rim.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <tuple>

#include "cli.hpp"
#include "closest_point_checks.hpp"
#include "loop_bfr_difference.hpp"
#include "loop_meshes.hpp"
#include "runtime_api.hpp"
#include "runtime_checks.hpp"
#include "bundled_meshes.hpp"
#include "family/family.hpp"
#include "stencil_runtime/closest_point.hpp"
#include "stencil_runtime/tessellation.hpp"

using namespace stencil_runtime;
using namespace test_runtime;

namespace {

std::shared_ptr<const Tables> loop_tables() { return Tables::load(generated_table("loop", "--valence 3-8 --n 1-8", "sgt").string()); }

// A grid of w x h quads, each split along its (0,0)-(1,1) diagonal, gently bent.
Mesh open_grid(int w, int h) {
  Mesh m;
  for (int j = 0; j <= h; ++j)
    for (int i = 0; i <= w; ++i)
      m.positions.push_back({double(i) + 0.1 * std::sin(1.7 * j), double(j) + 0.1 * std::cos(2.3 * i), 0.3 * std::sin(0.9 * i + 0.4 * j * j)});
  auto at = [&](int i, int j) { return j * (w + 1) + i; };
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      m.face_sizes.insert(m.face_sizes.end(), {3, 3});
      m.face_vertices.insert(m.face_vertices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return m;
}

// k triangles round vertex 0, open: its rim vertices in one or two faces.
Mesh fan(int k) {
  Mesh m;
  m.positions.push_back({0, 0, 0.4});
  const double step = (k <= 5 ? 1.0 : 5.5 / k) * M_PI / 3;
  for (int j = 0; j <= k; ++j) m.positions.push_back({std::cos(j * step), std::sin(j * step), 0.2 * std::sin(3.0 * j)});
  for (int j = 0; j < k; ++j) {
    m.face_sizes.push_back(3);
    m.face_vertices.insert(m.face_vertices.end(), {0, j + 1, j + 2});
  }
  return m;
}

std::pair<double, double> difference(const std::shared_ptr<const Tables>& tables, const Mesh& mesh, BoundaryInterpolation b,
                                     const std::vector<std::pair<int, float>>& corners = {}) {
  SharpFeatures f;
  f.boundary(b);
  for (const auto& [v, s] : corners) f.corner(v, s);
  return loop_bfr_difference(tables, mesh, f);
}

}  // namespace

TEST_CASE("Loop sectors: open grids equal OpenSubdiv's Bfr, edge-only and edge-and-corner", "[runtime][boundaries][loop][opensubdiv]") {
  const auto tables = loop_tables();
  for (const auto& [w, h] : {std::pair{3, 2}, {5, 4}, {1, 1}})
    for (const auto b : {BoundaryInterpolation::EdgeOnly, BoundaryInterpolation::EdgeAndCorner}) {
      INFO(w << " x " << h << (b == BoundaryInterpolation::EdgeOnly ? ", edge-only" : ", edge-and-corner"));
      const auto [positions, derivatives] = difference(tables, open_grid(w, h), b);
      CHECK(positions < 1e-14);
      CHECK(derivatives < 1e-13);
    }
}

TEST_CASE("Loop sectors: fans of 1..8 faces round one vertex equal Bfr", "[runtime][boundaries][loop][opensubdiv]") {
  const auto tables = loop_tables();
  for (int k = 1; k <= 8; ++k)
    for (const auto b : {BoundaryInterpolation::EdgeOnly, BoundaryInterpolation::EdgeAndCorner}) {
      INFO(k << " faces" << (b == BoundaryInterpolation::EdgeOnly ? ", edge-only" : ", edge-and-corner"));
      const auto [positions, derivatives] = difference(tables, fan(k), b);
      CHECK(positions < 1e-14);
      CHECK(derivatives < 1e-13);
    }
}

TEST_CASE("Loop sectors: a tube with rim vertices in two and four faces equals Bfr", "[runtime][boundaries][loop][opensubdiv]") {
  const auto tables = loop_tables();
  const Mesh mesh = loop_meshes::with_flip(loop_meshes::triangle_tube(7, 4), 7, 0);
  for (const auto b : {BoundaryInterpolation::EdgeOnly, BoundaryInterpolation::EdgeAndCorner}) {
    const auto [positions, derivatives] = difference(tables, mesh, b);
    CHECK(positions < 1e-14);
    CHECK(derivatives < 1e-13);
  }
}

TEST_CASE("Loop sectors: infinitely sharp corners on a rim are corner sectors equal to Bfr", "[runtime][boundaries][loop][opensubdiv]") {
  const auto tables = loop_tables();
  // Rim vertices in three faces tagged as corners (sharpness 10: infinite), and one of sharpness 2 (semi-sharp).
  const Mesh mesh = loop_meshes::triangle_tube(8, 3);
  const auto [positions, derivatives] = difference(tables, mesh, BoundaryInterpolation::EdgeOnly, {{1, 10.0f}, {5, 10.0f}, {27, 10.0f}, {30, 2.0f}});
  CHECK(positions < 1e-14);
  CHECK(derivatives < 1e-13);
}

TEST_CASE("Loop sectors: a triangulated cube with sharp edges, corners and semi-sharp edges equals Bfr",
          "[runtime][creases][loop][opensubdiv]") {
  const auto tables = loop_tables();
  // Each quad (a, b, c, d) of the cube split into (a, b, c) and (a, c, d); its 12 edges are the quads' edges.
  const Mesh quads = stencil_runtime::read_obj((test_meshes::kMeshes / "cube.obj").string());
  Mesh cube;
  cube.positions = quads.positions;
  std::vector<std::pair<int, int>> edges;
  for (std::size_t f = 0; f < quads.face_count(); ++f) {
    const int* q = &quads.face_vertices[4 * f];
    cube.face_sizes.insert(cube.face_sizes.end(), {3, 3});
    cube.face_vertices.insert(cube.face_vertices.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
    for (int c = 0; c < 4; ++c)
      if (q[c] < q[(c + 1) % 4]) edges.emplace_back(q[c], q[(c + 1) % 4]);
      else edges.emplace_back(q[(c + 1) % 4], q[c]);
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  REQUIRE(edges.size() == 12);
  {
    SharpFeatures f;  // every edge infinitely sharp: each corner on three sharp edges, its sides in one or two faces
    for (const auto& [a, b] : edges) f.crease(a, b, 10);
    const auto [positions, derivatives] = loop_bfr_difference(tables, cube, f);
    CHECK(positions < 1e-14);
    CHECK(derivatives < 1e-13);
  }
  {
    // A loop of four sharp edges round one face with a sharp corner on it, and
    // semi-sharp edges of 0.5, 1 and 2.5 round the opposite face (no vertex in common).
    SharpFeatures f;
    const int* q = &quads.face_vertices[0];
    for (int c = 0; c < 4; ++c) f.crease(q[c], q[(c + 1) % 4], 10);
    f.corner(q[2], 10);
    const int* o = &quads.face_vertices[4];
    f.crease(o[0], o[1], 0.5f);
    f.crease(o[1], o[2], 1.0f);
    f.crease(o[2], o[3], 2.5f);
    const auto [positions, derivatives] = loop_bfr_difference(tables, cube, f);
    CHECK(positions < 1e-14);
    CHECK(derivatives < 1e-13);
  }
}

TEST_CASE("Loop sectors: tessellations with random rates have one rim per boundary loop and the right Euler characteristic",
          "[runtime][boundaries][loop][tessellation]") {
  const auto tables = loop_tables();
  std::mt19937 rng(20261127u);
  const struct {
    const char* name;
    Mesh mesh;
    std::size_t rims;
    int genus;
  } cases[] = {{"grid 5x4", open_grid(5, 4), 1, 0},
               {"fan of 7", fan(7), 1, 0},
               {"tube with rim vertices in two and four faces", loop_meshes::with_flip(loop_meshes::triangle_tube(7, 4), 7, 0), 2, 0}};
  for (const auto& c : cases)
    for (const auto b : {BoundaryInterpolation::EdgeOnly, BoundaryInterpolation::EdgeAndCorner}) {
      MeshFeatures features;
      features.boundary = b;
      const Surface surface(SurfaceTopology::create(tables, c.mesh.vertex_count(), c.mesh.face_sizes, c.mesh.face_vertices, {}, features),
                            c.mesh.positions);
      for (int trial = 0; trial < 3; ++trial) {
        std::vector<int> rates(c.mesh.face_count());
        for (int& r : rates) r = std::uniform_int_distribution<int>(1, 8)(rng);
        INFO(c.name << ", trial " << trial);
        check_rimmed_manifold(tessellate(surface, rates), c.rims, c.genus);
      }
    }
}

TEST_CASE("Loop sectors: closest points lie on the surface and no farther than dense exact samples",
          "[runtime][boundaries][loop][distance]") {
  const auto tables = loop_tables();
  std::mt19937 rng(29);
  for (const auto& [name, mesh, b] : {std::tuple{"grid 4x3, edge-only", open_grid(4, 3), BoundaryInterpolation::EdgeOnly},
                                      std::tuple{"grid 4x3, edge-and-corner", open_grid(4, 3), BoundaryInterpolation::EdgeAndCorner},
                                      std::tuple{"fan of 7", fan(7), BoundaryInterpolation::EdgeOnly}}) {
    MeshFeatures features;
    features.boundary = b;
    const Surface surface(SurfaceTopology::create(tables, mesh.vertex_count(), mesh.face_sizes, mesh.face_vertices, {}, features),
                          mesh.positions);
    const double size = extent(mesh);
    // Dense exact samples: every node at rate 12 of every face (the rim and the sector vertices included).
    const std::vector<Point> samples = surface_nodes(surface, mesh, 12);
    const ClosestPointQuery query(surface);
    for (int k = 0; k < 150; ++k) {
      const Point q = random_query(samples, 0.3 * size, rng);
      INFO(name << ", query " << k);
      CHECK(closest_point_defect(surface, q, query.find(q), samples, size, 1e-9 * size) == "");
    }
  }
}

// The bound the closest-point search relies on: a sector face's surface lies in
// the hull of its root sub-patch's points (its layout's and the widened box's
// corners), on fans and grids with random heights. The widened box is a proven
// bound, not a tight one: in these 159 sector faces the surface stayed in its
// layout points' box too, and reaches its edges (the same box shrunk by 5% of
// its extent on each side is left, so the check is not vacuous).
TEST_CASE("Loop sectors: the widened box holds a sector's surface",
          "[runtime][boundaries][loop][distance]") {
  const auto tables = loop_tables();
  std::mt19937 rng(404);
  std::uniform_real_distribution<double> noise(-1, 1);
  double beyond_shrunk = 0, beyond_box = 0;
  int sector_faces = 0;
  for (int trial = 0; trial < 20; ++trial) {
    Mesh mesh = trial % 2 ? open_grid(3, 3) : fan(1 + trial % 8);
    for (Point& p : mesh.positions) p[2] += noise(rng);
    MeshFeatures features;
    features.boundary = trial % 4 < 2 ? BoundaryInterpolation::EdgeOnly : BoundaryInterpolation::EdgeAndCorner;
    const Surface surface(SurfaceTopology::create(tables, mesh.vertex_count(), mesh.face_sizes, mesh.face_vertices, {}, features),
                          mesh.positions);
    const Family& family = surface.topology().family();
    for (std::size_t f = 0; f < surface.topology().prepared_face_count(); ++f) {
      SubPatch root;
      family.root(f, surface.prepared_positions().data(), root);
      if (root.kind <= family.max_kind()) continue;  // not a sector
      ++sector_faces;
      const std::size_t layout = root.points.size() - 8;
      Point lo = root.points[0], hi = lo, wlo = lo, whi = lo;
      for (std::size_t h = 0; h < root.points.size(); ++h)
        for (int k = 0; k < 3; ++k) {
          if (h < layout) lo[k] = std::min(lo[k], root.points[h][k]), hi[k] = std::max(hi[k], root.points[h][k]);
          wlo[k] = std::min(wlo[k], root.points[h][k]), whi[k] = std::max(whi[k], root.points[h][k]);
        }
      for (int j = 0; j <= 24; ++j)
        for (int i = 0; i + j <= 24; ++i) {
          const Point p = family.evaluate(root, i / 24.0, j / 24.0, 1e-13).point;
          for (int k = 0; k < 3; ++k) {
            const double size = hi[k] - lo[k] + 1e-300;
            beyond_shrunk = std::max({beyond_shrunk, (lo[k] + 0.05 * size - p[k]) / size, (p[k] - hi[k] + 0.05 * size) / size});
            beyond_box = std::max({beyond_box, (wlo[k] - p[k]) / size, (p[k] - whi[k]) / size});
          }
        }
    }
  }
  INFO(sector_faces << " sector faces; beyond the widened box: " << beyond_box << "; beyond the shrunk layout box: " << beyond_shrunk);
  CHECK(sector_faces > 100);
  CHECK(beyond_box <= 0);
  CHECK(beyond_shrunk > 0);
}
