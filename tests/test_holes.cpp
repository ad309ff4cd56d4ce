// Faces tagged as holes (OpenSubdiv's `hole` tag): no surface there, the
// surface round them unchanged, and tessellations that leave them out with a
// clean rim. Oracles: OpenSubdiv Bfr with the same holes (its factory reports
// no limit surface at a hole and evaluates the others), and an independent
// count of the output's edges, boundary loops and Euler characteristic.
#include <catch2/catch.hpp>
#include <filesystem>
#include <functional>
#include <fstream>
#include <map>
#include <numeric>
#include <random>
#include <set>

#include "bfr_distance.hpp"
#include "bfr_reference.hpp"
#include "cli.hpp"
#include "runtime_api.hpp"
#include "runtime_checks.hpp"
#include "stencil_runtime/closest_point.hpp"

using namespace stencil_runtime;
using namespace test_runtime;
namespace fs = std::filesystem;

namespace {

const fs::path kMeshes = fs::path(STENCIL_SOURCE_DIR) / "meshes";

Mesh load(const std::string& name) { return read_obj((kMeshes / (name + ".obj")).string()); }

// Faces no two of which share a vertex, about one in `every`: each hole then has its own rim.
std::vector<int> separated_faces(const Mesh& m, std::size_t every) {
  std::vector<char> used(m.vertex_count(), 0);
  std::vector<int> out;
  std::size_t offset = 0;
  for (std::size_t f = 0; f < m.face_count(); ++f) {
    const auto size = static_cast<std::size_t>(m.face_sizes[f]);
    bool free = f % every == 0;
    for (std::size_t k = 0; k < size && free; ++k) free = !used[static_cast<std::size_t>(m.face_vertices[offset + k])];
    if (free) {
      for (std::size_t k = 0; k < size; ++k) used[static_cast<std::size_t>(m.face_vertices[offset + k])] = 1;
      out.push_back(static_cast<int>(f));
    }
    offset += size;
  }
  return out;
}

}  // namespace

TEST_CASE("holes: the surface round them equals OpenSubdiv's with the same holes, and they have none",
          "[runtime][holes][opensubdiv]") {
  struct Case {
    const char* mesh;
    const char* scheme;
    const char* options;
    const char* extension;
    std::size_t every;
  };
  for (const Case& c : {Case{"cube", "catmull-clark", "--valence 3-8 --n 4", "sgs", 4},
                        Case{"chess-piece", "catmull-clark", "--valence 3-8 --n 4", "sgs", 9},
                        Case{"icosahedron", "loop", "--valence 3-8 --n 4", "sgt", 5},
                        Case{"tri-torus", "loop", "--valence 3-8 --n 4", "sgt", 7}}) {
    const Mesh mesh = load(c.mesh);
    const std::vector<int> holes = separated_faces(mesh, c.every);
    REQUIRE(!holes.empty());
    const auto tables = Tables::load(generated_table(c.scheme, c.options, c.extension).string());
    const Surface surface(SurfaceTopology::create(tables, mesh.vertex_count(), mesh.face_sizes, mesh.face_vertices, holes),
                          mesh.positions);
    const bool loop = std::string(c.scheme) == "loop";
    bfr_reference::BfrLimit reference(mesh.positions, mesh.face_sizes, mesh.face_vertices,
                                      loop ? bfr_reference::osd::Sdc::SCHEME_LOOP : bfr_reference::osd::Sdc::SCHEME_CATMARK,
                                      holes);
    const double size = extent(mesh);
    double worst = 0;
    for (std::size_t f = 0; f < mesh.face_count(); ++f) {
      const bool hole = std::find(holes.begin(), holes.end(), static_cast<int>(f)) != holes.end();
      INFO(c.mesh << " face " << f);
      REQUIRE(reference.has_surface(static_cast<int>(f)) == !hole);  // the oracle agrees on which faces are holes
      REQUIRE(surface.topology().is_hole(f) == hole);
      if (hole) {
        CHECK_THROWS_WITH(surface.evaluate(f, grid(1, 2, 4)), Catch::Contains("face " + std::to_string(f) + " is a hole"));
        CHECK_THROWS_WITH(surface.evaluate(f, 0.5, 0.25, 1e-9), Catch::Contains("is a hole"));
        CHECK_THROWS_WITH(surface.derivatives(f, 0.5, 0.25), Catch::Contains("is a hole"));
        CHECK_THROWS_WITH(surface.normal(f, grid(0, 0, 1)), Catch::Contains("is a hole"));
        continue;
      }
      if (mesh.face_sizes[f] != (loop ? 3 : 4)) continue;
      for (long j = 0; j <= 4; ++j)
        for (long i = 0; i + (loop ? j : 0) <= 4; ++i) {
          const Point ours = surface.evaluate(f, grid(i, j, 4));
          const auto ref = reference.evaluate(static_cast<int>(f), static_cast<double>(i) / 4, static_cast<double>(j) / 4);
          worst = std::max(worst, distance(ours, ref) / size);
        }
    }
    CHECK(worst < 1e-10);
    WARN(c.mesh << " (" << c.scheme << ", " << holes.size() << " holes): largest difference to Bfr over the mesh size " << worst);
  }
}

TEST_CASE("holes: tessellations leave them out, with one rim per hole and the Euler characteristic that says so",
          "[runtime][holes][tessellation]") {
  std::mt19937 rng(20261125u);
  struct Case {
    const char* mesh;
    const char* scheme;
    const char* options;
    const char* extension;
    int genus;
  };
  for (const Case& c : {Case{"cube", "nonpoly", "--valence 3-8 --n 1-6", "sgs", 0},
                        Case{"torus-3-5", "catmull-clark", "--valence 3-8 --n 1-6", "sgs", 1},
                        Case{"chess-piece", "nonpoly", "--valence 3-8 --n 1-6", "sgs", 0},
                        Case{"tri-torus", "loop", "--valence 3-8 --n 1-6", "sgt", 1},
                        Case{"icosahedron", "sqrt3", "--valence 3-8 --n 1-3", "sgt", 0}}) {
    const Mesh mesh = load(c.mesh);
    const auto tables = Tables::load(generated_table(c.scheme, c.options, c.extension).string());
    for (std::size_t every : {3, 11}) {
      const std::vector<int> holes = separated_faces(mesh, every);
      const Surface surface(SurfaceTopology::create(tables, mesh.vertex_count(), mesh.face_sizes, mesh.face_vertices, holes),
                            mesh.positions);
      for (int trial = 0; trial < 3; ++trial) {
        std::vector<int> rates(mesh.face_count());
        for (int& r : rates) r = std::uniform_int_distribution<int>(1, 6)(rng);
        INFO(c.mesh << " (" << c.scheme << ") with " << holes.size() << " holes, trial " << trial);
        const PolygonSoup soup = tessellate(surface, rates);

        check_rimmed_manifold(soup, holes.size(), c.genus);
      }
    }
  }
}

TEST_CASE("holes from OBJ tags: evaluated round, refused in, left out of stenciltess, and stencildist refuses --signed",
          "[runtime][holes][tags]") {
  const fs::path dir = scratch_dir("holes-cli");
  {
    std::ifstream in(kMeshes / "cube.obj");
    std::ofstream out(dir / "cube-hole.obj");
    out << in.rdbuf() << "t hole 1/0/0 3\n";
  }
  const std::string tables = generated_table("catmull-clark", "--valence 3-8 --n 4", "sgs").parent_path().string();
  const std::string mesh = (dir / "cube-hole.obj").string();
  CliResult r = run_stencileval("--tables " + tables + " --mesh " + mesh + " --face 3 --uv 1/2,1/2");
  CHECK(r.status == 1);
  CHECK_THAT(r.output, Catch::Contains("face 3 is a hole"));
  r = run_stencileval("--tables " + tables + " --mesh " + mesh + " --face 2 --uv 1/2,1/2");
  CHECK(r.status == 0);
  r = run_stenciltess("--tables " + tables + " --mesh " + mesh + " --rate 4 --out " + (dir / "t.obj").string());
  REQUIRE(r.status == 0);
  const Mesh out = read_obj((dir / "t.obj").string());
  // Five faces of 4 prepared faces at rate 2 (4 / 2; the hole's four left out), one point per grid cell, and the
  // rim: the limit curve at the grid nodes of the hole's 8 prepared edges (2 per edge, the ends shared).
  CHECK(out.vertex_count() == 5 * 4 * 4 + 8 * 2);
  std::ofstream(dir / "points.xyz") << "0 0 0\n1 2 3\n";
  r = run_command(STENCILDIST_EXE, "--tables " + tables + " --mesh " + mesh + " --points " + (dir / "points.xyz").string() + " --signed");
  CHECK(r.status == 1);
  CHECK_THAT(r.output, Catch::Contains("--signed needs a closed surface") && Catch::Contains("line 17"));
  CHECK_THROWS_WITH(SurfaceTopology::create(Tables::load(tables), 8, read_obj(mesh).face_sizes, read_obj(mesh).face_vertices,
                                            {0, 1, 2, 3, 4, 5}),
                    Catch::Contains("every face is a hole"));
  CHECK_THROWS_WITH(SurfaceTopology::create(Tables::load(tables), 8, read_obj(mesh).face_sizes, read_obj(mesh).face_vertices, {6}),
                    Catch::Contains("hole face 6 does not exist"));
  fs::remove_all(dir);
}

TEST_CASE("holes: closest points never land in a hole and equal a Bfr brute force with the same holes",
          "[runtime][holes][distance][opensubdiv]") {
  std::mt19937 rng(7);
  for (const char* name : {"cube", "icosahedron"}) {
    const bool loop = std::string(name) == "icosahedron";
    const Mesh mesh = load(name);
    const std::vector<int> holes = separated_faces(mesh, 3);
    const auto tables = Tables::load(
        generated_table(loop ? "loop" : "catmull-clark", "--valence 3-8 --n 4", loop ? "sgt" : "sgs").string());
    const Surface surface(SurfaceTopology::create(tables, mesh.vertex_count(), mesh.face_sizes, mesh.face_vertices, holes),
                          mesh.positions);
    const ClosestPointQuery query(surface);
    const bfr_reference::BfrOracle oracle(mesh, loop ? bfr_reference::osd::Sdc::SCHEME_LOOP : bfr_reference::osd::Sdc::SCHEME_CATMARK,
                                          holes);
    const double size = extent(mesh);
    std::uniform_real_distribution<double> coordinate(-1.5, 1.5);
    for (int k = 0; k < 40; ++k) {
      // Points all round, some just off the surface above a hole (where the closed surface would be nearest).
      Point q{coordinate(rng), coordinate(rng), coordinate(rng)};
      if (k % 4 == 0) {
        const Point on = Surface(SurfaceTopology::create(tables, mesh.vertex_count(), mesh.face_sizes, mesh.face_vertices),
                                 mesh.positions)
                             .evaluate(static_cast<std::size_t>(holes[static_cast<std::size_t>(k / 4) % holes.size()]),
                                       grid(1, 1, 3));
        for (int c = 0; c < 3; ++c) q[static_cast<std::size_t>(c)] = on[static_cast<std::size_t>(c)] * 1.05;
      }
      INFO(name << " query " << k << ": " << q[0] << " " << q[1] << " " << q[2]);
      const ClosestPoint ours = query.find(q);
      REQUIRE(ours.found);
      CHECK_FALSE(surface.topology().is_hole(ours.face));
      CHECK(std::abs(ours.distance - oracle.distance_to(q)) < 1e-8 * size);
    }
  }
}
