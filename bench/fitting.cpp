// Benchmark: seed 003's ellipsoid test of PDM, TDM and SDM (issue "Fit
// subdivision surfaces to scanned points"). Points: 10,000 noisy samples of
// the ellipsoid with semi-axes 0.5, 0.35, 0.25 (in seed 003's unit box: the
// object scaled into [0,1]^3), Gaussian noise of 1e-4. Start: the bundled
// quad sphere (56 control points) scaled to radius 0.3; for a triangle scheme
// (Loop, sqrt(3)) its quads split along a diagonal (the same 56 points). For each method, the
// iterations and time until the max error is below 0.002 in the unit box
// (seed 003: SDM 8 iterations, TDM 12, PDM more than 100), at most 100
// iterations, no smoothing. One row per scheme (tables file) and method.
// Usage: bench_fitting TABLES.sgs [TABLES.sgs ...]
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "stencil_runtime/mesh_io.hpp"
#include "stencil_runtime/surface_fit.hpp"

using namespace stencil_runtime;

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: bench_fitting TABLES.sgs [TABLES.sgs ...]\n");
    return 1;
  }
  try {
    std::mt19937 rng(2004);
    std::normal_distribution<double> normal(0, 1);
    std::vector<Point> points;
    for (int i = 0; i < 10000; ++i) {
      const Point d{normal(rng), normal(rng), normal(rng)};
      const double l = std::hypot(d[0], d[1], d[2]);
      points.push_back({0.5 + 0.5 * d[0] / l + 1e-4 * normal(rng), 0.5 + 0.35 * d[1] / l + 1e-4 * normal(rng),
                        0.5 + 0.25 * d[2] / l + 1e-4 * normal(rng)});
    }
    const Mesh sphere = read_obj(std::string(STENCIL_SOURCE_DIR) + "/meshes/quad-sphere.obj");
    std::vector<Point> start = sphere.positions;
    for (Point& p : start) p = {0.5 + 0.3 * p[0], 0.5 + 0.3 * p[1], 0.5 + 0.3 * p[2]};
    std::printf("# seed 003's ellipsoid: %zu points, %zu control points, max error target 0.002 (unit box), no smoothing\n",
                points.size(), start.size());
    std::printf("%-14s %-6s %10s %10s %12s %12s %12s\n", "scheme", "method", "iterations", "seconds", "s/iteration",
                "max (box)", "rms (box)");
    for (int a = 1; a < argc; ++a) {
      const auto tables = Tables::load(argv[a]);
      Mesh control = sphere;
      if (tables->family() == SchemeFamily::Triangle) {
        control.face_sizes.clear(), control.face_vertices.clear();
        for (std::size_t f = 0; f < sphere.face_count(); ++f) {
          const int* q = &sphere.face_vertices[4 * f];
          control.face_sizes.insert(control.face_sizes.end(), {3, 3});
          control.face_vertices.insert(control.face_vertices.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
        }
      }
      const auto topology =
          SurfaceTopology::create(tables, control.vertex_count(), control.face_sizes, control.face_vertices);
      for (const FitMethod method : {FitMethod::SquaredDistance, FitMethod::TangentDistance, FitMethod::PointDistance}) {
        FitOptions options;
        options.method = method;
        options.iterations = 100;
        options.smoothing = 0;
        // The target in the fit's unit (the points' diagonal, about that of the 1 x 0.7 x 0.5 box).
        options.max_error = 0.002 / std::hypot(1.0, 0.7, 0.5);
        const FitResult fit = fit_surface(topology, start, points, options);
        const FitIteration& last = fit.history.back();
        const bool reached = last.max * fit.diagonal <= 0.002;
        std::printf("%-14s %-6s %9d%s %10.2f %12.3f %12.5f %12.6f\n", tables->scheme().c_str(), method_name(method),
                    last.iteration, reached ? " " : "+", last.seconds, last.seconds / std::max(1, last.iteration),
                    last.max * fit.diagonal, last.rms * fit.diagonal);
        std::fflush(stdout);
      }
    }
    std::printf("# +: the target was not reached within the iterations shown\n");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_fitting: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
