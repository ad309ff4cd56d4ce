// Loop meshes with boundaries where every boundary vertex is in three faces
// (regular boundary patches: the box spline with affine phantoms,
// triangle/boundary_patch.hpp), against OpenSubdiv's Bfr with the same
// boundary option: uniformly triangulated tubes (every vertex regular) and a
// tube with extraordinary vertices next to its rims (isolation steps near the
// boundary). Also: tessellations with one rim per boundary loop, and the
// refusal that remains (sqrt(3)).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "bfr_reference.hpp"
#include "cli.hpp"
#include "closest_point_checks.hpp"
#include "loop_bfr_difference.hpp"
#include "loop_meshes.hpp"
#include "runtime_api.hpp"
#include "runtime_checks.hpp"
#include "stencil_runtime/closest_point.hpp"
#include "stencil_runtime/tessellation.hpp"

using namespace stencil_runtime;
using namespace test_runtime;

namespace {

using loop_meshes::triangle_tube;

// The tube with the diagonal of quad (0, row) flipped (inside: valence 5 and 7;
// on a rim: rim vertices in two and four faces).
Mesh tube_with_flip(int around, int rows, int row) { return loop_meshes::with_flip(triangle_tube(around, rows), around, row); }

Surface loop_surface(const std::shared_ptr<const Tables>& tables, const Mesh& m, BoundaryInterpolation boundary) {
  MeshFeatures features;
  features.boundary = boundary;
  return Surface(SurfaceTopology::create(tables, m.vertex_count(), m.face_sizes, m.face_vertices, {}, features), m.positions);
}

bfr_reference::Creasing osd_boundary(BoundaryInterpolation b) {
  bfr_reference::Creasing c;
  c.boundary_corners = b == BoundaryInterpolation::EdgeAndCorner;
  c.boundary_none = b == BoundaryInterpolation::None;
  return c;
}

std::pair<double, double> bfr_difference(const std::shared_ptr<const Tables>& tables, const Mesh& mesh, BoundaryInterpolation b) {
  SharpFeatures f;
  f.boundary(b);
  return loop_bfr_difference(tables, mesh, f);
}

std::shared_ptr<const Tables> loop_tables() { return Tables::load(generated_table("loop", "--valence 3-8 --n 1-8", "sgt").string()); }

}  // namespace

TEST_CASE("Loop boundaries: tubes whose rim vertices are in three faces equal OpenSubdiv's Bfr, every option",
          "[runtime][boundaries][loop][opensubdiv]") {
  const auto tables = loop_tables();
  for (const auto& [name, mesh] : {std::pair<std::string, Mesh>{"tube 8x3", triangle_tube(8, 3)},
                                   {"tube 6x1", triangle_tube(6, 1)},
                                   {"tube 3x1 (fans that wrap round it)", triangle_tube(3, 1)},
                                   {"tube 4x2", triangle_tube(4, 2)},
                                   {"tube 7x4 with a flipped diagonal inside", tube_with_flip(7, 4, 2)}})
    for (BoundaryInterpolation b : {BoundaryInterpolation::EdgeOnly, BoundaryInterpolation::EdgeAndCorner, BoundaryInterpolation::None}) {
      INFO(name << ", boundary option " << static_cast<int>(b));
      const bool all_at_rims = name == "tube 6x1" || name == "tube 4x2" || name.rfind("tube 3x1", 0) == 0;
      if (b == BoundaryInterpolation::None && all_at_rims) {  // every face at a rim: no surface left
        CHECK_THROWS_WITH(loop_surface(tables, mesh, b), Catch::Contains("the mesh has no surface"));
        continue;
      }
      const auto [positions, derivatives] = bfr_difference(tables, mesh, b);
      CHECK(positions < 1e-14);
      CHECK(derivatives < 1e-13);
    }
}

TEST_CASE("Loop boundaries with semi-sharp creases and corners equal OpenSubdiv's Bfr (boundary edges infinitely sharp)",
          "[runtime][boundaries][loop][creases][opensubdiv]") {
  const auto tables = loop_tables();
  const Mesh mesh = triangle_tube(8, 4);
  auto ring_edge = [&](int j, int i) { return std::pair{j * 8 + i % 8, j * 8 + (i + 1) % 8}; };
  for (BoundaryInterpolation b : {BoundaryInterpolation::EdgeOnly, BoundaryInterpolation::EdgeAndCorner}) {
    MeshFeatures features;
    features.boundary = b;
    bfr_reference::Creasing osd = osd_boundary(b);
    // A ring of mixed sharpness one row from the rim, an edge of 0.5 from the rim
    // inwards, and a corner of sharpness 2 on the rim itself.
    for (int i = 0; i < 8; ++i) {
      const auto [a, c] = ring_edge(1, i);
      const float s = i % 3 == 0 ? 2.5f : 1.0f;
      features.edges.push_back({a, c, s});
      osd.crease_pairs.insert(osd.crease_pairs.end(), {a, c});
      osd.crease_sharpness.push_back(s);
    }
    features.edges.push_back({0, 8, 0.5});
    osd.crease_pairs.insert(osd.crease_pairs.end(), {0, 8});
    osd.crease_sharpness.push_back(0.5f);
    features.vertices.push_back({3, 2.0});
    osd.corners.push_back(3);
    osd.corner_sharpness.push_back(2.0f);
    const Surface surface(SurfaceTopology::create(tables, mesh.vertex_count(), mesh.face_sizes, mesh.face_vertices, {}, features),
                          mesh.positions);
    bfr_reference::BfrLimit reference(mesh.positions, mesh.face_sizes, mesh.face_vertices, bfr_reference::osd::Sdc::SCHEME_LOOP, {},
                                      osd);
    const double size = extent(mesh);
    double worst = 0;
    for (std::size_t f = 0; f < mesh.face_count(); ++f)
      for (long n = 1; n <= 8; ++n)
        for (long j = 0; j <= n; ++j)
          for (long i = 0; i + j <= n; ++i) {
            const auto ref = reference.evaluate(static_cast<int>(f), static_cast<double>(i) / n, static_cast<double>(j) / n);
            worst = std::max(worst, distance(surface.evaluate(f, grid(i, j, n)), ref) / size);
          }
    INFO("boundary option " << static_cast<int>(b) << ", " << surface.topology().preparation());
    CHECK(worst < 1e-14);
  }
}

TEST_CASE("Loop boundaries: tessellations have one rim per boundary loop and the tube's Euler characteristic",
          "[runtime][boundaries][loop][tessellation]") {
  const auto tables = loop_tables();
  std::mt19937 rng(20261127u);
  for (const Mesh& mesh : {triangle_tube(8, 3), tube_with_flip(7, 4, 2)}) {
    const Surface surface = loop_surface(tables, mesh, BoundaryInterpolation::EdgeOnly);
    for (int trial = 0; trial < 4; ++trial) {
      std::vector<int> rates(mesh.face_count());
      for (int& r : rates) r = std::uniform_int_distribution<int>(1, 8)(rng);
      INFO("trial " << trial);
      check_rimmed_manifold(tessellate(surface, rates), 2, 0);
    }
  }
}

TEST_CASE("Loop boundaries, `none`: any boundary vertex is accepted, faces at the boundary have no surface, the others equal Bfr",
          "[runtime][boundaries][loop][opensubdiv]") {
  const auto tables = loop_tables();
  // Rim vertices in two and four faces next to the flipped diagonal.
  const Mesh mesh = tube_with_flip(7, 4, 0);
  const auto [positions, derivatives] = bfr_difference(tables, mesh, BoundaryInterpolation::None);
  CHECK(positions < 1e-14);
  CHECK(derivatives < 1e-13);
}

TEST_CASE("Loop boundaries: what is not evaluated yet is refused, naming the vertex or the reason", "[runtime][boundaries][loop]") {
  // (Boundary vertices in other than three faces: test_loop_sectors.cpp.)
  const auto sqrt3 = Tables::load(generated_table("sqrt3", "--valence 3-8 --n 3", "sgt").string());
  CHECK_THROWS_WITH(loop_surface(sqrt3, triangle_tube(6, 2), BoundaryInterpolation::EdgeOnly),
                    Catch::Contains("sqrt(3), which splits no edges") && Catch::Contains("meshes with boundaries are refused"));
}

TEST_CASE("Loop boundaries: closest points on an open tube are on the surface and no farther than dense exact samples",
          "[runtime][boundaries][loop][distance]") {
  const auto tables = loop_tables();
  const Mesh mesh = tube_with_flip(7, 4, 2);
  const Surface surface = loop_surface(tables, mesh, BoundaryInterpolation::EdgeOnly);
  const double size = extent(mesh);
  // Dense exact samples: every node at rate 8 of every face (the rim included).
  const std::vector<Point> samples = surface_nodes(surface, mesh, 8);
  const ClosestPointQuery query(surface);
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> box(-1.6, 1.6), height(-0.5, 2.9);
  for (int k = 0; k < 200; ++k) {
    const Point q{box(rng), box(rng), height(rng)};
    const ClosestPoint c = query.find(q);
    INFO("query " << k);
    REQUIRE(closest_point_defect(surface, q, c, samples, size, 1e-9 * size) == "");
    // Inside a face (not on its edges, where the minimum may be a kink or the
    // rim), the residual is orthogonal to the tangent plane.
    if (c.u > 1e-6 && c.v > 1e-6 && c.u + c.v < 1 - 1e-6) {
      const Derivatives d = surface.derivatives(c.face, c.u, c.v);
      const Point r{q[0] - c.point[0], q[1] - c.point[1], q[2] - c.point[2]};
      auto cosine = [&](const Point& t) {
        return std::abs(r[0] * t[0] + r[1] * t[1] + r[2] * t[2]) / (std::max(c.distance, 1e-300) * std::hypot(t[0], t[1], t[2]));
      };
      if (c.distance > 1e-6 * size) CHECK(std::max(cosine(d.du), cosine(d.dv)) < 1e-6);
    }
  }
}
