// Runtime v2: topology once, positions every frame. A surface whose positions
// are replaced equals, bit for bit, a surface built afresh from the moved mesh
// (points, prepared positions and whole tessellations), for quad and triangle
// schemes, with isolation steps and with the polygon step; and the interface
// leaves no way to outlive the tables.
#include <catch2/catch.hpp>
#include <cstring>
#include <filesystem>
#include <random>
#include <type_traits>

#include "bundled_meshes.hpp"
#include "cli.hpp"
#include "runtime_api.hpp"
#include "runtime_checks.hpp"

using namespace stencil_runtime;
using namespace test_runtime;
namespace fs = std::filesystem;
using test_meshes::bundled;

namespace {

// The mesh with every vertex moved by a random offset of up to a tenth of its size.
Mesh moved(Mesh m, unsigned seed) {
  std::mt19937 rng(seed);
  const double amount = 0.1 * extent(m);
  std::uniform_real_distribution<double> offset(-amount, amount);
  for (auto& p : m.positions)
    for (double& x : p) x += offset(rng);
  return m;
}

bool same_bits(const std::vector<Point>& a, const std::vector<Point>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Point)) == 0;
}

// Per frame against afresh, for one scheme's tables and one mesh.
void check_frames(const std::shared_ptr<const Tables>& tables, const Mesh& rest, int expected_steps) {
  const auto topology = topology_of(tables, rest);
  REQUIRE(topology->refinement_steps() == expected_steps);
  Surface animated(topology, rest.positions);
  std::vector<int> rates(rest.face_count());
  for (std::size_t f = 0; f < rates.size(); ++f) rates[f] = 1 + static_cast<int>((f * 7) % 9);
  const TessellationPlan plan(topology, rates);
  PolygonSoup frame = plan.make_soup();
  for (unsigned k = 1; k <= 3; ++k) {
    const Mesh pose = moved(rest, k);
    animated.set_positions(pose.positions);
    plan.evaluate(animated, frame.positions.data());

    const Surface fresh = surface_of(tables, pose);
    INFO(tables->scheme() << " frame " << k);
    REQUIRE(same_bits(animated.prepared_positions(), fresh.prepared_positions()));
    const PolygonSoup again = tessellate(fresh, rates);
    REQUIRE(frame.positions.size() == again.positions.size());
    REQUIRE(std::memcmp(frame.positions.data(), again.positions.data(), frame.positions.size() * sizeof(frame.positions[0])) == 0);
    REQUIRE(frame.quads == again.quads);
    REQUIRE(frame.triangles == again.triangles);
    for (std::size_t f = 0; f < rest.face_count(); ++f) {
      const FaceDomain d = topology->domain(f);
      const ExactParameter at = d.kind == FaceDomain::Kind::Triangle ? grid(1, 1, 3)
                                : d.kind == FaceDomain::Kind::Quad   ? grid(1, 2, 3)
                                                                     : grid(1, 1, 4);
      const Point a = animated.evaluate(f, at), b = fresh.evaluate(f, at);
      REQUIRE(std::memcmp(a.data(), b.data(), sizeof a) == 0);
    }
  }
}

}  // namespace

TEST_CASE("new positions per frame equal a fresh build from the moved mesh, bit for bit", "[runtime][frames]") {
  const auto nonpoly = Tables::load(generated_table("nonpoly", "--valence 3-8 --n 24", "sgs").string());
  const auto cc = Tables::load(generated_table("catmull-clark", "--valence 3-8 --n 24", "sgs").string());
  const auto loop = Tables::load(generated_table("loop", "--valence 3-8 --n 24", "sgt").string());
  const auto sqrt3 = Tables::load(generated_table("sqrt3", "--valence 3-8 --n 1,3,9,27", "sgt").string());
  check_frames(nonpoly, bundled("cube"), 1);         // isolation step
  check_frames(nonpoly, bundled("chess-piece"), 1);
  check_frames(cc, prism(), 2);                      // the polygon step, then isolation
  check_frames(loop, bundled("tri-mix"), 1);
  check_frames(sqrt3, bundled("icosahedron"), 2);    // two double sqrt(3) steps
}

TEST_CASE("a surface keeps its tables alive, and tables exist only shared", "[runtime][frames]") {
  static_assert(!std::is_default_constructible_v<Tables>);
  static_assert(!std::is_copy_constructible_v<Tables>);
  static_assert(!std::is_copy_constructible_v<SurfaceTopology>);
  const Mesh cube = bundled("cube");
  std::unique_ptr<Surface> surface;
  {
    auto tables = Tables::load(generated_table("nonpoly", "--valence 3-8 --n 24", "sgs").string());
    surface = std::make_unique<Surface>(topology_of(tables, cube), cube.positions);
  }  // the caller's handle is gone; the topology still shares the tables
  const Point p = surface->evaluate(0, grid(1, 2, 3));
  CHECK(std::isfinite(p[0]));
  CHECK(surface->topology().tables().scheme() == "nonpoly");
}

TEST_CASE("per-frame input is checked: count, finiteness, topology", "[runtime][frames][errors]") {
  const auto tables = Tables::load(generated_table("nonpoly", "--valence 3-8 --n 24", "sgs").string());
  const Mesh cube = bundled("cube");
  Surface surface(topology_of(tables, cube));
  CHECK_THROWS_WITH(surface.evaluate(0, grid(0, 0, 1)), Catch::Contains("no control positions"));
  std::vector<Point> few(cube.positions.begin(), cube.positions.end() - 1);
  CHECK_THROWS_WITH(surface.set_positions(few), Catch::Contains("7 control positions for a mesh of 8 vertices"));
  std::vector<Point> bad = cube.positions;
  bad[5][1] = std::numeric_limits<double>::infinity();
  CHECK_THROWS_WITH(surface.set_positions(bad), Catch::Contains("vertex 5"));
  bad[5][1] = 1e300;
  CHECK_THROWS_WITH(surface.set_positions(bad), Catch::Contains("at most 1e37"));
  surface.set_positions(cube.positions);
  const TessellationPlan other(topology_of(tables, cube), std::vector<int>(6, 2));
  std::vector<std::array<float, 3>> out(other.point_count());
  CHECK_THROWS_WITH(other.evaluate(surface, out.data()), Catch::Contains("another topology"));
}
