// Limit points as sparse rows over the original control vertices (the
// refinement matrix of the preparation folded in): rows times the control
// positions equal the evaluated points on every bundled mesh, every row sums
// to 1, and for Catmull-Clark and Loop every row equals OpenSubdiv Bfr's limit
// stencil over the same control vertices.
#include <catch2/catch.hpp>
#include <filesystem>
#include <map>
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

namespace {

// Grid samples of every face (every `step`-th face), in each face's domain.
std::vector<Sample> samples_of(const SurfaceTopology& topology, std::size_t step) {
  std::vector<Sample> out;
  const std::vector<long> rates = topology.tables().has_rate(4) ? std::vector<long>{1, 3, 4} : std::vector<long>{1, 3, 9};
  for (std::size_t f = 0; f < topology.face_count(); f += step) {
    const FaceDomain d = topology.domain(f);
    for (long n : rates)
      for (long j = 0; j <= n; ++j)
        for (long i = 0; i <= n; ++i) {
          if (d.kind == FaceDomain::Kind::Triangle && i + j > n) continue;
          if (d.kind == FaceDomain::Kind::QuadSubfaces)  // the first sub-face's tile
            out.push_back({f, {Fraction::make(i, 2 * n), Fraction::make(j, 2 * n)}});
          else
            out.push_back({f, grid(i, j, n)});
        }
  }
  return out;
}

// rows * control == evaluate, and every row sums to 1.
void check_rows_evaluate(const std::shared_ptr<const Tables>& tables, const Mesh& mesh, std::size_t step) {
  const Surface surface = surface_of(tables, mesh);
  const std::vector<Sample> samples = samples_of(surface.topology(), step);
  const StencilRows rows = surface.topology().stencils(samples);
  REQUIRE(rows.rows() == samples.size());
  REQUIRE(rows.columns == mesh.vertex_count());
  const std::vector<Point> points = rows.apply(mesh.positions);
  const double size = extent(mesh);
  for (std::size_t k = 0; k < samples.size(); ++k) {
    INFO(tables->scheme() << " face " << samples[k].face << " at " << samples[k].at.str());
    REQUIRE(distance(points[k], surface.evaluate(samples[k].face, samples[k].at)) / size < 1e-13);
    double sum = 0;
    for (std::size_t e = rows.offsets[k]; e < rows.offsets[k + 1]; ++e) {
      REQUIRE(rows.vertices[e] < mesh.vertex_count());
      if (e > rows.offsets[k]) REQUIRE(rows.vertices[e - 1] < rows.vertices[e]);
      sum += rows.weights[e];
    }
    REQUIRE(sum == Approx(1.0).margin(1e-13));
  }
}

// Each row equals Bfr's stencil over the control vertices.
void check_rows_bfr(const std::shared_ptr<const Tables>& tables, const Mesh& mesh, OpenSubdiv::Sdc::SchemeType scheme,
                    std::size_t step) {
  const auto topology = topology_of(tables, mesh);
  const std::vector<Sample> samples = samples_of(*topology, step);
  const StencilRows rows = topology->stencils(samples);
  bfr_reference::BfrLimit reference(mesh.positions, mesh.face_sizes, mesh.face_vertices, scheme);
  double worst = 0;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    std::map<int, double> theirs =
        reference.stencil(static_cast<int>(samples[k].face), samples[k].at.u.to_double(), samples[k].at.v.to_double());
    for (std::size_t e = rows.offsets[k]; e < rows.offsets[k + 1]; ++e) theirs[static_cast<int>(rows.vertices[e])] -= rows.weights[e];
    for (const auto& [vertex, difference] : theirs) {
      worst = std::max(worst, std::abs(difference));
      INFO(tables->scheme() << " face " << samples[k].face << " at " << samples[k].at.str() << ", vertex " << vertex);
      REQUIRE(std::abs(difference) < 1e-12);
    }
  }
  INFO("largest weight difference " << worst);
  SUCCEED();
}


}  // namespace

TEST_CASE("stencil rows over the control vertices reproduce the evaluated points", "[runtime][stencils]") {
  const auto nonpoly = Tables::load(generated_table("nonpoly", "--valence 3-8 --n 24", "sgs").string());
  const auto sqrt3 = Tables::load(generated_table("sqrt3", "--valence 3-8 --n 1,3,9,27", "sgt").string());
  for (const char* name : {"cube", "torus-3-5", "chess-piece", "bumpy-sphere"}) check_rows_evaluate(nonpoly, bundled(name), 3);
  check_rows_evaluate(nonpoly, prism(), 1);
  for (const char* name : {"icosahedron", "tri-torus", "tri-mix"}) check_rows_evaluate(sqrt3, bundled(name), 3);
}

TEST_CASE("Catmull-Clark and Loop stencil rows equal OpenSubdiv's over the same control vertices", "[runtime][stencils][opensubdiv]") {
  const auto cc = Tables::load(generated_table("catmull-clark", "--valence 3-8 --n 24", "sgs").string());
  const auto loop = Tables::load(generated_table("loop", "--valence 3-8 --n 24", "sgt").string());
  for (const char* name : {"cube", "torus-3-5", "chess-piece", "bumpy-sphere"})
    check_rows_bfr(cc, bundled(name), OpenSubdiv::Sdc::SCHEME_CATMARK, 5);
  check_rows_bfr(cc, prism(), OpenSubdiv::Sdc::SCHEME_CATMARK, 1);
  for (const char* name : {"icosahedron", "tri-torus", "tri-mix"})
    check_rows_bfr(loop, bundled(name), OpenSubdiv::Sdc::SCHEME_LOOP, 2);
}

namespace {

// Random real parameters of every `step`-th face, near its corners too, in each face's domain.
std::vector<RealSample> real_samples_of(const SurfaceTopology& topology, std::size_t step, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<RealSample> out;
  for (std::size_t f = 0; f < topology.face_count(); f += step) {
    const FaceDomain d = topology.domain(f);
    for (int k = 0; k < 4; ++k) {
      double u = k == 1 ? 0.002 + 1e-3 * unit(rng) : unit(rng), v = k == 1 ? 0.001 * unit(rng) : unit(rng);
      if (k == 3) u = 1.0 / 29, v = 0.3;
      if (d.kind == FaceDomain::Kind::Triangle && u + v > 1) u = 1 - u, v = 1 - v;
      if (d.kind == FaceDomain::Kind::QuadSubfaces) u /= 2, v /= 2;  // the first sub-face's tile
      out.push_back({f, u, v});
    }
  }
  return out;
}

// Rows at real parameters equal Bfr's stencils there, and times the control points Surface::evaluate.
void check_real_rows(const std::shared_ptr<const Tables>& tables, const Mesh& mesh, OpenSubdiv::Sdc::SchemeType scheme,
                     std::size_t step) {
  const Surface surface = surface_of(tables, mesh);
  const std::vector<RealSample> samples = real_samples_of(surface.topology(), step, 7);
  const StencilRows rows = surface.topology().stencils(samples);
  REQUIRE(rows.rows() == samples.size());
  const std::vector<Point> points = rows.apply(mesh.positions);
  bfr_reference::BfrLimit reference(mesh.positions, mesh.face_sizes, mesh.face_vertices, scheme);
  const double size = extent(mesh);
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const auto& [f, u, v] = samples[k];
    INFO(tables->scheme() << " face " << f << " at (" << u << ", " << v << ")");
    const Evaluation e = surface.evaluate(f, u, v, 0.0);
    REQUIRE(e.exact);
    REQUIRE(distance(points[k], e.point) / size < 1e-13);
    std::map<int, double> theirs = reference.stencil(static_cast<int>(f), u, v);
    for (std::size_t e2 = rows.offsets[k]; e2 < rows.offsets[k + 1]; ++e2) theirs[static_cast<int>(rows.vertices[e2])] -= rows.weights[e2];
    for (const auto& [vertex, difference] : theirs) {
      INFO("vertex " << vertex);
      REQUIRE(std::abs(difference) < 1e-12);
    }
  }
}

}  // namespace

TEST_CASE("stencil rows at real parameters: Catmull-Clark and Loop equal OpenSubdiv's, and reproduce the evaluated points",
          "[runtime][stencils][real][opensubdiv]") {
  const auto cc = Tables::load(generated_table("catmull-clark", "--valence 3-8 --n 24", "sgs").string());
  const auto loop = Tables::load(generated_table("loop", "--valence 3-8 --n 24", "sgt").string());
  for (const char* name : {"cube", "torus-3-5", "chess-piece", "bumpy-sphere"})
    check_real_rows(cc, bundled(name), OpenSubdiv::Sdc::SCHEME_CATMARK, 5);
  check_real_rows(cc, prism(), OpenSubdiv::Sdc::SCHEME_CATMARK, 1);
  for (const char* name : {"icosahedron", "tri-torus", "tri-mix"})
    check_real_rows(loop, bundled(name), OpenSubdiv::Sdc::SCHEME_LOOP, 2);
}

TEST_CASE("non-polynomial schemes give rows where the descent is exact, and say why not between their grids",
          "[runtime][stencils][real]") {
  const auto nonpoly = Tables::load(generated_table("nonpoly", "--valence 3-8 --n 24", "sgs").string());
  const auto exact = Tables::load(generated_table("nonpoly", "--valence 3-8 --n 64-64", "sgs").string());
  const Mesh mesh = bundled("torus-3-5");
  const Surface surface = surface_of(nonpoly, mesh), reference = surface_of(exact, mesh);
  const double size = extent(mesh);
  for (std::size_t f = 0; f < mesh.face_count(); f += 7) {
    // 3/128 (3/64 on the prepared mesh's child face) is reached by the
    // descent: its row needs no rate-64 table.
    const ExactParameter at{Fraction{3, 128}, Fraction{17, 128}};
    const StencilRows rows = surface.topology().stencil(f, at);
    const Point truth = reference.evaluate(f, at);
    REQUIRE(distance(rows.apply(mesh.positions)[0], truth) / size < 1e-13);
    REQUIRE(distance(surface.topology().stencil(f, 3.0 / 128, 17.0 / 128).apply(mesh.positions)[0], truth) / size < 1e-13);
  }
  // A double is an exact binary fraction, reached within its binary digits
  // (0.3 has 54); one whose denominator needs more than 62 bits is not.
  REQUIRE(surface.topology().stencil(0, 0.3, 1.0 / 29).rows() == 1);
  CHECK_THROWS_WITH(surface.topology().stencil(0, 0.3, 1e-25), Catch::Contains("has no exact row"));
  CHECK_THROWS_WITH(surface.topology().stencil(0, ExactParameter{Fraction{1, 29}, Fraction{0, 1}}),
                    Catch::Contains("is on no grid the tables hold"));
}
