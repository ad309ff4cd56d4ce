// Fitting control positions to points (fit_at_samples, fit_surface) against
// independent data: points sampled from OpenSubdiv's Bfr limit surface of a
// known control mesh (Catmull-Clark), whose control points a fit must find
// again; errors recomputed by brute force on dense exact samples.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "bfr_reference.hpp"
#include "cli.hpp"
#include "runtime_api.hpp"
#include "stencil_runtime/closest_point.hpp"
#include "stencil_runtime/mesh_io.hpp"
#include "stencil_runtime/surface_fit.hpp"

using namespace stencil_runtime;
namespace osd = OpenSubdiv::OPENSUBDIV_VERSION;

namespace {

const std::filesystem::path kMeshes = std::filesystem::path(STENCIL_SOURCE_DIR) / "meshes";

double distance(const Point& a, const Point& b) { return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }

double diagonal_of(const std::vector<Point>& points) {
  Point lo = points[0], hi = lo;
  for (const Point& p : points)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  return distance(lo, hi);
}

double largest_difference(const std::vector<Point>& a, const std::vector<Point>& b) {
  double worst = 0;
  for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, distance(a[i], b[i]));
  return worst;
}

// `per_face` random samples on every face of a Catmull-Clark mesh, evaluated by Bfr.
struct BfrSamples {
  std::vector<RealSample> samples;
  std::vector<Point> points;
};

BfrSamples bfr_samples(const Mesh& mesh, int per_face, unsigned seed) {
  bfr_reference::BfrLimit limit(mesh.positions, mesh.face_sizes, mesh.face_vertices);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(0, 1);
  BfrSamples out;
  for (std::size_t f = 0; f < mesh.face_count(); ++f)
    for (int s = 0; s < per_face; ++s) {
      const double u = uniform(rng), v = uniform(rng);
      out.samples.push_back({f, u, v});
      out.points.push_back(limit.evaluate(static_cast<int>(f), u, v));
    }
  return out;
}

std::vector<Point> perturbed(const std::vector<Point>& control, double amount, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-amount, amount);
  std::vector<Point> out = control;
  for (Point& p : out)
    for (double& x : p) x += uniform(rng);
  return out;
}

}  // namespace

TEST_CASE("fit_at_samples recovers Catmull-Clark control points from Bfr's limit points at known parameters",
          "[fitting]") {
  const auto tables = Tables::load(generated_table("catmull-clark", "--valence 3-8 --n 8", "sgs").string());
  for (const char* name : {"chess-piece.obj", "torus-3-5.obj", "rook.obj"}) {
    INFO(name);
    const Mesh mesh = read_obj((kMeshes / name).string());
    const BfrSamples data = bfr_samples(mesh, 12, 7);
    const auto topology = test_runtime::topology_of(tables, mesh);
    const std::vector<Point> fitted = fit_at_samples(*topology, data.samples, data.points, 0);
    const double error = largest_difference(fitted, mesh.positions) / diagonal_of(mesh.positions);
    INFO("largest control-point error / diagonal " << error);
    CHECK(error < 1e-9);
  }
}

TEST_CASE("fit_surface: PDM, TDM and SDM from a perturbed control mesh", "[fitting]") {
  const auto tables = Tables::load(generated_table("catmull-clark", "--valence 3-8 --n 8", "sgs").string());
  const Mesh mesh = read_obj((kMeshes / "chess-piece.obj").string());
  const BfrSamples data = bfr_samples(mesh, 8, 11);
  const double diagonal = diagonal_of(mesh.positions);
  const auto topology = test_runtime::topology_of(tables, mesh);
  for (const FitMethod method : {FitMethod::PointDistance, FitMethod::TangentDistance, FitMethod::SquaredDistance}) {
    FitOptions options;
    options.method = method;
    options.iterations = 30;
    options.smoothing = 0;
    options.progress = [](const FitIteration& it) {
      std::printf("  %d rms %.3e max %.3e mu %.1e rejected %d %.2f s\n", it.iteration, it.rms, it.max, it.damping,
                  it.rejected, it.seconds);
    };
    std::printf("%s\n", method_name(method));
    const FitResult fit = fit_surface(topology, perturbed(mesh.positions, 0.01 * diagonal, 3), data.points, options);
    std::printf("control error %.3e\n", largest_difference(fit.control, mesh.positions) / diagonal);
  }
}

TEST_CASE("fit_surface on nonpoly", "[fitting]") {
  const auto tables = Tables::load(generated_table("nonpoly", "--valence 3-8 --n 8", "sgs").string());
  const Mesh mesh = read_obj((kMeshes / "chess-piece.obj").string());
  const auto topology = test_runtime::topology_of(tables, mesh);
  const Surface truth(topology, mesh.positions);
  std::vector<Point> points;
  for (std::size_t f = 0; f < mesh.face_count(); ++f)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i) points.push_back(truth.evaluate(f, test_runtime::grid(2 * i + 1, 2 * j + 1, 8)));
  const double diagonal = diagonal_of(mesh.positions);
  for (const FitMethod method : {FitMethod::PointDistance, FitMethod::TangentDistance, FitMethod::SquaredDistance}) {
    FitOptions options;
    options.method = method;
    options.iterations = 30;
    options.smoothing = 0;
    options.progress = [](const FitIteration& it) {
      std::printf("  %d rms %.3e max %.3e mu %.1e rejected %d %.2f s\n", it.iteration, it.rms, it.max, it.damping,
                  it.rejected, it.seconds);
    };
    std::printf("%s\n", method_name(method));
    const FitResult fit = fit_surface(topology, perturbed(mesh.positions, 0.01 * diagonal, 3), points, options);
    std::printf("control error %.3e\n", largest_difference(fit.control, mesh.positions) / diagonal);
  }
}
