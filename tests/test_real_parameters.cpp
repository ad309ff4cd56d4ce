// Evaluation at any parameter (runtime v2): the patch descends through the
// scheme's own subdivision matrices. Catmull-Clark ends in bicubic pieces, so
// the value at any real parameter equals OpenSubdiv's there; nonpoly at
// parameters no stored rate holds (1/29 with rates 1..24) agrees with the exact
// value from tables that do hold them, within the reported bound, and the bound
// is not loose (within 100 times the actual error); dyadic parameters are
// reached exactly.
#include <catch2/catch.hpp>
#include <filesystem>
#include <random>

#include "bfr_reference.hpp"
#include "bundled_meshes.hpp"
#include "cli.hpp"
#include "runtime_api.hpp"
#include "runtime_checks.hpp"

using namespace stencil_runtime;
using namespace test_runtime;
namespace fs = std::filesystem;
using test_meshes::bundled;

TEST_CASE("Catmull-Clark at real parameters equals OpenSubdiv at the same parameters", "[runtime][real]") {
  const auto cc = Tables::load(generated_table("catmull-clark", "--valence 3-8 --n 24", "sgs").string());
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const char* name : {"cube", "torus-3-5", "chess-piece", "bumpy-sphere"}) {
    const Mesh mesh = bundled(name);
    const Surface surface = surface_of(cc, mesh);
    bfr_reference::BfrLimit reference(mesh.positions, mesh.face_sizes, mesh.face_vertices);
    const double size = extent(mesh);
    for (std::size_t f = 0; f < mesh.face_count(); f += 3) {
      // Random points, points near the corners (extraordinary vertices: eight
      // levels of A0 and more, but still where Bfr at level 10 is exact) and
      // non-dyadic ones.
      std::vector<std::array<double, 2>> uv{{unit(rng), unit(rng)}, {0.002 + 1e-3 * unit(rng), 0.002 * unit(rng)},
                                            {1 - 0.002, 0.0025}, {1.0 / 29, 0.3}, {0.5, 1.0 / 3}};
      for (const auto& [u, v] : uv) {
        const Evaluation ours = surface.evaluate(f, u, v, 1e-12 * size);
        const auto ref = reference.evaluate(static_cast<int>(f), u, v);
        INFO(name << " face " << f << " at (" << u << ", " << v << "), bound " << ours.bound);
        REQUIRE(ours.exact);
        REQUIRE(distance(ours.point, ref) / size < 1e-12);
      }
    }
  }
}

TEST_CASE("near every corner of a cube face the surface has the cube's symmetry", "[runtime][real]") {
  const Mesh cube = bundled("cube");
  for (const char* scheme : {"catmull-clark", "nonpoly"}) {
    const Surface surface = surface_of(Tables::load(generated_table(scheme, "--valence 3-8 --n 24", "sgs").string()), cube);
    // Face 0's quarter turn maps (u, v) to (1 - v, u) and corner c to corner c + 1.
    const ExactParameter corners[4] = {{}, {Fraction{1, 1}, {}}, {Fraction{1, 1}, Fraction{1, 1}}, {{}, Fraction{1, 1}}};
    double u = 3e-6, v = 7e-5;
    const double expected = distance(surface.evaluate(0, u, v, 1e-15).point, surface.evaluate(0, corners[0]));
    for (int c = 1; c < 4; ++c) {
      const double turned = 1 - v;
      v = u, u = turned;
      INFO(scheme << " corner " << c << " at (" << u << ", " << v << ")");
      REQUIRE(distance(surface.evaluate(0, u, v, 1e-15).point, surface.evaluate(0, corners[c])) == Approx(expected).epsilon(1e-9));
    }
  }
}

TEST_CASE("nonpoly at parameters no stored rate holds agrees with exact tables within a tight bound", "[runtime][real]") {
  const auto tables = Tables::load(generated_table("nonpoly", "--valence 3-8 --n 24", "sgs").string());
  // The same scheme at rates that hold 1/29, 1/31 and 1/64 exactly.
  const auto exact = Tables::load(generated_table("nonpoly", "--valence 3-8 --n 29,31,32", "sgs").string());
  for (const char* name : {"cube", "torus-3-5", "chess-piece"}) {
    const Mesh mesh = bundled(name);
    const Surface surface = surface_of(tables, mesh), reference = surface_of(exact, mesh);
    const double size = extent(mesh);
    int checked_ratio = 0;
    for (std::size_t f = 0; f < mesh.face_count(); f += 5)
      for (const auto& [u, v] : {std::pair{Fraction{1, 29}, Fraction{3, 29}}, std::pair{Fraction{7, 29}, Fraction{0, 1}},
                                  std::pair{Fraction{20, 31}, Fraction{13, 31}}, std::pair{Fraction{1, 31}, Fraction{30, 31}}}) {
        const Point truth = reference.evaluate(f, ExactParameter{u, v});
        for (double tolerance : {1e-3, 1e-5, 1e-7, 1e-9}) {
          const Evaluation fraction = surface.evaluate(f, ExactParameter{u, v}, tolerance * size);
          const Evaluation real = surface.evaluate(f, u.to_double(), v.to_double(), tolerance * size);
          for (const Evaluation* e : {&fraction, &real}) {
            const double error = distance(e->point, truth);
            INFO(name << " face " << f << " at (" << u.str() << ", " << v.str() << "), tolerance " << tolerance << ": error "
                      << error / size << ", bound " << e->bound / size);
            REQUIRE_FALSE(e->exact);
            REQUIRE(e->bound <= tolerance * size);
            REQUIRE(error <= e->bound);
            if (error > 1e-13 * size) {  // above rounding: the bound is within 100 times the error
              REQUIRE(e->bound <= 100 * error);
              ++checked_ratio;
            }
          }
        }
      }
    INFO(name << ": " << checked_ratio << " ratio checks");
    REQUIRE(checked_ratio > 0);
  }
}

TEST_CASE("dyadic parameters the tables do not hold are reached exactly by subdivision", "[runtime][real]") {
  const auto tables = Tables::load(generated_table("nonpoly", "--valence 3-8 --n 24", "sgs").string());
  const auto exact = Tables::load(generated_table("nonpoly", "--valence 3-8 --n 29,31,32", "sgs").string());
  const Mesh mesh = bundled("torus-3-5");
  const Surface surface = surface_of(tables, mesh), reference = surface_of(exact, mesh);
  const double size = extent(mesh);
  for (std::size_t f = 0; f < mesh.face_count(); f += 7)
    for (const auto& [u, v] : {std::pair{Fraction{3, 64}, Fraction{17, 64}}, std::pair{Fraction{1, 64}, Fraction{63, 64}}}) {
      const Evaluation e = surface.evaluate(f, ExactParameter{u, v}, 0.0);
      const Evaluation d = surface.evaluate(f, u.to_double(), v.to_double(), 0.0);
      const Point truth = reference.evaluate(f, ExactParameter{u, v});
      INFO("face " << f << " at (" << u.str() << ", " << v.str() << ")");
      REQUIRE(e.exact);
      REQUIRE(d.exact);
      REQUIRE(distance(e.point, truth) / size < 1e-14);
      REQUIRE(distance(d.point, truth) / size < 1e-14);
    }
}

TEST_CASE("real parameters outside a face, or bad tolerances, are refused", "[runtime][real][errors]") {
  const auto tables = Tables::load(generated_table("nonpoly", "--valence 3-8 --n 24", "sgs").string());
  const Surface surface = surface_of(tables, bundled("cube"));
  CHECK_THROWS_WITH(surface.evaluate(0, 1.5, 0.5, 1e-9), Catch::Contains("lies outside face 0"));
  CHECK_THROWS_WITH(surface.evaluate(0, std::nan(""), 0.5, 1e-9), Catch::Contains("lies outside face 0"));
  // Every digit: a %f "(0.500000, -0.000000)" hid why the parameter was outside.
  CHECK_THROWS_WITH(surface.evaluate(0, 0.5, -1e-7, 1e-9), Catch::Contains("the parameter (0.5, -9.9999999999999995e-08) lies outside"));
  CHECK_THROWS_WITH(surface.evaluate(0, 0.5, 0.5, -1), Catch::Contains("tolerance"));
  CHECK_THROWS_WITH(surface.evaluate(9, 0.5, 0.5, 1e-9), Catch::Contains("face 9 does not exist"));
}
