// The library used wrongly from C++ (a review as a hostile library user):
// every misuse is an exception of the runtime's error types that says what
// was wrong, never a crash, undefined behaviour, a silently wrong answer or a
// file that read_obj would refuse.
#include <catch2/catch.hpp>

#include <array>
#include <climits>
#include <cstdlib>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <utility>
#include <vector>

#include "bundled_meshes.hpp"
#include "cli.hpp"
#include "runtime_api.hpp"
#include "stencil_runtime/closest_point.hpp"
#include "stencil_runtime/mesh_io.hpp"
#include "stencil_runtime/subdivide.hpp"
#include "stencil_runtime/tessellation.hpp"

using namespace stencil_runtime;
namespace fs = std::filesystem;

namespace {

std::shared_ptr<const Tables> catmull_clark() {
  return Tables::load(generated_table("catmull-clark", "--valence 3-8 --n 24", "sgs").string());
}

// A square pyramid: four triangles (N-gons to a quad scheme: sub-face tiles) and the base quad.
Mesh pyramid() {
  Mesh m;
  m.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {0, 0, 1.5}};
  m.face_sizes = {3, 3, 3, 3, 4};
  m.face_vertices = {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4, 0, 3, 2, 1};
  return m;
}

double distance(const Point& a, const Point& b) { return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }

}  // namespace

TEST_CASE("closest points: a query point beyond the coordinate limit is refused, not reported as not found",
          "[runtime][misuse][closest]") {
  const Surface surface = test_runtime::surface_of(catmull_clark(), test_meshes::bundled("cube"));
  const ClosestPointQuery query(surface);
  // Far but within the limit: found, at the distance the far point has from the cube (|q| - at most the cube's size).
  for (const double x : {1e30, 1e37}) {
    const ClosestPoint r = query.find(Point{x, 0, 0});
    REQUIRE(r.found);
    CHECK(r.distance >= x - 2);
    CHECK(r.distance <= x + 2);
  }
  // Squared distances overflowed from about 1.4e154 on, and the point came back with found == false.
  for (const double x : {2e154, 1e300, -1.0000000000000001e37}) {
    INFO(x);
    CHECK_THROWS_WITH(query.find(Point{0, x, 0}), Catch::Contains("beyond +-1e37"));
  }
  CHECK_THROWS_WITH(query.find(std::vector<Point>{{0, 0, 0}, {0, 0, 2e154}}), Catch::StartsWith("query 1 "));
  ClosestPointOptions bad;
  bad.tolerance = -1;
  CHECK_THROWS_WITH(ClosestPointQuery(surface, bad), Catch::Contains("(got -1)"));
}

TEST_CASE("exact parameters are placed on an N-gon's tiles exactly, whatever their 64-bit denominators",
          "[runtime][misuse][parameters]") {
  const Surface surface = test_runtime::surface_of(catmull_clark(), pyramid());
  const FaceDomain triangle = surface.topology().domain(0);
  REQUIRE(triangle.kind == FaceDomain::Kind::QuadSubfaces);
  // (2^61 - 1)/(2^63 - 1), just below 1/4: its tile used to need 4 * num + den in 64 bits and threw
  // ParameterOverflow before the evaluation's fallback to the nearest double could run.
  const ExactParameter near_quarter{Fraction::make(INT64_MAX / 4, INT64_MAX), Fraction::make(1, 3)};
  REQUIRE(triangle.contains(near_quarter));
  const Evaluation e = surface.evaluate(0, near_quarter, 1e-12);
  const Point quarter = surface.evaluate(0, ExactParameter{Fraction::make(1, 4), Fraction::make(1, 3)});
  CHECK(distance(e.point, quarter) < 1e-14);  // the parameters differ by 1.6e-19
  // 2^62/(2^63 - 1) is above 1/2 by 5e-20: between the tiles (its double, 0.5, is on tile 0's border).
  const ExactParameter past_half{Fraction::make(std::int64_t{1} << 62, INT64_MAX), Fraction::make(1, 4)};
  CHECK_FALSE(triangle.contains(past_half));
  CHECK(triangle.contains(0.5, 0.25));
  CHECK_THROWS_WITH(surface.evaluate(0, past_half, 1e-12), Catch::Contains("lies outside face 0"));
  CHECK_THROWS_WITH(surface.derivatives(0, past_half), Catch::Contains("lies outside face 0"));
  // On a triangle of a triangle scheme, u + v <= 1 is decided in 128 bits too.
  const FaceDomain tri = FaceDomain::of(SchemeFamily::Triangle, 3);
  const Fraction half_up = Fraction::make((std::int64_t{1} << 62) + 1, INT64_MAX);  // 1/2 + 1.6e-19
  const Fraction half_down = Fraction::make(std::int64_t{1} << 62, INT64_MAX - 2);  // 2^62/(2^63 - 3), just above 1/2
  CHECK_FALSE(tri.contains(ExactParameter{half_up, half_down}));
  CHECK(tri.contains(ExactParameter{half_up, Fraction::make(1, 3)}));
  // NaN used to reach an undefined conversion to int in the tile lookup.
  double su = 0, sv = 0;
  const int s = FaceDomain::of(SchemeFamily::Quad, 5).subface(std::nan(""), 0.3, su, sv);
  CHECK(s >= 0);
  CHECK(s < 5);
}

TEST_CASE("FaceDomain::clamp moves a parameter rounded just outside to the nearest point inside", "[runtime][parameters]") {
  const FaceDomain quad = FaceDomain::of(SchemeFamily::Quad, 4), tri = FaceDomain::of(SchemeFamily::Triangle, 3);
  struct Case {
    const FaceDomain* domain;
    double u, v, cu, cv;  // the parameter and the nearest point of the domain
  };
  const FaceDomain pentagon = FaceDomain::of(SchemeFamily::Quad, 5);  // 3 x 2 tiles of 1/2
  for (const Case& c : {Case{&tri, 0.125, -2.7755575615628914e-17, 0.125, 0}, Case{&tri, -1.1e-16, 0.25, 0, 0.25},
                        Case{&tri, 0.7, 0.30000000000000004, 0.69999999999999996, 0.30000000000000004},
                        Case{&tri, 0.6, 0.6, 0.5, 0.5}, Case{&tri, 0.2, 0.3, 0.2, 0.3}, Case{&quad, 1 + 1e-16, -1e-17, 1, 0},
                        Case{&quad, 0.4, 0.6, 0.4, 0.6}, Case{&pentagon, 1.5 + 1e-15, 0.25, 1.5, 0.25},
                        Case{&pentagon, 2.25, -1e-16, 2.25, 0}}) {
    double u = c.u, v = c.v;
    c.domain->clamp(u, v);
    INFO(c.u << ", " << c.v << " -> " << u << ", " << v);
    CHECK(c.domain->contains(u, v));
    CHECK(u == Approx(c.cu).margin(1e-15));
    CHECK(v == Approx(c.cv).margin(1e-15));
  }
}

TEST_CASE("fractions take every value 64 bits hold, -2^63 included", "[runtime][misuse][parameters]") {
  CHECK(Fraction::make(INT64_MIN, 1) == Fraction{INT64_MIN, 1});
  CHECK(Fraction::make(0, INT64_MIN) == Fraction{0, 1});
  CHECK(Fraction::make(2, INT64_MIN) == Fraction{-1, std::int64_t{1} << 62});
  CHECK(Fraction::make(INT64_MIN, INT64_MIN) == Fraction{1, 1});
  CHECK(Fraction::make(6, -4) == Fraction{-3, 2});
  CHECK_THROWS_AS(Fraction::make(1, INT64_MIN), ParameterOverflow);  // -1/2^63: the denominator does not fit
  CHECK(parse_fraction("-9223372036854775808") == Fraction{INT64_MIN, 1});
  CHECK_THROWS_WITH(parse_fraction("1/-9223372036854775808"), Catch::Contains("'1/-9223372036854775808'"));
}

TEST_CASE("write_obj refuses a mesh read_obj would refuse, naming what is wrong, and writes nothing",
          "[runtime][misuse][io]") {
  const fs::path dir = scratch_dir("misuse-write-obj");
  const Mesh cube = test_meshes::bundled("cube");
  const fs::path out = dir / "out.obj";
  auto refused = [&](const Mesh& m, const std::string& why) {
    INFO(why);
    CHECK_THROWS_WITH(write_obj(m, out.string()), Catch::Contains(why));
    CHECK(fs::is_empty(dir));  // neither the file nor a partial one
  };
  Mesh m = cube;
  m.face_sizes.assign(3000000, 4);  // read 12 million indices from 24: used to crash
  refused(m, "add up to more than the 24 face-vertex indices");
  m = cube, m.face_sizes.push_back(4), m.face_sizes.push_back(4);
  refused(m, "add up to more than the 24");
  m = cube, m.face_vertices.push_back(0);
  refused(m, "add up to 24 face-vertex indices, but 25 are given");
  m = cube, m.face_vertices[5] = 8;
  refused(m, "face 1 refers to vertex 8, but the mesh has 8");
  m = cube, m.face_vertices[5] = -1;
  refused(m, "refers to vertex -1");
  m = cube, m.positions[3][2] = std::nan("");
  refused(m, "vertex 3 (numbered from 0) has the coordinate nan");
  m = cube, m.positions[2][0] = 1e38;
  refused(m, "the coordinate 1e38");
  m = cube, m.face_sizes[0] = 2, m.face_sizes[1] = 6;
  refused(m, "face 0 has 2 vertices");
  m = cube, m.face_sizes.clear(), m.face_vertices.clear();
  refused(m, "no faces");
  m = cube, m.tags.creases.push_back({0, 6, 1.0, 0});
  refused(m, "not joined by an edge");
  m = cube, m.tags.corners.push_back({-2, 1.0, 0});
  refused(m, "refers to vertex -2");
  m = cube, m.tags.corners.push_back({1, std::nan(""), 0});
  refused(m, "sharpness nan");
  m = cube, m.tags.holes.push_back({6, 0});
  refused(m, "refers to face 6");
  // A good one still round-trips.
  write_obj(cube, out.string());
  const Mesh back = read_obj(out.string());
  CHECK(back.positions == cube.positions);
  CHECK(back.face_vertices == cube.face_vertices);
  fs::remove_all(dir);
}

TEST_CASE("write_polygons refuses polygons naming missing points and points that are not finite",
          "[runtime][misuse][io]") {
  const fs::path dir = scratch_dir("misuse-write-polygons");
  PolygonSoup soup;
  soup.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  soup.quads = {{0, 1, 2, 3}};
  soup.triangles = {{0, 1, 2}};
  for (const char* name : {"s.obj", "s.ply"}) {
    const std::string path = (dir / name).string();
    PolygonSoup bad = soup;
    bad.triangles[0][2] = 4;
    CHECK_THROWS_WITH(write_polygons(bad, path), Catch::Contains("triangle 0 of the tessellation refers to point 4"));
    bad = soup, bad.quads[0][1] = -7;
    CHECK_THROWS_WITH(write_polygons(bad, path), Catch::Contains("quad 0 of the tessellation refers to point -7"));
    bad = soup, bad.positions[2][1] = std::nanf("");
    CHECK_THROWS_WITH(write_polygons(bad, path), Catch::Contains("point 2 of the tessellation has the coordinate nan"));
    bad = soup, bad.normals.assign(4, {0, 0, 1}), bad.normals[1][0] = INFINITY;
    CHECK_THROWS_WITH(write_polygons(bad, path), Catch::Contains("normal 1 of the tessellation has the coordinate inf"));
    CHECK(fs::is_empty(dir));
    write_polygons(soup, path);
    CHECK(fs::exists(path));
    fs::remove(path);
  }
  fs::remove_all(dir);
}

TEST_CASE("a surface or plan moved from, and null output pointers, are errors, not crashes", "[runtime][misuse]") {
  const auto tables = catmull_clark();
  const Mesh cube = test_meshes::bundled("cube");
  Surface a = test_runtime::surface_of(tables, cube);
  Surface b(std::move(a));
  // The moved-from surface keeps its topology and has no positions (it used to say it had, then crash).
  CHECK_FALSE(a.has_positions());
  CHECK(&a.topology() == &b.topology());
  CHECK_THROWS_WITH(a.evaluate(0, 0.5, 0.5, 0), Catch::Contains("no control positions"));
  CHECK_THROWS_WITH(a.evaluate(0, test_runtime::grid(1, 1, 2)), Catch::Contains("no control positions"));
  a.set_positions(cube.positions);  // usable again
  CHECK(distance(a.evaluate(0, test_runtime::grid(1, 1, 2)), b.evaluate(0, test_runtime::grid(1, 1, 2))) == 0);
  Surface c = test_runtime::surface_of(tables, cube);
  c = std::move(b);
  CHECK_FALSE(b.has_positions());
  CHECK(c.has_positions());

  CHECK_THROWS_WITH(c.set_positions(nullptr, cube.positions.size()), Catch::Contains("null pointer"));
  CHECK(c.has_positions());  // the positions before stay

  const std::vector<int> rates(c.topology().face_count(), 3);
  TessellationPlan p(c.shared_topology(), rates);
  TessellationPlan q(std::move(p));
  for (const auto& call : std::vector<std::function<void()>>{
           [&] { (void)p.point_count(); }, [&] { (void)p.quads(); }, [&] { (void)p.triangles(); },
           [&] { (void)p.prepared_rates(); }, [&] { (void)p.topology(); }, [&] { (void)p.make_soup(); },
           [&] {
             std::vector<std::array<float, 3>> out(q.point_count());
             p.evaluate(c, out.data());
           }})
    CHECK_THROWS_WITH(call(), Catch::Contains("moved from"));
  PolygonSoup soup = q.make_soup();
  CHECK_THROWS_WITH(q.evaluate(c, nullptr), Catch::Contains("positions are to go to a null pointer"));
  CHECK_THROWS_WITH(q.evaluate(c, nullptr, soup.positions.data()), Catch::Contains("positions are to go to a null pointer"));
  CHECK_THROWS_WITH(q.evaluate_normals(c, nullptr), Catch::Contains("normals are to go to a null pointer"));
  p = std::move(q);  // a plan assigned to it makes it usable again
  p.evaluate(c, soup.positions.data());
  CHECK(soup.positions.size() == p.point_count());
}

TEST_CASE("an enumerator that names no value is refused", "[runtime][misuse]") {
  const Mesh cube = test_meshes::bundled("cube");
  MeshFeatures features;
  features.boundary = static_cast<BoundaryInterpolation>(42);
  CHECK_THROWS_WITH(SurfaceTopology::create(catmull_clark(), cube.vertex_count(), cube.face_sizes, cube.face_vertices, {}, features),
                    Catch::Contains("unknown boundary interpolation 42"));
}

TEST_CASE("subdivide refuses positions that are not finite instead of spreading them", "[runtime][misuse]") {
  Mesh cube = test_meshes::bundled("cube");
  cube.positions[4][1] = INFINITY;
  CHECK_THROWS_WITH(subdivide(*catmull_clark(), cube), Catch::Contains("vertex 4 (numbered from 0) has the coordinate inf"));
}

TEST_CASE("numbers in messages: as few digits as give the double back, exponents plain", "[runtime][misuse]") {
  CHECK(number_text(1e37) == "1e37");
  CHECK(number_text(1e-30) == "1e-30");
  CHECK(number_text(-1) == "-1");
  CHECK(number_text(0.1) == "0.1");
  CHECK(number_text(1.0 / 3) == "0.33333333333333331");
  CHECK(number_text(std::nextafter(1e37, 2e37)) == "1.0000000000000001e37");
  CHECK(number_text(std::nan("")) == "nan");
  CHECK(number_text(-INFINITY) == "-inf");
  CHECK(std::strtod(number_text(5e-324).c_str(), nullptr) == 5e-324);
}
