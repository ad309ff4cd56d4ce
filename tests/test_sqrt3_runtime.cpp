// The runtime on triangle meshes with sqrt(3) tables, against plain sqrt(3)
// subdivision (sqrt3_reference.hpp, written from Kobbelt's rules with no
// runtime code): 2j steps, then the limit rule at the vertex that sits at
// parameter (i/3^j, k/3^j) of each original face. This goes through the
// runtime's double sqrt(3) isolation steps, the 1-to-9 child location, the
// band regions of the extraordinary vertices' second rings and the regular
// faces next to them. Then watertight tessellations and the command-line tools.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>

#include "bundled_meshes.hpp"
#include "cli.hpp"
#include "runtime_checks.hpp"
#include "sqrt3_reference.hpp"
#include "runtime_api.hpp"
#include "triangle/triangle_family.hpp"

using namespace stencil_runtime;
using namespace test_runtime;
namespace fs = std::filesystem;
using test_meshes::bundled;
using test_meshes::kMeshes;
using test_meshes::kTriangleMeshes;

namespace {

// sqrt(3) tables at the rates 3^j the reference reaches (and 1), once per test process.
fs::path sqrt3_tables() { return generated_table("sqrt3", "--valence 3-8 --n 1,3,9,27", "sgt"); }


}  // namespace

TEST_CASE("runtime sqrt(3) evaluation equals plain sqrt(3) subdivision and its limit rule", "[runtime][triangle][sqrt3]") {
  const auto tables = Tables::load(sqrt3_tables().string());
  for (const char* name : kTriangleMeshes) {
    const Mesh mesh = bundled(name);
    const Surface surface = surface_of(tables, mesh);
    const auto& family = dynamic_cast<const TriangleFamily&>(surface.topology().family());
    // Every kind of face occurs: regular, the EV's own patch and the three band regions.
    std::set<std::pair<bool, int>> kinds;
    for (std::size_t f = 0; f < family.topology().faces(); ++f)
      kinds.emplace(family.patch(f).valence == 6, family.patch(f).region);
    CHECK(kinds == std::set<std::pair<bool, int>>{{true, 0}, {false, 0}, {false, 1}, {false, 2}, {false, 3}});

    sqrt3_reference::Subdivision reference(mesh);
    const double size = extent(mesh);
    double worst = 0;
    long n = 1;
    // n = 27 on the small mesh: its points fall inside the "down" cells of the 1-to-9 splits.
    const int levels = std::string(name) == "icosahedron" ? 3 : 2;
    for (int j = 1; j <= levels; ++j) {
      reference.step();
      reference.step();
      n *= 3;
      const auto limits = reference.limits();
      for (std::size_t f = 0; f < mesh.face_count(); ++f)
        for (long k = 0; k <= n; ++k)
          for (long i = 0; i + k <= n; ++i) {
            const Point ours = at_grid(surface, f, i, k, n);
            const auto& ref = limits[static_cast<std::size_t>(reference.vertex_at(static_cast<int>(f), i, k, n))];
            const double err = distance(ours, ref) / size;
            worst = std::max(worst, err);
            INFO(name << " face " << f << " at (" << i << "/" << n << ", " << k << "/" << n << "): " << err);
            REQUIRE(err < 1e-12);
          }
    }
    INFO(name << ": " << surface.topology().preparation() << ", largest difference " << worst);
    SUCCEED();
  }
}

TEST_CASE("sqrt(3) tessellations are closed oriented 2-manifolds for random rate mixes", "[runtime][triangle][sqrt3][tessellation]") {
  const auto tables = Tables::load(sqrt3_tables().string());
  std::mt19937 rng(20261122u);
  for (const char* name : kTriangleMeshes) {
    const Mesh mesh = bundled(name);
    const Surface surface = surface_of(tables, mesh);
    for (int trial = 0; trial < 3; ++trial) {
      std::vector<int> rates(mesh.face_count());
      for (int& r : rates) r = trial == 0 ? 1 : std::uniform_int_distribution<int>(1, 27)(rng);
      const PolygonSoup soup = tessellate(surface, rates);
      INFO(name << " trial " << trial);
      REQUIRE(tessellation_defect(soup, euler_characteristic(mesh)) == "");
    }
  }
}

TEST_CASE("stencileval and stenciltess take triangle meshes with sqrt(3) tables", "[runtime][triangle][sqrt3][tessellation]") {
  const fs::path dir = scratch_dir("sqrt3-tools");
  const std::string tables = sqrt3_tables().parent_path().string();
  const std::string mix = (kMeshes / "tri-mix.obj").string();
  const Mesh mesh = bundled("tri-mix");
  sqrt3_reference::Subdivision reference(mesh);
  for (int s = 0; s < 4; ++s) reference.step();
  const auto limits = reference.limits();
  {
    std::ofstream q(dir / "q.txt");
    q << "0 0 0\n1 1/3 1/3\n2 2/9 5/9\n3 1 0\n";
  }
  const CliResult r = run_stencileval("--tables " + tables + " --mesh " + mix + " --batch " + (dir / "q.txt").string());
  INFO(r.output);
  REQUIRE(r.status == 0);
  std::istringstream lines(r.output);
  const long queries[][3] = {{0, 0, 0}, {1, 3, 3}, {2, 2, 5}, {3, 9, 0}};  // face, i, k on n = 9
  for (const auto& q : queries) {
    Point p{};
    REQUIRE(static_cast<bool>(lines >> p[0] >> p[1] >> p[2]));
    const auto& ref = limits[static_cast<std::size_t>(reference.vertex_at(static_cast<int>(q[0]), q[1], q[2], 9))];
    REQUIRE(distance(p, ref) / extent(mesh) < 1e-12);
  }
  for (const std::string& mode : {std::string("--rate 9"), std::string("--tolerance 0.01")}) {
    const fs::path out = dir / "t.obj";
    const CliResult t = run_stenciltess("--tables " + tables + " --mesh " + mix + " " + mode + " --out " + out.string());
    INFO(mode << "\n" << t.output);
    REQUIRE(t.status == 0);
    const Mesh m = read_obj(out.string());
    const auto directed = directed_edges(m);
    for (const auto& [e, count] : directed) REQUIRE((count == 1 && directed.count({e.second, e.first}) == 1));
    REQUIRE(static_cast<long>(m.vertex_count()) - static_cast<long>(directed.size() / 2) + static_cast<long>(m.face_count()) ==
            euler_characteristic(mesh));
  }
  fs::remove_all(dir);
}

// A double is an exact binary fraction, but sqrt(3)'s steps (x 3) never
// shrink its denominator: adding two such coordinates (to find the face's part
// holding them) overflowed 64 bits before the descent's own fallback to
// doubles was reached, and stencileval refused parameters such as
// (0.001198901704, 0.993872147900) that stencildist itself returns. Now they
// are evaluated within the tolerance, and land next to the exact limit
// points of the grid round them (plain subdivision).
TEST_CASE("sqrt(3) evaluates any double parameter within its bound, next to the reference's limit points", "[runtime][triangle][sqrt3]") {
  const auto tables = Tables::load(sqrt3_tables().string());
  const Mesh mesh = bundled("tri-torus");
  const Surface surface = surface_of(tables, mesh);
  sqrt3_reference::Subdivision reference(mesh);
  constexpr long n = 9;
  reference.step(), reference.step(), reference.step(), reference.step();
  const auto limits = reference.limits();
  const double size = extent(mesh), tolerance = 1e-12 * size;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int trial = 0; trial < 100; ++trial) {
    const std::size_t f = static_cast<std::size_t>(trial) % mesh.face_count();
    double u = unit(rng), v = unit(rng);
    if (u + v > 1) u = 1 - u, v = 1 - v;
    if (trial % 4 == 0) u = 0.001198901704, v = 0.993872147900;  // the reported one, on every fourth face
    CAPTURE(f, u, v);
    Evaluation e;
    REQUIRE_NOTHROW(e = surface.evaluate(f, u, v, tolerance));
    CHECK(e.bound <= tolerance);
    // The nearest reference limit point of the face's grid 1/9 is within the grid's reach.
    double nearest = INFINITY;
    for (long k = 0; k <= n; ++k)
      for (long i = 0; i + k <= n; ++i)
        nearest = std::min(nearest, distance(e.point, limits[static_cast<std::size_t>(reference.vertex_at(static_cast<int>(f), i, k, n))]));
    CHECK(nearest < 0.2 * size);
  }
}
