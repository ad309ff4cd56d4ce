// The initial control mesh from points alone (seed 004's step through CGAL),
// checked on points sampled from a known closed surface: the result is a
// closed, consistently and outward oriented mesh the runtime accepts, of the
// requested size, whose vertices lie near the points (within 5% of their
// diagonal, by brute force: simplification places vertices off them), and
// fitting from it approaches the points.
#include <catch2/catch.hpp>
#include <tuple>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>

#include "cli.hpp"
#include "runtime_api.hpp"
#include "stencil_reconstruction/initial_mesh.hpp"
#include "stencil_runtime/mesh_io.hpp"
#include "stencil_runtime/surface_fit.hpp"

using namespace stencil_runtime;
using stencil_reconstruction::InitialMeshOptions;
using stencil_reconstruction::ReconstructionError;

namespace {

const std::filesystem::path kMeshes = std::filesystem::path(STENCIL_SOURCE_DIR) / "meshes";

// Exact limit points of the chess piece at the cell centres of a k x k grid on every face.
std::vector<Point> chess_piece_points(int k) {
  const auto tables = Tables::load(generated_table("catmull-clark", "--valence 3-8 --n 8", "sgs").string());
  const Mesh mesh = read_obj((kMeshes / "chess-piece.obj").string());
  const Surface surface = test_runtime::surface_of(tables, mesh);
  std::vector<Point> points;
  for (std::size_t f = 0; f < mesh.face_count(); ++f)
    for (int j = 0; j < k; ++j)
      for (int i = 0; i < k; ++i) points.push_back(surface.evaluate(f, test_runtime::grid(2 * i + 1, 2 * j + 1, 2 * k)));
  return points;
}

double diagonal_of(const std::vector<Point>& points) {
  Point lo = points[0], hi = lo;
  for (const Point& p : points)
    for (int c = 0; c < 3; ++c) lo[c] = std::min(lo[c], p[c]), hi[c] = std::max(hi[c], p[c]);
  return std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
}

// The enclosed volume by the divergence theorem (fan triangulation of each face):
// positive for outward-oriented faces.
double signed_volume(const Mesh& mesh) {
  double volume = 0;
  std::size_t offset = 0;
  for (const int size : mesh.face_sizes) {
    const Point& a = mesh.positions[static_cast<std::size_t>(mesh.face_vertices[offset])];
    for (int c = 1; c + 1 < size; ++c) {
      const Point& b = mesh.positions[static_cast<std::size_t>(mesh.face_vertices[offset + static_cast<std::size_t>(c)])];
      const Point& d = mesh.positions[static_cast<std::size_t>(mesh.face_vertices[offset + static_cast<std::size_t>(c) + 1])];
      volume += (a[0] * (b[1] * d[2] - b[2] * d[1]) - a[1] * (b[0] * d[2] - b[2] * d[0]) + a[2] * (b[0] * d[1] - b[1] * d[0])) / 6;
    }
    offset += static_cast<std::size_t>(size);
  }
  return volume;
}

}  // namespace

TEST_CASE("The initial mesh from points is closed, outward, of the requested size and near the points", "[fitting]") {
  const std::vector<Point> points = chess_piece_points(6);  // 8,064 points
  const double diagonal = diagonal_of(points);
  for (const std::size_t wanted : {std::size_t{60}, std::size_t{300}}) {
    INFO(wanted << " control points");
    InitialMeshOptions options;
    options.control_points = wanted;
    const Mesh mesh = stencil_reconstruction::initial_control_mesh(points, options);
    CHECK(mesh.vertex_count() == wanted);  // exactly: "--control-points N" gave N - 1 until the stop count was mended
    // Closed, manifold, consistently oriented: the runtime's own checks.
    const auto tables = Tables::load(generated_table("catmull-clark", "--valence 3-16 --n 4", "sgs").string());
    CHECK_NOTHROW(SurfaceTopology::create(tables, mesh.vertex_count(), mesh.face_sizes, mesh.face_vertices));
    CHECK(signed_volume(mesh) > 0);
    // Every vertex near the points (nearest point by brute force).
    double farthest = 0;
    for (const Point& v : mesh.positions) {
      double nearest = INFINITY;
      for (const Point& p : points) nearest = std::min(nearest, std::hypot(v[0] - p[0], v[1] - p[1], v[2] - p[2]));
      farthest = std::max(farthest, nearest);
    }
    CHECK(farthest < 0.05 * diagonal);
  }
}

TEST_CASE("A large scan is reduced to a subset before the reconstruction, and still gives a closed mesh", "[fitting]") {
  const std::vector<Point> points = chess_piece_points(6);
  InitialMeshOptions options;
  options.control_points = 100;
  options.max_points_per_control_point = 20;
  options.min_points = 1000;
  stencil_reconstruction::InitialMeshReport report;
  const Mesh mesh = stencil_reconstruction::initial_control_mesh(points, options, &report);
  CHECK(report.points_used == 2000);
  CHECK(mesh.vertex_count() >= 98);
  CHECK(mesh.vertex_count() <= 100);
  CHECK(signed_volume(mesh) > 0);
  const auto tables = Tables::load(generated_table("catmull-clark", "--valence 3-16 --n 4", "sgs").string());
  CHECK_NOTHROW(SurfaceTopology::create(tables, mesh.vertex_count(), mesh.face_sizes, mesh.face_vertices));
}

TEST_CASE("stencilfit from raw points: initial mesh, then a fit that approaches the points", "[fitting][cli]") {
  const auto dir = scratch_dir("stencilfit-raw");
  {
    std::ofstream out(dir / "points.xyz");
    out.precision(17);
    for (const Point& p : chess_piece_points(4)) out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  }
  // Every scheme: the quad ones through their polygon step, the triangle ones on the triangle mesh itself.
  // sqrt(3) runs one iteration: its closest points take differences of
  // approximate evaluations (no derivative stencils), some 20 times slower.
  for (const auto& [scheme, options, extension, iterations] :
       std::vector<std::tuple<const char*, const char*, const char*, int>>{{"catmull-clark", "--valence 3-16 --n 4", "sgs", 4},
                                                                           {"loop", "--valence 3-16 --n 4", "sgt", 4},
                                                                           {"sqrt3", "--valence 3-16 --n 1,3,9", "sgt", 1}}) {
    CAPTURE(scheme);
    const std::string tables = generated_table(scheme, options, extension).string();
    const auto report_path = dir / (std::string(scheme) + ".json");
    const CliResult r = run_stencilfit("--tables " + tables + " --points " + (dir / "points.xyz").string() +
                                       " --control-points 200 --iterations " + std::to_string(iterations) + " --out " +
                                       (dir / "fit.obj").string() +
                                       " --report " + report_path.string());
    INFO(r.output);
    REQUIRE(r.status == 0);
    CHECK_THAT(r.output, Catch::Contains("initial mesh: simplifying"));
    const Mesh fitted = read_obj((dir / "fit.obj").string());
    CHECK(fitted.vertex_count() <= 200);
    CHECK(fitted.vertex_count() >= 198);
    // The report's last max error, against the first: the fit moved the surface onto the points.
    std::ifstream report(report_path);
    const nlohmann::json json = nlohmann::json::parse(report);
    const auto& history = json["iterations"];
    REQUIRE(history.size() == static_cast<std::size_t>(iterations) + 1);
    CHECK(history.back()["max"].get<double>() < 0.75 * history.front()["max"].get<double>());
    CHECK(history.back()["rms"].get<double>() < 0.75 * history.front()["rms"].get<double>());
  }
}

TEST_CASE("The initial mesh refuses what cannot make a surface", "[fitting]") {
  const std::vector<Point> points = chess_piece_points(2);
  InitialMeshOptions options;
  options.control_points = 3;
  CHECK_THROWS_WITH(stencil_reconstruction::initial_control_mesh(points, options), Catch::Contains("at least 4 control points"));
  options.control_points = 100;
  CHECK_THROWS_WITH(stencil_reconstruction::initial_control_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, options),
                    Catch::Contains("at least 4 points"));
  options.control_points = points.size() + 1;
  CHECK_THROWS_WITH(stencil_reconstruction::initial_control_mesh(points, options), Catch::Contains("fewer than the"));
  std::vector<Point> bad = points;
  bad[5][2] = INFINITY;
  options.control_points = 50;
  CHECK_THROWS_WITH(stencil_reconstruction::initial_control_mesh(bad, options), Catch::Contains("point 5"));
  CHECK_THROWS_WITH(stencil_reconstruction::initial_control_mesh(std::vector<Point>(10, Point{1, 1, 1}), options),
                    Catch::Contains("coplanar"));
  std::vector<Point> flat;
  for (int i = 0; i < 100; ++i) flat.push_back({std::cos(i * 0.1), std::sin(i * 0.3), 0});
  CHECK_THROWS_WITH(stencil_reconstruction::initial_control_mesh(flat, options), Catch::Contains("coplanar"));
}
