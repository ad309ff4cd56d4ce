// Benchmark: the Stanford bunny from raw points to a fitted smooth surface
// (issue "Fit subdivision surfaces to scanned points"), beside seeds 003 and
// 002's figures. Points: the 37,706 vertices of bunny00.off from Debian's
// libcgal-demo (extracted at run time from
// /usr/share/doc/libcgal-dev/data.tar.gz; never committed), scaled uniformly
// into the unit box [0,1]^3 (seed 003's measure). Per scheme (tables file):
//   - the initial control mesh from the points (CGAL reconstruction and
//     simplification) with about 1,000 and about 8,000 vertices;
//   - SDM iterations (smoothing 1e-3 halving), each row: time since the start
//     (initial mesh included), max and RMS distance of the points to the
//     surface in the unit box and as a fraction of the diagonal;
//   - adaptive fitting (seed 002's route) from about 1,000 control points with
//     a budget of 8,440, to a max error of 0.048% of the diagonal.
// Then the initial mesh's time against the number of points (10k to 1M
// points sampled uniformly on the bunny's triangles; seed 004 claims linear).
// Usage: bench_bunny_fit TABLES.sgs [TABLES.sgs ...] (valences up to 12 or more);
//        bench_bunny_fit --initial-mesh-only (the growth table alone)
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "stencil_reconstruction/initial_mesh.hpp"
#include "stencil_runtime/surface_fit.hpp"

using namespace stencil_runtime;

namespace {

struct OffMesh {
  std::vector<Point> vertices;
  std::vector<std::array<int, 3>> triangles;
};

OffMesh read_bunny() {
  const std::string dir = "bench-data";
  const std::string path = dir + "/data/meshes/bunny00.off";
  if (!std::ifstream(path)) {
    const std::string command = "mkdir -p " + dir + " && tar xzf /usr/share/doc/libcgal-dev/data.tar.gz -C " + dir +
                                " data/meshes/bunny00.off";
    if (std::system(command.c_str()) != 0)
      throw std::runtime_error("cannot extract bunny00.off (install libcgal-demo: scripts/install-deps.sh)");
  }
  std::ifstream in(path);
  std::string header;
  std::size_t v = 0, f = 0, e = 0;
  in >> header >> v >> f >> e;
  if (header != "OFF" || v == 0 || v > 10000000 || f > 20000000) throw std::runtime_error(path + ": unexpected header");
  OffMesh mesh;
  mesh.vertices.resize(v);
  for (Point& p : mesh.vertices) in >> p[0] >> p[1] >> p[2];
  for (std::size_t i = 0; i < f; ++i) {
    int n = 0;
    std::array<int, 3> t{};
    in >> n >> t[0] >> t[1] >> t[2];
    if (n != 3 || !in) throw std::runtime_error(path + ": a face that is not a triangle");
    mesh.triangles.push_back(t);
  }
  return mesh;
}

// Uniform scaling into [0,1]^3 (seed 003's normalisation).
void to_unit_box(std::vector<Point>& points) {
  Point lo = points[0], hi = lo;
  for (const Point& p : points)
    for (int c = 0; c < 3; ++c) lo[c] = std::min(lo[c], p[c]), hi[c] = std::max(hi[c], p[c]);
  const double side = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  for (Point& p : points)
    for (int c = 0; c < 3; ++c) p[c] = (p[c] - lo[c]) / side;
}

std::vector<Point> sample_triangles(const OffMesh& mesh, std::size_t count, unsigned seed) {
  std::vector<double> area(mesh.triangles.size());
  double total = 0;
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const Point &a = mesh.vertices[mesh.triangles[i][0]], &b = mesh.vertices[mesh.triangles[i][1]],
                &c = mesh.vertices[mesh.triangles[i][2]];
    const Point u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    total += 0.5 * std::hypot(u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]);
    area[i] = total;
  }
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uniform(0, 1);
  std::vector<Point> points;
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t i = std::lower_bound(area.begin(), area.end(), uniform(rng) * total) - area.begin();
    double s = uniform(rng), t = uniform(rng);
    if (s + t > 1) s = 1 - s, t = 1 - t;
    const auto& tri = mesh.triangles[std::min(i, mesh.triangles.size() - 1)];
    const Point &a = mesh.vertices[tri[0]], &b = mesh.vertices[tri[1]], &c = mesh.vertices[tri[2]];
    points.push_back({a[0] + s * (b[0] - a[0]) + t * (c[0] - a[0]), a[1] + s * (b[1] - a[1]) + t * (c[1] - a[1]),
                      a[2] + s * (b[2] - a[2]) + t * (c[2] - a[2])});
  }
  return points;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: bench_bunny_fit TABLES.sgs [TABLES.sgs ...] | --initial-mesh-only\n");
    return 1;
  }
  const bool fits = std::string(argv[1]) != "--initial-mesh-only";
  if (!fits) argc = 1;
  try {
    const OffMesh bunny = read_bunny();
    std::vector<Point> points = bunny.vertices;
    to_unit_box(points);
    std::printf("# bunny00.off: %zu points in the unit box; SDM, smoothing 1e-3 halving; all threads\n", points.size());
    std::printf("# targets: seed 003 max 0.0082, RMS 0.0009 (unit box) with ~1,000 control points in 20 s;\n"
                "#          seed 002 max 0.048%% of the diagonal with at most 8,440 control points in 60 s\n");
    std::printf("%-14s %8s %5s %9s %11s %11s %11s %11s\n", "scheme", "control", "iter", "seconds", "max(box)",
                "rms(box)", "max/diag", "rms/diag");
    for (int a = 1; a < argc; ++a) {
      const auto tables = Tables::load(argv[a]);
      for (const std::size_t wanted : {std::size_t{1000}, std::size_t{8000}}) {
        const auto start = std::chrono::steady_clock::now();
        stencil_reconstruction::InitialMeshOptions initial;
        initial.control_points = wanted;
        const Mesh mesh = stencil_reconstruction::initial_control_mesh(points, initial);
        const double initial_seconds = seconds_since(start);
        const auto topology = SurfaceTopology::create(tables, mesh.vertex_count(), mesh.face_sizes, mesh.face_vertices);
        FitOptions options;
        options.iterations = 10;
        options.tolerance = 1e-7;
        const FitResult fit = fit_surface(topology, mesh.positions, points, options);
        for (const FitIteration& it : fit.history)
          std::printf("%-14s %8zu %5d %9.2f %11.5f %11.5f %10.4f%% %10.4f%%\n", tables->scheme().c_str(),
                      mesh.vertex_count(), it.iteration, initial_seconds + it.seconds, it.max * fit.diagonal,
                      it.rms * fit.diagonal, 100 * it.max, 100 * it.rms);
        std::printf("# initial mesh %.2f s\n", initial_seconds);
        std::fflush(stdout);
      }
    }
    if (fits)
      std::printf("# adaptive (seed 002's route): from ~1,000 control points, red-green refinement of the faces above half\n"
                "# of max error 0.048%% of the diagonal, budget 8,440, 3 SDM iterations per round\n");
    for (int a = 1; a < argc; ++a) {
      const auto tables = Tables::load(argv[a]);
      const auto start = std::chrono::steady_clock::now();
      stencil_reconstruction::InitialMeshOptions initial;
      initial.control_points = 1000;
      const Mesh mesh = stencil_reconstruction::initial_control_mesh(points, initial);
      const double initial_seconds = seconds_since(start);
      FitOptions options;
      options.iterations = 3;
      options.tolerance = 1e-7;
      options.max_error = 0.00048;
      const AdaptiveFit fit = fit_adaptively(tables, mesh, points, options, 8440);
      for (const FitIteration& it : fit.fit.history)
        std::printf("%-14s %8zu %5d %9.2f %11.5f %11.5f %10.4f%% %10.4f%%\n", tables->scheme().c_str(),
                    it.control_points, it.iteration, initial_seconds + it.seconds, it.max * fit.fit.diagonal,
                    it.rms * fit.fit.diagonal, 100 * it.max, 100 * it.rms);
      std::printf("# %d refinement rounds, %zu control points, initial mesh %.2f s\n", fit.rounds,
                  fit.mesh.vertex_count(), initial_seconds);
      std::fflush(stdout);
    }
    std::printf("# the initial mesh (1,000 vertices) against the number of points sampled on the bunny's triangles\n");
    std::printf("%10s %10s %12s %12s %12s %12s\n", "points", "used", "total s", "reconstruct", "repair", "simplify");
    for (const std::size_t count :
         {std::size_t{10000}, std::size_t{30000}, std::size_t{100000}, std::size_t{300000}, std::size_t{1000000}}) {
      const std::vector<Point> sample = sample_triangles(bunny, count, 7);
      stencil_reconstruction::InitialMeshOptions initial;
      initial.control_points = 1000;
      stencil_reconstruction::InitialMeshReport report;
      const auto start = std::chrono::steady_clock::now();
      stencil_reconstruction::initial_control_mesh(sample, initial, &report);
      std::printf("%10zu %10zu %12.2f %12.2f %12.2f %12.2f\n", count, report.points_used, seconds_since(start),
                  report.reconstruction_seconds, report.repair_seconds, report.simplification_seconds);
      std::fflush(stdout);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_bunny_fit: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
