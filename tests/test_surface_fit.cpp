// Fitting control positions to points (fit_at_samples, fit_surface) against
// independent data: points sampled from OpenSubdiv's Bfr limit surface of a
// known control mesh (Catmull-Clark), whose control points a fit must find
// again; errors recomputed by brute force on Bfr (dense samples polished by
// Gauss-Newton). Nonpoly's data are its limit points at table nodes, evaluated
// by table look-up (Surface::evaluate), not by the rows the fit uses.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <map>
#include <nlohmann/json.hpp>
#include <random>

#include "bfr_distance.hpp"
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

BfrSamples bfr_samples(const Mesh& mesh, int per_face, unsigned seed, osd::Sdc::SchemeType scheme = osd::Sdc::SCHEME_CATMARK) {
  bfr_reference::BfrLimit limit(mesh.positions, mesh.face_sizes, mesh.face_vertices, scheme);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(0, 1);
  BfrSamples out;
  for (std::size_t f = 0; f < mesh.face_count(); ++f)
    for (int s = 0; s < per_face; ++s) {
      double u = uniform(rng), v = uniform(rng);
      if (scheme == osd::Sdc::SCHEME_LOOP && u + v > 1) u = 1 - u, v = 1 - v;  // Loop's triangle u + v <= 1
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

TEST_CASE("a control vertex in no face is refused by the fits, naming it (it has no part in the surface)", "[fitting]") {
  const auto tables = Tables::load(generated_table("catmull-clark", "--valence 3-8 --n 8", "sgs").string());
  Mesh mesh = read_obj((kMeshes / "cube.obj").string());
  mesh.positions.push_back({5, 5, 5});  // vertex 8, in no face: evaluated meshes ignore it
  const auto topology = test_runtime::topology_of(tables, mesh);
  const Surface surface(topology, mesh.positions);
  const std::vector<Point> points{surface.evaluate(0, test_runtime::grid(1, 1, 2)), surface.evaluate(1, test_runtime::grid(1, 1, 2))};
  const std::vector<RealSample> samples{{0, 0.5, 0.5}, {1, 0.5, 0.5}};
  try {
    fit_at_samples(*topology, samples, points, 0);
    FAIL("fitted a control vertex in no face");
  } catch (const FitError& e) {
    CHECK(std::string(e.what()).find("control vertex 8 ") != std::string::npos);
  }
  CHECK_THROWS_AS(fit_surface(topology, mesh.positions, points, FitOptions{}), FitError);
}

TEST_CASE("fit_at_samples recovers Loop control points from Bfr's limit points at known parameters", "[fitting]") {
  const auto tables = Tables::load(generated_table("loop", "--valence 3-8 --n 8", "sgt").string());
  for (const char* name : {"icosahedron.obj", "tri-torus.obj", "tri-mix.obj"}) {
    INFO(name);
    const Mesh mesh = read_obj((kMeshes / name).string());
    const BfrSamples data = bfr_samples(mesh, 12, 7, osd::Sdc::SCHEME_LOOP);
    const auto topology = test_runtime::topology_of(tables, mesh);
    const std::vector<Point> fitted = fit_at_samples(*topology, data.samples, data.points, 0);
    const double error = largest_difference(fitted, mesh.positions) / diagonal_of(mesh.positions);
    INFO("largest control-point error / diagonal " << error);
    CHECK(error < 1e-9);
  }
}

namespace {

// A quad sphere: the cube's faces split k x k, projected onto the unit sphere.
Mesh quad_sphere(int k) {
  Mesh mesh;
  std::map<std::array<long, 3>, int> index;
  auto vertex = [&](std::array<double, 3> p) {
    const std::array<long, 3> key{std::lround(p[0] * 1e6), std::lround(p[1] * 1e6), std::lround(p[2] * 1e6)};
    auto [it, fresh] = index.emplace(key, static_cast<int>(mesh.positions.size()));
    if (fresh) {
      const double l = std::hypot(p[0], p[1], p[2]);
      mesh.positions.push_back({p[0] / l, p[1] / l, p[2] / l});
    }
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int side = -1; side <= 1; side += 2)
      for (int j = 0; j < k; ++j)
        for (int i = 0; i < k; ++i) {
          int corners[4];
          const int di[4] = {0, 1, 1, 0}, dj[4] = {0, 0, 1, 1};
          for (int c = 0; c < 4; ++c) {
            const double s = -1 + 2.0 * (i + di[c]) / k, t = -1 + 2.0 * (j + dj[c]) / k;
            std::array<double, 3> p{};
            p[axis] = side;
            p[(axis + 1) % 3] = s;
            p[(axis + 2) % 3] = t;
            corners[c] = vertex(p);
          }
          // Counter-clockwise seen from outside.
          mesh.face_sizes.push_back(4);
          if (side > 0) mesh.face_vertices.insert(mesh.face_vertices.end(), {corners[0], corners[1], corners[2], corners[3]});
          else mesh.face_vertices.insert(mesh.face_vertices.end(), {corners[0], corners[3], corners[2], corners[1]});
        }
  return mesh;
}

}  // namespace


namespace {

// Noisy points on the ellipsoid with semi-axes 1, 0.7, 0.5 (seed 003's test shape).
std::vector<Point> ellipsoid_points(int count, double noise, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0, 1);
  std::vector<Point> points;
  for (int i = 0; i < count; ++i) {
    const Point d{normal(rng), normal(rng), normal(rng)};
    const double l = std::hypot(d[0], d[1], d[2]);
    points.push_back({d[0] / l + noise * normal(rng), 0.7 * d[1] / l + noise * normal(rng),
                      0.5 * d[2] / l + noise * normal(rng)});
  }
  return points;
}

std::vector<Point> scaled(std::vector<Point> points, double s) {
  for (Point& p : points) p = {s * p[0], s * p[1], s * p[2]};
  return points;
}

// Exact limit points of a surface at the cell centres of a 4 x 4 grid on every
// quad face, or at the nodes (i/9, j/9) inside every triangle face.
std::vector<Point> grid_points(const Surface& surface) {
  std::vector<Point> points;
  const bool triangles = surface.topology().tables().family() == SchemeFamily::Triangle;
  for (std::size_t f = 0; f < surface.topology().face_count(); ++f)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i) {
        if (!triangles) points.push_back(surface.evaluate(f, test_runtime::grid(2 * i + 1, 2 * j + 1, 8)));
        else if (i + j <= 3) points.push_back(surface.evaluate(f, test_runtime::grid(2 * i + 1, 2 * j + 1, 9)));
      }
  return points;
}

}  // namespace

TEST_CASE("fit_at_samples recovers nonpoly control points from its limit points at table nodes", "[fitting]") {
  const auto tables = Tables::load(generated_table("nonpoly", "--valence 3-8 --n 8", "sgs").string());
  const Mesh mesh = read_obj((kMeshes / "chess-piece.obj").string());
  const auto topology = test_runtime::topology_of(tables, mesh);
  const std::vector<Point> points = grid_points(Surface(topology, mesh.positions));
  std::vector<RealSample> samples;
  for (std::size_t f = 0; f < mesh.face_count(); ++f)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i) samples.push_back({f, (2 * i + 1) / 8.0, (2 * j + 1) / 8.0});
  const std::vector<Point> fitted = fit_at_samples(*topology, samples, points, 0);
  CHECK(largest_difference(fitted, mesh.positions) / diagonal_of(mesh.positions) < 1e-9);
}

TEST_CASE("SDM recovers the control points of the surface the points lie on, from a perturbed control mesh",
          "[fitting]") {
  const Mesh mesh = read_obj((kMeshes / "chess-piece.obj").string());
  const double diagonal = diagonal_of(mesh.positions);
  FitOptions options;
  options.method = FitMethod::SquaredDistance;
  options.iterations = 20;
  options.smoothing = 0;
  const std::vector<Point> start = perturbed(mesh.positions, 0.01 * diagonal, 3);
  SECTION("Catmull-Clark, points from Bfr at random parameters") {
    const auto tables = Tables::load(generated_table("catmull-clark", "--valence 3-8 --n 8", "sgs").string());
    const BfrSamples data = bfr_samples(mesh, 8, 11);
    const FitResult fit = fit_surface(test_runtime::topology_of(tables, mesh), start, data.points, options);
    CHECK(fit.history.front().max > 1e-3);
    CHECK(largest_difference(fit.control, mesh.positions) / diagonal < 1e-6);
    // The warm start: once the feet settle on their faces the matrix keeps its
    // pattern, and the symbolic analysis is reused.
    INFO(fit.factorizations << " factorisations, " << fit.symbolic_analyses << " symbolic analyses");
    CHECK(fit.factorizations >= 10);
    CHECK(fit.symbolic_analyses >= 1);
    CHECK(fit.symbolic_analyses * 2 < fit.factorizations);
  }
  SECTION("Loop, points from Bfr at random parameters") {
    const Mesh tri = read_obj((kMeshes / "tri-mix.obj").string());
    const double tri_diagonal = diagonal_of(tri.positions);
    const auto tables = Tables::load(generated_table("loop", "--valence 3-8 --n 8", "sgt").string());
    const BfrSamples data = bfr_samples(tri, 8, 11, osd::Sdc::SCHEME_LOOP);
    const FitResult fit = fit_surface(test_runtime::topology_of(tables, tri), perturbed(tri.positions, 0.01 * tri_diagonal, 3),
                                      data.points, options);
    CHECK(fit.history.front().max > 1e-3);
    CHECK(largest_difference(fit.control, tri.positions) / tri_diagonal < 1e-6);
  }
  SECTION("sqrt(3), its exact limit points") {
    const Mesh tri = read_obj((kMeshes / "tri-mix.obj").string());
    const double tri_diagonal = diagonal_of(tri.positions);
    const auto tables = Tables::load(generated_table("sqrt3", "--valence 3-8 --n 1,3,9,27", "sgt").string());
    const auto topology = test_runtime::topology_of(tables, tri);
    const FitResult fit = fit_surface(topology, perturbed(tri.positions, 0.01 * tri_diagonal, 3),
                                      grid_points(Surface(topology, tri.positions)), options);
    CHECK(fit.history.front().max > 1e-3);
    CHECK(largest_difference(fit.control, tri.positions) / tri_diagonal < 1e-6);
  }
  SECTION("nonpoly, its exact limit points") {
    const auto tables = Tables::load(generated_table("nonpoly", "--valence 3-8 --n 8", "sgs").string());
    const auto topology = test_runtime::topology_of(tables, mesh);
    const FitResult fit = fit_surface(topology, start, grid_points(Surface(topology, mesh.positions)), options);
    CHECK(fit.history.front().max > 1e-3);
    CHECK(largest_difference(fit.control, mesh.positions) / diagonal < 1e-6);
  }
}

TEST_CASE("On a noisy ellipsoid SDM reaches a max error in fewer iterations than TDM, and TDM than PDM (seed 003)",
          "[fitting]") {
  const auto tables = Tables::load(generated_table("catmull-clark", "--valence 3-8 --n 8", "sgs").string());
  const Mesh sphere = quad_sphere(3);
  const auto topology = test_runtime::topology_of(tables, sphere);
  const std::vector<Point> points = ellipsoid_points(4000, 2e-4, 5);
  std::map<FitMethod, std::size_t> iterations;
  for (const FitMethod method : {FitMethod::PointDistance, FitMethod::TangentDistance, FitMethod::SquaredDistance}) {
    FitOptions options;
    options.method = method;
    options.iterations = 25;
    options.smoothing = 0;
    options.max_error = 1e-3;
    const FitResult fit = fit_surface(topology, scaled(sphere.positions, 0.6), points, options);
    iterations[method] = fit.history.back().max <= options.max_error ? fit.history.size() - 1 : 1000;
    INFO(method_name(method) << ": " << iterations[method] << " iterations, max " << fit.history.back().max);
    CHECK(fit.history.front().max > 0.1);
  }
  CHECK(iterations[FitMethod::SquaredDistance] < iterations[FitMethod::TangentDistance]);
  CHECK(iterations[FitMethod::TangentDistance] < iterations[FitMethod::PointDistance]);
}

TEST_CASE("The errors a fit reports are the points' distances to the fitted surface (Bfr brute force)", "[fitting]") {
  const auto tables = Tables::load(generated_table("catmull-clark", "--valence 3-8 --n 8", "sgs").string());
  Mesh sphere = quad_sphere(2);
  const auto topology = test_runtime::topology_of(tables, sphere);
  const std::vector<Point> points = ellipsoid_points(150, 1e-2, 9);
  for (const FitMethod method : {FitMethod::PointDistance, FitMethod::TangentDistance, FitMethod::SquaredDistance}) {
    INFO(method_name(method));
    FitOptions options;
    options.method = method;
    options.iterations = 4;
    options.smoothing = 1e-3;
    const FitResult fit = fit_surface(topology, scaled(sphere.positions, 0.6), points, options);
    REQUIRE(fit.history.size() == 5);
    sphere.positions = fit.control;
    const bfr_reference::BfrOracle oracle(sphere);
    double sum = 0, largest = 0;
    for (const Point& q : points) {
      const double d = oracle.distance_to(q);
      sum += d * d, largest = std::max(largest, d);
    }
    const double diagonal = diagonal_of(points);
    CHECK(fit.diagonal == Approx(diagonal).epsilon(1e-15));
    CHECK(fit.history.back().rms == Approx(std::sqrt(sum / points.size()) / diagonal).epsilon(1e-8));
    CHECK(fit.history.back().max == Approx(largest / diagonal).epsilon(1e-8));
  }
}

TEST_CASE("Fitting refuses bad inputs with clear errors", "[fitting]") {
  const auto tables = Tables::load(generated_table("catmull-clark", "--valence 3-8 --n 8", "sgs").string());
  const Mesh sphere = quad_sphere(2);
  const auto topology = test_runtime::topology_of(tables, sphere);
  const std::vector<Point> points = ellipsoid_points(200, 0, 1);
  FitOptions options;
  CHECK_THROWS_WITH(fit_surface(topology, sphere.positions, {}, options), "no points to fit");
  std::vector<Point> bad = points;
  bad[17][1] = std::nan("");
  CHECK_THROWS_WITH(fit_surface(topology, sphere.positions, bad, options),
                    Catch::Contains("point 17 (numbered from 0) has the coordinate nan"));
  std::vector<Point> far = sphere.positions;
  far[3][2] = 2e37;
  CHECK_THROWS_WITH(fit_surface(topology, far, points, options),
                    Catch::Contains("control vertex 3 (numbered from 0) has the coordinate 2e37; coordinates must be finite"));
  CHECK_THROWS_WITH(fit_surface(topology, {sphere.positions.begin(), sphere.positions.end() - 1}, points, options),
                    Catch::Contains("control positions for a control mesh of"));
  CHECK_THROWS_WITH(fit_surface(topology, sphere.positions, std::vector<Point>(5, Point{1, 2, 3}), options),
                    Catch::Contains("all equal"));
  options.threads = -1;
  CHECK_THROWS_WITH(fit_surface(topology, sphere.positions, points, options), Catch::Contains("threads"));
  options.threads = 0;
  options.smoothing = -1;
  CHECK_THROWS_AS(fit_surface(topology, sphere.positions, points, options), FitError);
  CHECK_THROWS_WITH(parse_fit_method("pdx"), Catch::Contains("'pdx'"));
  // Too few points for the control points, and no smoothing: a singular system, said so.
  CHECK_THROWS_WITH(fit_at_samples(*topology, {{0, 0.5, 0.5}}, {{0, 0, 0}}, 0), Catch::Contains("singular"));
  // Smoothing so large that its term alone decides (it used to end in "singular ... add smoothing"),
  // and a decay that would make it grow, are refused as such, naming the value.
  options.smoothing = 1e300;
  CHECK_THROWS_WITH(fit_surface(topology, sphere.positions, points, options), Catch::Contains("from 0 to 1000 (got 1e300"));
  CHECK_THROWS_WITH(fit_at_samples(*topology, {{0, 0.5, 0.5}}, {{0, 0, 0}}, 1e300), Catch::Contains("from 0 to 1000"));
  options.smoothing = 1e-3;
  options.smoothing_decay = 2;
  CHECK_THROWS_WITH(fit_surface(topology, sphere.positions, points, options), Catch::Contains("factors from 0 to 1 (got 2)"));
  options.smoothing_decay = 0.5;
  options.method = static_cast<FitMethod>(9);  // used to fit as tdm
  CHECK_THROWS_WITH(fit_surface(topology, sphere.positions, points, options), Catch::Contains("unknown fit method 9"));
  options.method = FitMethod::SquaredDistance;
  {
    FitOptions adaptive = options;
    adaptive.max_error = 0.01;
    CHECK_THROWS_WITH(fit_adaptively(nullptr, sphere, points, adaptive, 1000), Catch::Contains("needs tables"));
  }
  // What the layers below refuse reaches the caller as the fit's error (one type per layer), saying what it was.
  try {
    fit_surface(topology, std::vector<Point>(sphere.positions.size(), Point{0, 0, 0}), points, options);
    FAIL("a control mesh collapsed to a point was fitted");
  } catch (const FitError& e) {
    CHECK_THAT(e.what(), Catch::Contains("the initial control mesh"));
  }
  try {
    fit_at_samples(*topology, {{topology->face_count(), 0.5, 0.5}}, {{0, 0, 0}}, 1);
    FAIL("a sample on a face that does not exist was fitted");
  } catch (const FitError& e) {
    CHECK_THAT(e.what(), Catch::Contains("a sample: face " + std::to_string(topology->face_count())));
  }
}

TEST_CASE("A fit step that would throw control points beyond the coordinate limit is damped, not an error",
          "[fitting]") {
  // Points near the largest coordinates: an undamped first step overshoots
  // past 1e37 (it used to end the fit with set_positions' error about a
  // coordinate the caller never gave).
  const auto tables = Tables::load(generated_table("catmull-clark", "--valence 3-8 --n 8", "sgs").string());
  Mesh sphere = quad_sphere(2);
  const auto topology = test_runtime::topology_of(tables, sphere);
  const double scale = 4e36;
  for (Point& p : sphere.positions)
    for (double& x : p) x *= scale;
  std::vector<Point> points = ellipsoid_points(300, 0, 1);
  for (Point& p : points)
    for (double& x : p) x *= 2.4 * scale;
  FitOptions options;
  options.method = FitMethod::PointDistance;
  options.smoothing = 0;
  options.iterations = 5;
  const FitResult fit = fit_surface(topology, sphere.positions, points, options);
  CHECK(fit.history.back().rms <= fit.history.front().rms);
  for (const Point& p : fit.control)
    for (double x : p) CHECK(std::fabs(x) <= 1e37);
}

namespace {

void write_points(const std::filesystem::path& path, const std::vector<Point>& points) {
  std::ofstream out(path);
  out << std::setprecision(17);
  for (const Point& p : points) out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
}

void write_mesh(const std::filesystem::path& path, const Mesh& mesh) { write_obj(mesh, path.string()); }

}  // namespace

TEST_CASE("stencilfit: fits a perturbed control mesh to points, writes the mesh, a report and a plot", "[fitting][cli]") {
  const std::string tables = generated_table("catmull-clark", "--valence 3-8 --n 8", "sgs").string();
  const auto dir = scratch_dir("stencilfit");
  const Mesh mesh = read_obj((kMeshes / "chess-piece.obj").string());
  const double diagonal = diagonal_of(mesh.positions);
  write_points(dir / "points.xyz", bfr_samples(mesh, 8, 21).points);
  Mesh start = mesh;
  start.positions = perturbed(mesh.positions, 0.01 * diagonal, 4);
  write_mesh(dir / "start.obj", start);
  const CliResult r = run_stencilfit("--tables " + tables + " --points " + (dir / "points.xyz").string() + " --control " +
                                     (dir / "start.obj").string() + " --smoothing 0 --iterations 20 --out " +
                                     (dir / "fitted.obj").string() + " --report " + (dir / "r.json").string() +
                                     " --plot " + (dir / "p.svg").string());
  INFO(r.output);
  REQUIRE(r.status == 0);
  CHECK_THAT(r.output, Catch::Contains("iteration   1  rms"));
  const Mesh fitted = read_obj((dir / "fitted.obj").string());
  CHECK(fitted.face_vertices == mesh.face_vertices);
  CHECK(largest_difference(fitted.positions, mesh.positions) / diagonal < 1e-6);
  const auto report = nlohmann::json::parse(std::ifstream(dir / "r.json"));
  CHECK(report["method"] == "sdm");
  CHECK(report["iterations"].size() >= 2);
  CHECK(report["iterations"][0]["max"].get<double>() > 1e-3);
  std::ifstream svg(dir / "p.svg");
  const std::string text((std::istreambuf_iterator<char>(svg)), std::istreambuf_iterator<char>());
  CHECK_THAT(text, Catch::StartsWith("<svg") && Catch::Contains("<polyline"));
}

TEST_CASE("stencilfit ends when the points are a millionth of the control mesh's size", "[fitting][cli]") {
  // Its closest-point tolerance, 1e-9 of the points' diagonal, was 1e-15 of
  // the surface's, finer than doubles resolve there: the first query never
  // ended. The query now raises it to 1e-14 of the surface's extent.
  const std::string tables = generated_table("catmull-clark", "--valence 3-8 --n 8", "sgs").string();
  const auto dir = scratch_dir("stencilfit-tiny");
  std::vector<Point> points = ellipsoid_points(100, 0, 3);
  for (Point& p : points)
    for (double& x : p) x *= 1e-6;
  write_points(dir / "tiny.xyz", points);
  write_mesh(dir / "sphere.obj", quad_sphere(2));
  const CliResult r = run_command(std::string("timeout -s KILL 120 ") + STENCILFIT_EXE,
                                  "--tables " + tables + " --points " + (dir / "tiny.xyz").string() + " --control " +
                                      (dir / "sphere.obj").string() + " --iterations 2 --out " + (dir / "out.obj").string());
  INFO(r.output);
  CHECK(r.status == 0);
  CHECK(std::filesystem::exists(dir / "out.obj"));
}

TEST_CASE("stencilfit refuses bad inputs with one line naming the fault, and writes nothing", "[fitting][cli]") {
  const std::string tables = generated_table("catmull-clark", "--valence 3-8 --n 8", "sgs").string();
  const std::string loop = generated_table("loop", "--valence 3-8 --n 4", "sgt").string();
  const auto dir = scratch_dir("stencilfit-bad");
  write_points(dir / "points.xyz", ellipsoid_points(100, 0, 3));
  {
    std::ofstream(dir / "nan.xyz") << "0 0 0\n1 2 3\n1 nan 2\n";
    std::ofstream(dir / "empty.xyz") << "# nothing\n";
    std::ofstream(dir / "columns.xyz") << "0 0 0\n1 2\n";
    std::ofstream(dir / "short.off") << "OFF\n3 1 0\n0 0 0\n1 0 0\n";
    // The faces an OFF header declares must be there, and nothing after them (as for PLY).
    std::ofstream(dir / "faces.off") << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n";
    std::ofstream(dir / "extra.off") << "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  }
  write_mesh(dir / "sphere.obj", quad_sphere(2));
  const std::string out = (dir / "out.obj").string();
  const auto run = [&](const std::string& points, const std::string& extra, const std::string& table) {
    return run_stencilfit("--tables " + table + " --points " + (dir / points).string() + " --control " +
                          (dir / "sphere.obj").string() + " --out " + out + " " + extra);
  };
  const std::vector<std::tuple<std::string, std::string, std::string, std::string>> cases{
      {"nan.xyz", "", tables, "nan.xyz:3"},
      {"empty.xyz", "", tables, "no points"},
      {"columns.xyz", "", tables, "columns.xyz:2"},
      {"short.off", "", tables, "2 of 3 vertices"},
      {"faces.off", "", tables, "truncated: the file ends after 0 of the 1 faces its header declares"},
      {"extra.off", "", tables, "extra.off:6: more lines than the header's 3 vertices and 0 faces declare"},
      {"points.xyz", "--smoothing 1e300", tables, "--smoothing must be a number from 0 to 1000"},
      {"points.xyz", "--method xdm", tables, "'xdm'"},
      {"points.xyz", "--smoothing -1", tables, "--smoothing"},
      {"points.xyz", "--iterations -2", tables, "--iterations"},
      {"points.xyz", "", loop, "triangle"},
      {"points.xyz", "--max-control-points 100", tables, "needs --max-error"},
      {"points.xyz", "--max-control-points 10 --max-error 0.001", tables, "below the control mesh's 26"},
      {"points.xyz", "--max-control-points 100 --max-error 1e-6", tables, "splits triangles"},
      {"points.xyz", "--max-control-points -3 --max-error 0.001", tables, "at least 4, got -3"},
      {"points.xyz", "--tolerance 1e-300", tables, "at least 1e-14"},
      {"points.xyz", "--report " + out, tables, "three different files"},
      // Outputs that could not be written are refused before the fit, not after it.
      {"points.xyz", "--plot " + (dir / "no-such-folder" / "p.svg").string(), tables, "p.svg: cannot be written: its folder"},
      {"points.xyz", "--report " + dir.string(), tables, ": is a directory, not a file to write"},
  };
  for (const auto& [points, extra, table, message] : cases) {
    INFO(points << " " << extra);
    const CliResult r = run(points, extra, table);
    INFO(r.output);
    CHECK(r.status == 1);
    CHECK_THAT(r.output, Catch::Contains(message));
    CHECK(std::count(r.output.begin(), r.output.end(), '\n') == 1);
    CHECK(!std::filesystem::exists(out));
    CHECK(!std::filesystem::exists(out + ".partial"));
  }
  // A negative size is named before any reconstruction work (it once wrapped round to 2^64 - 5).
  const CliResult negative = run_stencilfit("--tables " + tables + " --points " + (dir / "points.xyz").string() +
                                            " --control-points -5 --out " + out);
  CHECK(negative.status == 1);
  CHECK_THAT(negative.output, Catch::Contains("--control-points must be at least 4, got -5"));
  CHECK_THAT(negative.output, !Catch::Contains("initial mesh"));
  CHECK(!std::filesystem::exists(out));
}

namespace {

double area_of(const Mesh& mesh) {
  double area = 0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const Point& a = mesh.positions[static_cast<std::size_t>(mesh.face_vertices[3 * f])];
    const Point& b = mesh.positions[static_cast<std::size_t>(mesh.face_vertices[3 * f + 1])];
    const Point& c = mesh.positions[static_cast<std::size_t>(mesh.face_vertices[3 * f + 2])];
    const Point u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    area += 0.5 * std::hypot(u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]);
  }
  return area;
}

// Every directed edge once and its reverse once: closed, manifold, consistently oriented.
bool closed_and_oriented(const Mesh& mesh) {
  std::map<std::pair<int, int>, int> directed;
  std::size_t offset = 0;
  for (const int size : mesh.face_sizes) {
    for (int c = 0; c < size; ++c)
      ++directed[{mesh.face_vertices[offset + static_cast<std::size_t>(c)],
                  mesh.face_vertices[offset + static_cast<std::size_t>((c + 1) % size)]}];
    offset += static_cast<std::size_t>(size);
  }
  for (const auto& [edge, count] : directed)
    if (count != 1 || directed.count({edge.second, edge.first}) == 0) return false;
  return true;
}

std::vector<int> valences_of(const Mesh& mesh) {
  std::vector<int> valence(mesh.vertex_count(), 0);
  for (const int v : mesh.face_vertices) ++valence[static_cast<std::size_t>(v)];
  return valence;
}

}  // namespace

TEST_CASE("Red-green refinement: closed, oriented, the same polyhedron, no T-vertices, valences capped", "[fitting]") {
  const Mesh ico = read_obj((kMeshes / "icosahedron.obj").string());
  SECTION("one marked face: 3 midpoints, the face in 4, its 3 neighbours bisected") {
    std::vector<bool> marked(ico.face_count(), false);
    marked[7] = true;
    const Mesh refined = refine_red_green(ico, marked, 64);
    CHECK(refined.vertex_count() == 15);
    CHECK(refined.face_count() == 26);
    CHECK(closed_and_oriented(refined));
    CHECK(area_of(refined) == Approx(area_of(ico)).epsilon(1e-14));
    for (std::size_t v = 0; v < ico.vertex_count(); ++v) CHECK(refined.positions[v] == ico.positions[v]);
  }
  SECTION("a face with two split edges turns red; caps turn greens red") {
    std::mt19937 rng(3);
    for (int trial = 0; trial < 20; ++trial) {
      std::vector<bool> marked(ico.face_count(), false);
      for (std::size_t f = 0; f < marked.size(); ++f) marked[f] = rng() % 4 == 0;
      for (const int cap : {5, 6, 64}) {
        const Mesh refined = refine_red_green(ico, marked, cap);
        CHECK(closed_and_oriented(refined));
        CHECK(area_of(refined) == Approx(area_of(ico)).epsilon(1e-14));
        const std::vector<int> valence = valences_of(refined);
        CHECK(*std::max_element(valence.begin(), valence.end()) <= std::max(cap, 6));
      }
    }
  }
  CHECK_THROWS_WITH(refine_red_green(read_obj((kMeshes / "cube.obj").string()), std::vector<bool>(6, true), 8),
                    Catch::Contains("splits triangles"));
  CHECK_THROWS_WITH(refine_red_green(ico, {true}, 8), Catch::Contains("1 marks"));
  // Indices and the valence cap are checked before use (an index past the vertices was written through).
  Mesh broken = ico;
  broken.face_vertices[7] = static_cast<int>(ico.vertex_count());
  CHECK_THROWS_WITH(refine_red_green(broken, std::vector<bool>(ico.face_count(), true), 8),
                    Catch::Contains("face 2 refers to vertex 12, but the mesh has 12"));
  broken = ico, broken.face_vertices.pop_back();
  CHECK_THROWS_WITH(refine_red_green(broken, std::vector<bool>(ico.face_count(), true), 8), Catch::Contains("59 face-vertex indices"));
  CHECK_THROWS_WITH(refine_red_green(ico, std::vector<bool>(ico.face_count(), true), 0), Catch::Contains("3..64 (got 0)"));
}

TEST_CASE("Adaptive fitting refines where the error is large, within the budget, and beats the unrefined fit",
          "[fitting]") {
  const auto tables = Tables::load(generated_table("catmull-clark", "--valence 3-8 --n 8", "sgs").string());
  Mesh ico = read_obj((kMeshes / "icosahedron.obj").string());
  for (Point& p : ico.positions) {
    const double l = std::hypot(p[0], p[1], p[2]);
    p = {0.9 * p[0] / l, 0.9 * 0.7 * p[1] / l, 0.9 * 0.5 * p[2] / l};
  }
  // A bump on the ellipsoid that 12 control points cannot follow.
  std::vector<Point> points = ellipsoid_points(3000, 0, 8);
  for (Point& p : points) {
    const double bump = 0.15 * std::exp(-20 * ((p[0] - 1) * (p[0] - 1) + p[1] * p[1] + p[2] * p[2]));
    p[0] += bump;
  }
  FitOptions options;
  options.iterations = 4;
  options.max_error = 0.004;
  const FitResult plain = fit_surface(test_runtime::topology_of(tables, ico), ico.positions, points, options);
  const AdaptiveFit adaptive = fit_adaptively(tables, ico, points, options, 120);
  INFO("plain max " << plain.history.back().max << ", adaptive max " << adaptive.fit.history.back().max << " with "
                    << adaptive.mesh.vertex_count() << " control points in " << adaptive.rounds << " rounds");
  CHECK(adaptive.rounds >= 1);
  CHECK(adaptive.mesh.vertex_count() > ico.vertex_count());
  CHECK(adaptive.mesh.vertex_count() <= 120);
  CHECK(closed_and_oriented(adaptive.mesh));
  CHECK(adaptive.fit.history.back().max < 0.5 * plain.history.back().max);
  CHECK(adaptive.fit.history.back().control_points == adaptive.mesh.vertex_count());
  CHECK(adaptive.stopped.size() > 0);
  // A tight budget is used, not dropped: a round whose red-green closure
  // overshoots splits fewer faces (it used to split none, without a word).
  for (const std::size_t budget : {std::size_t{16}, std::size_t{24}}) {
    INFO("budget " << budget);
    const AdaptiveFit tight = fit_adaptively(tables, ico, points, options, budget);
    CHECK(tight.rounds >= 1);
    CHECK(tight.mesh.vertex_count() > ico.vertex_count());
    CHECK(tight.mesh.vertex_count() <= budget);
    CHECK(closed_and_oriented(tight.mesh));
    CHECK_THAT(tight.stopped, Catch::Contains("budget"));
  }
  CHECK_THROWS_WITH(fit_adaptively(tables, ico, points, options, 11), Catch::Contains("below the control mesh's 12"));
  // The splits make a new mesh from the faces alone: a tag would be dropped
  // and the fit would answer for another surface (it used to, silently).
  for (int kind = 0; kind < 3; ++kind) {
    Mesh tagged = ico;
    tagged.source = "ico.obj";
    if (kind == 0) tagged.tags.creases.push_back({ico.face_vertices[0], ico.face_vertices[1], 2.0, 21});
    if (kind == 1) tagged.tags.corners.push_back({ico.face_vertices[0], 3.0, 22});
    if (kind == 2) tagged.tags.holes.push_back({5, 23});
    CHECK_THROWS_WITH(fit_adaptively(tables, tagged, points, options, 120),
                      Catch::Contains("ico.obj:2" + std::to_string(kind + 1)) &&
                          Catch::Contains("does not carry crease, corner or hole tags"));
  }
  {  // the whole-mesh options go with every round
    Mesh with_options = ico;
    with_options.tags.boundary = BoundaryInterpolation::EdgeAndCorner;
    const AdaptiveFit carried = fit_adaptively(tables, with_options, points, options, 24);
    CHECK(carried.rounds >= 1);
    CHECK(carried.mesh.tags.boundary == BoundaryInterpolation::EdgeAndCorner);
  }
  options.max_error = 0;
  CHECK_THROWS_WITH(fit_adaptively(tables, ico, points, options, 100), Catch::Contains("max error above 0"));
}

TEST_CASE("no tool writes over its tables or into a folder of JSON tables", "[fitting][cli]") {
  // The tables are an input like the mesh and the points: stencildist and
  // stencilfit used to replace a .sgs given again as --out, --report or --plot.
  const std::filesystem::path table = generated_table("catmull-clark", "--valence 3-8 --n 8", "sgs");
  const auto dir = scratch_dir("tables-as-output");
  const std::filesystem::path copy = dir / "tables" / "cc.sgs";
  std::filesystem::create_directories(copy.parent_path());
  std::filesystem::copy_file(table, copy);
  const std::uintmax_t bytes = std::filesystem::file_size(copy);
  write_points(dir / "points.xyz", ellipsoid_points(100, 0, 3));
  write_mesh(dir / "sphere.obj", quad_sphere(2));
  const std::string mesh = (dir / "sphere.obj").string(), points = (dir / "points.xyz").string();
  for (const std::string& tables : {copy.string(), copy.parent_path().string(), copy.parent_path().string() + "/"}) {
    const std::vector<CliResult> runs{
        run_command(STENCILDIST_EXE, "--tables " + tables + " --mesh " + mesh + " --points " + points + " --out " + copy.string()),
        run_stencilfit("--tables " + tables + " --points " + points + " --control " + mesh + " --out " +
                       (dir / "f.obj").string() + " --report " + copy.string()),
        run_stencilfit("--tables " + tables + " --points " + points + " --control " + mesh + " --out " +
                       (dir / "f.obj").string() + " --plot " + copy.string())};
    for (const CliResult& r : runs) {
      INFO(tables << "\n" << r.output);
      CHECK(r.status == 1);
      CHECK_THAT(r.output, Catch::Contains(copy.string() + " is an input and the output"));
    }
  }
  CHECK(std::filesystem::file_size(copy) == bytes);
  CHECK(Tables::load(copy.string())->scheme() == "catmull-clark");
  // Other files beside a table file are not read: an output may go there.
  const std::string beside = (copy.parent_path() / "beside.obj").string();
  const CliResult next_to = run_stenciltess("--tables " + copy.parent_path().string() + " --mesh " + mesh + " --rate 2 --out " + beside);
  INFO(next_to.output);
  CHECK(next_to.status == 0);
  CHECK(std::filesystem::exists(beside));
  // A folder of exact JSON tables is read whole: nothing is written into it.
  const std::filesystem::path json = dir / "json";
  std::filesystem::copy(table.parent_path(), json, std::filesystem::copy_options::recursive);
  std::filesystem::remove(json / table.filename());
  const std::string inside = (json / "v3" / "new.obj").string();
  const std::vector<CliResult> into{
      run_command(STENCILDIST_EXE, "--tables " + json.string() + " --mesh " + mesh + " --points " + points + " --out " + inside),
      run_stenciltess("--tables " + json.string() + " --mesh " + mesh + " --rate 2 --out " + inside),
      run_stencilfit("--tables " + json.string() + " --points " + points + " --control " + mesh + " --out " + inside)};
  for (const CliResult& r : into) {
    INFO(r.output);
    CHECK(r.status == 1);
    CHECK_THAT(r.output, Catch::Contains("a folder of tables read whole"));
  }
  CHECK_FALSE(std::filesystem::exists(inside));
  std::filesystem::remove_all(dir);
}

TEST_CASE("every tool refuses, before its work, an output it could not write at the end", "[fitting][cli]") {
  const std::string tables = generated_table("catmull-clark", "--valence 3-8 --n 8", "sgs").string();
  const auto dir = scratch_dir("unwritable-outputs");
  write_points(dir / "points.xyz", ellipsoid_points(100, 0, 3));
  write_mesh(dir / "sphere.obj", quad_sphere(2));
  std::ofstream(dir / "a-file") << "x";
  const std::string mesh = (dir / "sphere.obj").string(), points = (dir / "points.xyz").string();
  for (const std::filesystem::path& bad : {dir / "a-file" / "out.obj", dir / "missing" / "out.obj"}) {
    const std::vector<CliResult> runs{
        run_stencilfit("--tables " + tables + " --points " + points + " --control " + mesh + " --out " + bad.string()),
        run_stenciltess("--tables " + tables + " --mesh " + mesh + " --rate 2 --out " + bad.string()),
        run_command(STENCILDIST_EXE, "--tables " + tables + " --mesh " + mesh + " --points " + points + " --out " + bad.string())};
    for (const CliResult& r : runs) {
      INFO(r.output);
      CHECK(r.status == 1);
      CHECK_THAT(r.output, Catch::Contains(bad.string() + ": cannot be written: "));
      CHECK(std::count(r.output.begin(), r.output.end(), '\n') == 1);  // the error alone: no iteration, no summary
    }
  }
  std::filesystem::remove_all(dir);
}
