// Closest points on the exact limit surface (ClosestPointQuery) against
// independent oracles: for Catmull-Clark, a brute force on OpenSubdiv's Bfr
// (every face sampled densely, the best samples polished by projected
// Gauss-Newton with Bfr's own derivatives, the minimum over all faces); for
// nonpoly, dense exact limit points. Signs against the mesh's inside.
#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <iterator>
#include <map>
#include <fstream>
#include <sstream>
#include <random>

#include "bfr_distance.hpp"
#include "distance/affine_enclosure.hpp"
#include "distance/convex_bound.hpp"
#include "open_meshes.hpp"
#include "cli.hpp"
#include "runtime_api.hpp"
#include "stencil_runtime/closest_point.hpp"
#include "stencil_runtime/mesh_io.hpp"
#include "stencil_runtime/tessellation.hpp"

using namespace stencil_runtime;
using test_runtime::surface_of;
namespace osd = OpenSubdiv::OPENSUBDIV_VERSION;

using bfr_reference::BfrOracle;

namespace {

const std::filesystem::path kMeshes = std::filesystem::path(STENCIL_SOURCE_DIR) / "meshes";

double distance(const Point& a, const Point& b) { return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }

double diagonal_of(const Mesh& mesh) {
  Point lo = mesh.positions[0], hi = lo;
  for (const Point& p : mesh.positions)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  return distance(lo, hi);
}

}  // namespace

namespace {

// Closest points on every mesh against the Bfr brute force of the same scheme.
void check_against_bfr(const std::shared_ptr<const Tables>& tables, osd::Sdc::SchemeType scheme,
                       std::initializer_list<const char*> meshes) {
  const bool triangles = scheme == osd::Sdc::SCHEME_LOOP;
  for (const char* name : meshes) {
    const Mesh mesh = read_obj((kMeshes / name).string());
    // The big meshes get fewer queries (the brute force samples every face).
    const int per_kind = mesh.face_count() > 100 ? 3 : 12;
    const Surface surface = surface_of(tables, mesh);
    const ClosestPointQuery query(surface);
    const BfrOracle oracle(mesh, scheme);
    const double diagonal = diagonal_of(mesh);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(-1, 1);
    std::vector<Point> queries;
    // Near the surface, far away, on it, next to the valence-3 corners of the cube, and on the medial axis (the centre).
    for (int i = 0; i < per_kind; ++i) {
      const std::size_t f = static_cast<std::size_t>(i * 37) % mesh.face_count();
      const double u = (1 + i % 5) / (triangles ? 14.0 : 7.0), v = (2 + i % 3) / 9.0;  // inside a triangle too
      const Point on = surface.evaluate(f, u, v, 1e-14 * diagonal).point;
      queries.push_back(on);
      queries.push_back({on[0] + 0.05 * diagonal * unit(rng), on[1] + 0.05 * diagonal * unit(rng), on[2] + 0.05 * diagonal * unit(rng)});
      queries.push_back({3 * diagonal * unit(rng), 3 * diagonal * unit(rng), 3 * diagonal * unit(rng)});
      const Point corner = surface.evaluate(f, 1.0 / 512, 1.0 / 1024, 1e-14 * diagonal).point;
      queries.push_back({corner[0] * (1 + 0.02 * unit(rng)), corner[1] * (1 + 0.02 * unit(rng)), corner[2] * (1 + 0.02 * unit(rng))});
    }
    queries.push_back({0, 0, 0});
    const std::vector<ClosestPoint> got = query.find(queries);
    for (std::size_t i = 0; i < queries.size(); ++i) {
      const double expected = oracle.distance_to(queries[i]);
      INFO(name << " query " << i << " (" << queries[i][0] << ", " << queries[i][1] << ", " << queries[i][2] << ")");
      REQUIRE(got[i].found);
      INFO(std::setprecision(17) << "ours " << got[i].distance << " oracle " << expected << " accuracy " << got[i].accuracy
                                 << " at face " << got[i].face << " (" << got[i].u << ", " << got[i].v << ")");
      CHECK(std::fabs(got[i].distance - expected) <= 1e-9 * diagonal);
      // The reported point is the surface at the reported parameter, at the reported distance.
      const Evaluation at = surface.evaluate(got[i].face, got[i].u, got[i].v, 1e-13 * diagonal);
      CHECK(distance(at.point, got[i].point) <= 1e-11 * diagonal);
      CHECK(std::fabs(distance(got[i].point, queries[i]) - got[i].distance) <= 1e-12 * diagonal);
      // The normal is Bfr's du x dv there (the faces are outward-oriented quads, Bfr's parameters are ours).
      Point p{}, du{}, dv{};
      oracle.evaluate(got[i].face, got[i].u, got[i].v, p, du, dv);
      const Point n{du[1] * dv[2] - du[2] * dv[1], du[2] * dv[0] - du[0] * dv[2], du[0] * dv[1] - du[1] * dv[0]};
      const double len = distance(n, {0, 0, 0});
      // Not at a degenerate point of the parametrisation (an extraordinary
      // vertex), nor within 2^-(level - 1) of a corner: Bfr's patches there are
      // Gregory approximations below its approximation level (measured: normals
      // 1e-5 off at 1e-4 from a Loop EV, where positions still agree to 1e-9).
      const double u = got[i].u, v = got[i].v, corner = std::ldexp(1.0, 1 - bfr_reference::kApproxLevel);
      const bool near_corner = triangles ? std::min({std::hypot(u, v), std::hypot(1 - u, v), std::hypot(u, 1 - v)}) < corner
                                         : std::min({std::hypot(u, v), std::hypot(1 - u, v), std::hypot(u, 1 - v), std::hypot(1 - u, 1 - v)}) < corner;
      if (len > 1e-9 * diagonal * diagonal && !near_corner)
        CHECK(distance(got[i].normal, Point{n[0] / len, n[1] / len, n[2] / len}) <= 1e-8);
    }
  }
}

}  // namespace

TEST_CASE("Catmull-Clark closest points equal a brute force on OpenSubdiv Bfr", "[runtime][distance]") {
  const auto cc = Tables::load(generated_table("catmull-clark", "--valence 3-8 --n 16", "sgs").string());
  check_against_bfr(cc, osd::Sdc::SCHEME_CATMARK, {"cube.obj", "torus-3-5.obj", "chess-piece.obj", "rook.obj"});
}

TEST_CASE("Loop closest points equal a brute force on OpenSubdiv Bfr", "[runtime][distance]") {
  const auto loop = Tables::load(generated_table("loop", "--valence 3-8 --n 8", "sgt").string());
  check_against_bfr(loop, osd::Sdc::SCHEME_LOOP, {"icosahedron.obj", "tri-torus.obj", "tri-mix.obj"});
}

namespace {

// A scheme without a polynomial basis (no Bfr): distances never above the
// nearest of dense exact limit points, points on the surface, residuals
// orthogonal to it inside the face, signs by the centre of the icosahedron.
void check_against_dense_points(const std::shared_ptr<const Tables>& tables, int dense, bool exact_tangents) {
  const Mesh mesh = read_obj((kMeshes / "icosahedron.obj").string());
  const Surface surface = surface_of(tables, mesh);
  const ClosestPointQuery query(surface);
  const double diagonal = diagonal_of(mesh);
  // Dense exact limit points: every face on the grid 1/dense.
  std::vector<Point> points;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const FaceDomain d = surface.topology().domain(f);
    for (int j = 0; j <= dense; ++j)
      for (int i = 0; i <= dense; ++i)
        if (d.contains(ExactParameter{Fraction::make(i, dense), Fraction::make(j, dense)}))
          points.push_back(surface.evaluate(f, ExactParameter{Fraction::make(i, dense), Fraction::make(j, dense)}));
  }
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(-1, 1);
  int orthogonal_checked = 0;
  for (int i = 0; i < 40; ++i) {
    const Point q{0.8 * diagonal * unit(rng), 0.8 * diagonal * unit(rng), 0.8 * diagonal * unit(rng)};
    const ClosestPoint r = query.find(q);
    REQUIRE(r.found);
    double nearest = INFINITY;
    for (const Point& p : points) nearest = std::min(nearest, distance(p, q));
    CHECK(r.distance <= nearest + query.tolerance());
    const Evaluation at = surface.evaluate(r.face, r.u, r.v, 1e-13 * diagonal);
    CHECK(distance(at.point, r.point) <= 1e-11 * diagonal);
    // Inside the face's domain the residual is orthogonal to the surface.
    // Tangents by central differences of exact evaluations: nonpoly's surface
    // is C1 but its derivatives are only Hoelder continuous, so differences
    // converge slowly (measured: about 1e-3 h), and at h = 1e-6 they check
    // orthogonality to about 1e-7 (the search itself reaches 1e-12 with the
    // exact derivatives; without its final refinement the cosines here are
    // 1e-5 to 1e-4).
    const FaceDomain domain = surface.topology().domain(r.face);
    constexpr double h = 1e-6;
    bool inside = true;
    for (double du : {-2 * h, 2 * h})
      for (double dv : {-2 * h, 2 * h}) inside = inside && domain.contains(r.u + du, r.v + dv);
    if (inside && r.distance > 1e-6 * diagonal) {
      auto at_uv = [&](double u, double v) { return surface.evaluate(r.face, u, v, 1e-15 * diagonal).point; };
      const Point a = at_uv(r.u - h, r.v), b = at_uv(r.u + h, r.v), c = at_uv(r.u, r.v - h), d = at_uv(r.u, r.v + h);
      const Point tu{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, tv{d[0] - c[0], d[1] - c[1], d[2] - c[2]};
      const Point res{q[0] - r.point[0], q[1] - r.point[1], q[2] - r.point[2]};
      auto cosine = [&](const Point& t) {
        return std::fabs(res[0] * t[0] + res[1] * t[1] + res[2] * t[2]) / (distance(res, {0, 0, 0}) * distance(t, {0, 0, 0}));
      };
      INFO("cosines " << cosine(tu) << " " << cosine(tv));
      CHECK(cosine(tu) <= 1e-6);
      CHECK(cosine(tv) <= 1e-6);
      ++orthogonal_checked;
      // Against the exact tangents at the returned parameters (nonpoly: any parameter, through the orbit
      // under halving; sqrt(3) has none yet): the residual's component along them. The search stops when
      // the distance is certified, not at orthogonality, and nonpoly's derivatives are only Hoelder
      // continuous, so the component does not fall with the parameter error as it would for a polynomial
      // patch; measured: at most 3.1e-8 of the diagonal (issue 15 asks 1e-9: not met for nonpoly).
      if (exact_tangents) {
        const Derivatives d = surface.derivatives(r.face, r.u, r.v);
        const double along_u = cosine(d.du) * r.distance / diagonal, along_v = cosine(d.dv) * r.distance / diagonal;
        INFO("tangential residual / diagonal " << along_u << " " << along_v);
        CHECK(along_u <= 1e-7);
        CHECK(along_v <= 1e-7);
      }
    }
    // The icosahedron's limit surface is closed and convex-ish around the origin: signs by a ray to the centre.
    if (distance(q, {0, 0, 0}) < 0.1 * diagonal) CHECK(r.signed_distance < 0);
    if (distance(q, {0, 0, 0}) > diagonal) CHECK(r.signed_distance > 0);
  }
  CHECK(orthogonal_checked >= 20);
}

}  // namespace

TEST_CASE("nonpoly closest points are never farther than dense exact limit points, and lie on the surface",
          "[runtime][distance]") {
  check_against_dense_points(Tables::load(generated_table("nonpoly", "--valence 3-8 --n 16", "sgs").string()), 16, true);
}

TEST_CASE("sqrt(3) closest points are never farther than dense exact limit points, and lie on the surface",
          "[runtime][distance]") {
  check_against_dense_points(Tables::load(generated_table("sqrt3", "--valence 3-8 --n 1,3,9,27", "sgt").string()), 27, false);
}

// Whether a ray from q along +x crosses the triangles an odd number of times
// (Moeller-Trumbore; the direction is perturbed off the axes so that it meets
// no edge exactly).
bool inside_by_parity(const PolygonSoup& soup, const Point& q) {
  const Point dir{1, 0.000123, 0.000071};
  int crossings = 0;
  auto cross3 = [](const Point& a, const Point& b) {
    return Point{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  };
  auto dot3 = [](const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  auto test = [&](int ia, int ib, int ic) {
    const auto& A = soup.positions[static_cast<std::size_t>(ia)];
    const auto& B = soup.positions[static_cast<std::size_t>(ib)];
    const auto& C = soup.positions[static_cast<std::size_t>(ic)];
    const Point a{A[0], A[1], A[2]}, e1{B[0] - a[0], B[1] - a[1], B[2] - a[2]}, e2{C[0] - a[0], C[1] - a[1], C[2] - a[2]};
    const Point pv = cross3(dir, e2);
    const double det = dot3(e1, pv);
    if (std::fabs(det) < 1e-300) return;
    const Point tv{q[0] - a[0], q[1] - a[1], q[2] - a[2]};
    const double u = dot3(tv, pv) / det;
    if (u < 0 || u > 1) return;
    const Point qv = cross3(tv, e1);
    const double v = dot3(dir, qv) / det;
    if (v < 0 || u + v > 1) return;
    if (dot3(e2, qv) / det > 0) ++crossings;
  };
  for (const auto& t : soup.triangles) test(t[0], t[1], t[2]);
  for (const auto& f : soup.quads) test(f[0], f[1], f[2]), test(f[0], f[2], f[3]);
  return crossings % 2 == 1;
}

// Signed distances against inside/outside by ray parity on a fine exact
// tessellation (rate 16 or 27: within 1e-4 of the diagonal of the surface), for
// points farther than 1e-2 of the diagonal from the surface.
namespace {

// The bundled icosahedron split twice at its edges' midpoints (320 faces) and
// projected onto an ellipsoid with axes 1, 0.7, 0.5: a mesh like CGAL's
// ellipsoid.off, on which Loop closest points came back a few ulps outside
// their faces.
Mesh split_ellipsoid() {
  Mesh mesh = read_obj((kMeshes / "icosahedron.obj").string());
  for (int step = 0; step < 2; ++step) {
    std::map<std::pair<int, int>, int> middle;
    const auto at = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      const auto [it, added] = middle.emplace(key, static_cast<int>(mesh.positions.size()));
      if (added) {
        const Point& p = mesh.positions[static_cast<std::size_t>(a)];
        const Point& q = mesh.positions[static_cast<std::size_t>(b)];
        mesh.positions.push_back({(p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2});
      }
      return it->second;
    };
    std::vector<int> faces;
    for (std::size_t f = 0; f < mesh.face_count(); ++f) {
      const int a = mesh.face_vertices[3 * f], b = mesh.face_vertices[3 * f + 1], c = mesh.face_vertices[3 * f + 2];
      const int ab = at(a, b), bc = at(b, c), ca = at(c, a);
      faces.insert(faces.end(), {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca});
    }
    mesh.face_vertices = faces;
    mesh.face_sizes.assign(faces.size() / 3, 3);
  }
  for (Point& p : mesh.positions) {
    const double r = std::hypot(p[0], p[1], p[2]);
    p = {p[0] / r, 0.7 * p[1] / r, 0.5 * p[2] / r};
  }
  return mesh;
}

}  // namespace

TEST_CASE("closest points on and near the faces' borders come back inside the faces' domains", "[runtime][distance]") {
  // The parameter maps from a prepared face back to the original one round:
  // a Loop closest point on CGAL's ellipsoid came back at v = -2.8e-17, which
  // evaluation (and so a fit, or stencileval) refuses. On the split ellipsoid
  // below 6 of these 3,960 queries did.
  const auto quad = Tables::load(generated_table("catmull-clark", "--valence 3-8 --n 8", "sgs").string());
  const auto loop = Tables::load(generated_table("loop", "--valence 3-8 --n 8", "sgt").string());
  struct Case {
    std::shared_ptr<const Tables> tables;
    std::string name;
    Mesh mesh;
  };
  std::vector<Case> cases{{loop, "split ellipsoid", split_ellipsoid()}};
  for (const char* name : {"icosahedron.obj", "tri-mix.obj"}) cases.push_back({loop, name, read_obj((kMeshes / name).string())});
  for (const char* name : {"cube.obj", "chess-piece.obj"}) cases.push_back({quad, name, read_obj((kMeshes / name).string())});
  for (const Case& c : cases) {
    INFO(c.name);
    const Surface surface = surface_of(c.tables, c.mesh);
    const ClosestPointQuery query(surface);
    const double diagonal = diagonal_of(c.mesh);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> unit(0, 1);
    std::vector<Point> queries;
    // The surface's points on two borders of every face (u = 0, v = 0) and on the third (u = 1, or the hypotenuse).
    for (std::size_t f = 0; f < c.mesh.face_count(); ++f) {
      const FaceDomain d = surface.topology().domain(f);
      const double t = unit(rng);
      for (const auto& [u, v] : {std::array<double, 2>{t, 0}, {0, t}, {d.kind == FaceDomain::Kind::Triangle ? 1 - t : 1.0, t}})
        if (d.contains(u, v)) queries.push_back(surface.evaluate(f, u, v, 0).point);
    }
    // And points in a box 1.4 times the mesh's.
    Point lo = c.mesh.positions[0], hi = lo;
    for (const Point& p : c.mesh.positions)
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
    for (int n = 0; n < 3000; ++n) {
      Point q;
      for (int k = 0; k < 3; ++k) q[k] = lo[k] + (1.4 * unit(rng) - 0.2) * (hi[k] - lo[k]);
      queries.push_back(q);
    }
    std::size_t outside = 0;
    for (const ClosestPoint& r : query.find(queries)) {
      REQUIRE(r.found);
      if (!surface.topology().domain(r.face).contains(r.u, r.v)) {
        if (++outside <= 3) UNSCOPED_INFO("face " << r.face << " at " << std::setprecision(17) << r.u << ", " << r.v);
        continue;
      }
      CHECK(distance(surface.evaluate(r.face, r.u, r.v, 0).point, r.point) <= 1e-12 * diagonal);
    }
    CHECK(outside == 0);
  }
}

TEST_CASE("signed distances are negative exactly inside every bundled closed mesh", "[runtime][distance]") {
  struct Case {
    const char* scheme;
    const char* extension;
    std::vector<const char*> meshes;
  };
  const std::vector<const char*> quads{"cube.obj", "torus-3-5.obj", "chess-piece.obj", "bumpy-sphere.obj", "rook.obj"};
  const std::vector<const char*> triangles{"icosahedron.obj", "tri-torus.obj", "tri-mix.obj"};
  for (const Case& c : {Case{"catmull-clark", "sgs", quads}, Case{"nonpoly", "sgs", quads}, Case{"loop", "sgt", triangles},
                        Case{"sqrt3", "sgt", triangles}}) {
    const char* scheme = c.scheme;
    // sqrt(3)'s tessellation rates are multiples of 3 apart: 1..27 holds 16 only in part, so its grid is 27.
    const bool sqrt3 = std::string(scheme) == "sqrt3";
    const int rate = sqrt3 ? 27 : 16;
    const auto tables = Tables::load(generated_table(scheme, sqrt3 ? "--valence 3-8 --n 1,3,9,27" : "--valence 3-8 --n 16", c.extension).string());
    for (const char* name : c.meshes) {
      CAPTURE(scheme, name);
      const Mesh mesh = read_obj((kMeshes / name).string());
      const Surface surface = surface_of(tables, mesh);
      const ClosestPointQuery query(surface);
      const PolygonSoup soup = tessellate(surface, std::vector<int>(mesh.face_count(), rate));
      const double diagonal = diagonal_of(mesh);
      Point lo = mesh.positions[0], hi = lo;
      for (const Point& p : mesh.positions)
        for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
      std::mt19937 rng(3);
      std::uniform_real_distribution<double> unit(-0.1, 1.1);
      int inside = 0, outside = 0;
      for (int i = 0; i < 300; ++i) {
        const Point q{lo[0] + unit(rng) * (hi[0] - lo[0]), lo[1] + unit(rng) * (hi[1] - lo[1]), lo[2] + unit(rng) * (hi[2] - lo[2])};
        const ClosestPoint r = query.find(q);
        REQUIRE(r.found);
        if (r.distance < 1e-2 * diagonal) continue;
        const bool in = inside_by_parity(soup, q);
        INFO("query (" << q[0] << ", " << q[1] << ", " << q[2] << ") distance " << r.signed_distance);
        CHECK((r.signed_distance < 0) == in);
        ++(in ? inside : outside);
      }
      CHECK(inside >= 5);
      CHECK(outside >= 5);
    }
  }
}

// Infinitely sharp edges make creases and corners in the surface, where the
// faces on either side have different normals: the side of a point whose
// nearest surface point is on a crease or a corner follows from the normals
// of all the faces there (their angle-weighted sum), not from the one face the
// search found it in (whose normal may be orthogonal to the residual: a point
// in the plane of a flat face, just beyond its sharp edge). Query points on
// and next to the planes of the control cube's faces, against ray parity on a
// fine tessellation.
TEST_CASE("signed distances next to infinitely sharp creases and corners follow every face there", "[runtime][distance]") {
  const std::string cube_text = [] {
    std::ifstream in(kMeshes / "cube.obj");
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }();
  // A crease loop round the face x = -0.5 (corners 0 1 3 2), and every edge of the cube sharp.
  const std::string loop = cube_text + "t crease 5/4/0 0 1 3 2 0 10 10 10 10\n";
  std::string all = cube_text;
  for (const char* e : {"0 1", "1 3", "3 2", "2 0", "4 5", "5 7", "7 6", "6 4", "0 4", "1 5", "2 6", "3 7"})
    all += std::string("t crease 2/1/0 ") + e + " 10\n";
  // Loop: the cube's quads split into triangles, every cube edge sharp.
  std::string triangles;
  for (const char* line : {"v -0.5 -0.5 -0.5", "v -0.5 -0.5 0.5", "v -0.5 0.5 -0.5", "v -0.5 0.5 0.5", "v 0.5 -0.5 -0.5",
                            "v 0.5 -0.5 0.5", "v 0.5 0.5 -0.5", "v 0.5 0.5 0.5", "f 1 3 7", "f 1 7 5", "f 2 6 8", "f 2 8 4",
                            "f 1 5 6", "f 1 6 2", "f 3 4 8", "f 3 8 7", "f 1 2 4", "f 1 4 3", "f 5 7 8", "f 5 8 6"})
    triangles += std::string(line) + "\n";
  triangles += all.substr(cube_text.size());
  const auto dir = scratch_dir("sharp-signs");
  int near_crease = 0;
  struct Case {
    const char* scheme;
    const char* extension;
    std::vector<std::pair<const char*, std::string>> meshes;
  };
  for (const Case& c : {Case{"catmull-clark", "sgs", {{"crease-loop", loop}, {"all-sharp", all}}},
                        Case{"nonpoly", "sgs", {{"crease-loop", loop}, {"all-sharp", all}}},
                        Case{"loop", "sgt", {{"all-sharp-triangles", triangles}}}}) {
    const char* scheme = c.scheme;
    const auto tables = Tables::load(generated_table(scheme, "--valence 3-8 --n 16", c.extension).string());
    for (const auto& [name, text] : c.meshes) {
      CAPTURE(scheme, name);
      const auto path = dir / (std::string(name) + ".obj");
      std::ofstream(path) << text;
      const Mesh mesh = read_obj(path.string());
      const Surface surface(SurfaceTopology::create(tables, mesh), mesh.positions);
      const ClosestPointQuery query(surface);
      const PolygonSoup soup = tessellate(surface, std::vector<int>(mesh.face_count(), 16));
      const double diagonal = diagonal_of(mesh);
      for (int axis = 0; axis < 3; ++axis)
        for (double plane : {-0.5, 0.5})
          for (double offset : {-1e-9, 0.0, 1e-9})
            for (int i = 0; i <= 8; ++i)
              for (int j = 0; j <= 8; ++j) {
                Point q{0, 0, 0};
                q[axis] = plane + offset;
                q[(axis + 1) % 3] = -0.95 + 0.2375 * i;
                q[(axis + 2) % 3] = -0.95 + 0.2375 * j;
                const ClosestPoint r = query.find(q);
                REQUIRE(r.found);
                if (r.distance < 1e-2 * diagonal) continue;  // parity on the tessellation is not reliable there
                const bool in = inside_by_parity(soup, q);
                INFO("query (" << q[0] << ", " << q[1] << ", " << q[2] << ") signed distance " << r.signed_distance << ", normal . residual "
                               << (q[0] - r.point[0]) * r.normal[0] + (q[1] - r.point[1]) * r.normal[1] + (q[2] - r.point[2]) * r.normal[2]);
                CHECK((r.signed_distance < 0) == in);
                // Where the residual is nearly in the found face's tangent plane, only the other faces decide.
                const Point res{q[0] - r.point[0], q[1] - r.point[1], q[2] - r.point[2]};
                if (std::fabs(res[0] * r.normal[0] + res[1] * r.normal[1] + res[2] * r.normal[2]) < 1e-3 * r.distance) ++near_crease;
              }
    }
  }
  CHECK(near_crease >= 8);  // the cases the found face's normal alone gets wrong half the time
}

// A sub-patch `depth` scheme steps below a random prepared face's patch, down random children.
SubPatch random_sub_patch(const Surface& surface, std::mt19937& rng, int depth) {
  const Family& family = surface.topology().family();
  std::uniform_int_distribution<std::size_t> face(0, surface.topology().prepared_face_count() - 1);
  SubPatch s;
  family.root(face(rng), surface.prepared_positions().data(), s);
  SubPatch children[kMaxSubPatchChildren];
  for (int level = 0; level < depth; ++level) {
    const int n = family.split(s, children);
    s = children[std::uniform_int_distribution<int>(0, n - 1)(rng)];
  }
  return s;
}

// The patch parameter at own coordinates (X, Y) of a sub-patch's unit square
// or triangle, for X, Y in [0, 1]: a triangle folds the square's far half.
std::array<double, 2> sub_patch_point(const SubPatch& s, double X, double Y) {
  if (s.domain.triangle && X + Y > 1) X = 1 - X, Y = 1 - Y;
  return s.domain.at(X, Y);
}

// Exact evaluations of a sub-patch at the nodes of an n x n grid of its own
// frame (the unit square, or the unit triangle's half of it), with their own coordinates.
struct FrameSamples {
  std::vector<std::array<double, 2>> at;
  std::vector<Point> points;
};
FrameSamples frame_samples(const Family& family, const SubPatch& s, int n, double tolerance) {
  FrameSamples out;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= (s.domain.triangle ? n - j : n); ++i) {
      const double X = double(i) / n, Y = double(j) / n;
      const auto p = s.domain.at(X, Y);
      out.at.push_back({X, Y});
      out.points.push_back(family.evaluate(s, p[0], p[1], tolerance).point);
    }
  return out;
}

// The scheme, its tables and the mesh each sub-patch test runs on.
struct SubPatchCase {
  const char* scheme;
  const char* options;
  const char* extension;
  const char* mesh;
  int regular_kind;
  int extraordinary_kind;
};
const SubPatchCase kSubPatchCases[] = {
    {"catmull-clark", "--valence 3-8 --n 16", "sgs", "chess-piece.obj", 4, 5},
    {"nonpoly", "--valence 3-8 --n 16", "sgs", "chess-piece.obj", 4, 5},
    {"loop", "--valence 3-8 --n 8", "sgt", "tri-mix.obj", 6, 5},
};

// The affine enclosure (distance/affine_enclosure.hpp) against dense exact
// evaluations of the sub-patch it bounds: never above the nearest of them,
// and, being of second order, close to it for small sub-patches.
TEST_CASE("the affine enclosure bounds every sampled sub-patch from below and tightens with depth", "[runtime][distance]") {
  for (const SubPatchCase& tc : kSubPatchCases) {
    CAPTURE(tc.scheme);
    const Mesh mesh = read_obj((kMeshes / tc.mesh).string());
    const auto tables = Tables::load(generated_table(tc.scheme, tc.options, tc.extension).string());
    const Surface surface = surface_of(tables, mesh);
    const Family& family = surface.topology().family();
    const AffineParameters* affine = family.affine_parameters(tc.regular_kind);
    REQUIRE(affine != nullptr);
    CHECK(affine->residual < 1e-12);
    CHECK(family.affine_parameters(tc.extraordinary_kind) == nullptr);
    const AffineEnclosure enclosure(*affine);
    const double diagonal = diagonal_of(mesh);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> unit(-1, 1);
    int tested = 0;
    double worst_gap_deep = 0, worst_gap_shallow = 0;  // how far below the sampled minimum the bound is, at depths 5 and 1
    while (tested < 60) {
      const int depth = tested % 6;
      const SubPatch s = random_sub_patch(surface, rng, depth);
      if (s.kind != tc.regular_kind) continue;  // only regular sub-patches have the enclosure
      ++tested;
      const std::vector<Point> samples = frame_samples(family, s, 24, 1e-14 * diagonal).points;
      const Point centre = samples[samples.size() / 2];
      for (int k = 0; k < 20; ++k) {
        const double reach = (k < 10 ? 0.01 : 0.5) * diagonal;
        const Point q{centre[0] + reach * unit(rng), centre[1] + reach * unit(rng), centre[2] + reach * unit(rng)};
        double nearest = INFINITY;
        for (const Point& p : samples) nearest = std::min(nearest, distance(p, q));
        const double bound = enclosure.lower_bound(s.points, q);
        CHECK(bound <= nearest + 1e-12 * diagonal);
        if (depth == 5) worst_gap_deep = std::max(worst_gap_deep, nearest - bound);
        if (depth == 1) worst_gap_shallow = std::max(worst_gap_shallow, nearest - bound);
      }
    }
    // A depth-5 sub-patch spans 1/32 of a face: its bound is within 1e-3 of
    // the diagonal of the samples' minimum, and, the residuals being of second
    // order, 4 levels below depth 1 the gap is far smaller (1/256 ideally).
    CHECK(worst_gap_deep < 1e-3 * diagonal);
    CHECK(worst_gap_deep < worst_gap_shallow / 16);
  }
}

// The convexity bound (distance/convex_bound.hpp): the polynomial a family
// declares for its regular sub-patches is their surface (against the family's
// exact evaluation from the tables), the point Newton returns lies on that
// surface, and wherever the squared distance is certified convex the bound
// is never above the nearest of dense exact samples, and close to it; the
// bound with a negative lambda (not convex) is never above them either.
TEST_CASE("the convexity bound holds below dense samples of every sub-patch it certifies", "[runtime][distance]") {
  for (const SubPatchCase& tc : kSubPatchCases) {
    CAPTURE(tc.scheme);
    const Mesh mesh = read_obj((kMeshes / tc.mesh).string());
    const auto tables = Tables::load(generated_table(tc.scheme, tc.options, tc.extension).string());
    const Surface surface = surface_of(tables, mesh);
    const Family& family = surface.topology().family();
    const PolynomialPatch* polynomial = family.polynomial_patch(tc.regular_kind);
    CHECK(family.polynomial_patch(tc.extraordinary_kind) == nullptr);
    if (std::string(tc.scheme) == "nonpoly") {  // its regular patch is no polynomial
      CHECK(polynomial == nullptr);
      continue;
    }
    REQUIRE(polynomial != nullptr);
    const ConvexBound convex(*polynomial);
    REQUIRE(!convex.empty());
    const double diagonal = diagonal_of(mesh);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> unit(-1, 1);
    int tested = 0, certified = 0, tight = 0, near_deep = 0, near_deep_certified = 0, nonconvex_bounds = 0;
    while (tested < 60) {
      const int depth = tested % 5;
      const SubPatch s = random_sub_patch(surface, rng, depth);
      if (s.kind != tc.regular_kind) continue;
      ++tested;
      const FrameSamples frame = frame_samples(family, s, 32, 1e-14 * diagonal);
      const std::vector<Point>& samples = frame.points;
      for (std::size_t n = 0; n < samples.size(); ++n) {
        // The declared polynomial at the same own coordinates.
        const double X = frame.at[n][0], Y = frame.at[n][1];
        Point p{0, 0, 0};
        for (std::size_t h = 0; h < s.points.size(); ++h)
          for (std::size_t m = 0; m < polynomial->monomials.size(); ++m) {
            const double w = polynomial->coefficients[h][m] * std::pow(X, polynomial->monomials[m][0]) *
                             std::pow(Y, polynomial->monomials[m][1]);
            for (int k = 0; k < 3; ++k) p[k] += w * s.points[h][k];
          }
        REQUIRE(distance(p, samples[n]) <= 1e-12 * diagonal);
      }
      ConvexBound::Prepared prepared;
      convex.prepare(s.points, prepared);
      const Point centre = samples[samples.size() / 2];
      double size = 0;
      for (const Point& p : samples) size = std::max(size, distance(p, centre));
      for (int k = 0; k < 24; ++k) {
        // Near the sub-patch (on both sides, within and beyond its curvature's reach) and far away.
        const double reach = (k < 8 ? 0.5 : k < 16 ? 4.0 : 100.0) * size;
        const Point q{centre[0] + reach * unit(rng), centre[1] + reach * unit(rng), centre[2] + reach * unit(rng)};
        double nearest = INFINITY;
        for (const Point& p : samples) nearest = std::min(nearest, distance(p, q));
        const ConvexBound::Result r = convex.bound(prepared, q, INFINITY);  // INFINITY: always Newton's point
        const auto at = s.domain.at(r.X, r.Y);
        INFO("depth " << depth << " query " << k << " distance " << nearest << " bound " << r.lower);
        CHECK(s.domain.contains(at[0], at[1], 1e-12));
        CHECK(distance(r.point, family.evaluate(s, at[0], at[1], 1e-14 * diagonal).point) <= 1e-12 * diagonal);
        CHECK(std::fabs(distance(r.point, q) - r.distance) <= 1e-12 * diagonal);
        if (depth >= 3 && k < 8) ++near_deep, near_deep_certified += r.convex ? 1 : 0;
        // At the centre, with the bound made also where F is not convex (a negative lambda).
        const ConvexBound::Result centre_bound = convex.bound(prepared, q, 0.0);
        REQUIRE(centre_bound.bounded);
        CHECK(centre_bound.lower <= nearest + 1e-12 * diagonal);
        if (!centre_bound.convex && centre_bound.lower > 0) ++nonconvex_bounds;
        if (!r.convex) continue;
        ++certified;
        CHECK(r.lower <= nearest + 1e-12 * diagonal);
        // Certified convex: the squared distance is midpoint-convex along chords of the frame.
        const auto squared = [&](double X, double Y) {
          const auto p = s.domain.at(X, Y);
          const double d = distance(family.evaluate(s, p[0], p[1], 1e-15 * diagonal).point, q);
          return d * d;
        };
        std::uniform_real_distribution<double> own(0, 1);
        for (int chord = 0; chord < 8; ++chord) {
          double ax = own(rng), ay = own(rng), bx = own(rng), by = own(rng);
          if (s.domain.triangle && ax + ay > 1) ax = 1 - ax, ay = 1 - ay;
          if (s.domain.triangle && bx + by > 1) bx = 1 - bx, by = 1 - by;
          const double fa = squared(ax, ay), fb = squared(bx, by), fm = squared(0.5 * (ax + bx), 0.5 * (ay + by));
          CHECK(fm <= 0.5 * (fa + fb) + 1e-12 * diagonal * diagonal);
        }
        // The samples are 1/32 apart: their minimum is within a second-order step of the true one.
        // Newton's point is the sub-patch's nearest: the bound is its distance.
        if (r.lower >= r.distance - 1e-9 * size) ++tight;
      }
    }
    // Nearly every query within half a sub-patch's size of a small sub-patch
    // is certified (the squared distance is convex there), and the certified
    // bound is the distance of Newton's point.
    CAPTURE(certified, tight, near_deep, near_deep_certified, nonconvex_bounds);
    CHECK(near_deep_certified >= 0.9 * near_deep);
    CHECK(nonconvex_bounds > 100);  // the bound with a negative lambda is exercised and not vacuous
    CHECK(tight == certified);
  }
}

// Family::derivatives on sub-patches (exact: polynomial patches anywhere,
// non-polynomial ones on the stored grid they snap to) against central
// differences of exact evaluations of the same sub-patch.
// sqrt(3)'s exact sub-patch derivatives sit on the grid 1/(3N) of the
// largest stored rate N (the point moves there); its kinds take no part in
// the enclosure and convexity tests above (it has no polynomial patch).
const SubPatchCase kSqrt3SubPatches = {"sqrt3", "--valence 3-8 --n 1,3,9,27", "sgt", "tri-mix.obj", 6, 5};

TEST_CASE("sub-patch derivatives equal difference quotients of exact evaluations", "[runtime][distance]") {
  std::vector<SubPatchCase> cases(std::begin(kSubPatchCases), std::end(kSubPatchCases));
  cases.push_back(kSqrt3SubPatches);
  for (const SubPatchCase& tc : cases) {
    CAPTURE(tc.scheme);
    const Mesh mesh = read_obj((kMeshes / tc.mesh).string());
    const auto tables = Tables::load(generated_table(tc.scheme, tc.options, tc.extension).string());
    const Surface surface = surface_of(tables, mesh);
    const Family& family = surface.topology().family();
    const double diagonal = diagonal_of(mesh);
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> unit(0.05, 0.95);
    double worst = 0;
    const int trials = std::string(tc.scheme) == "sqrt3" ? 20 : 60;  // its evaluations between grids are slow
    for (int trial = 0; trial < trials; ++trial) {
      const SubPatch s = random_sub_patch(surface, rng, trial % 5);
      // A point away from the border (h below stays inside).
      auto [x, y] = sub_patch_point(s, unit(rng), unit(rng));
      x += 0.02 * (s.domain.centre()[0] - x), y += 0.02 * (s.domain.centre()[1] - y);
      Derivatives d;
      REQUIRE(family.derivatives(s, x, y, d));
      const double size = s.domain.size(), h = 1e-5 * size, tol = 1e-15 * diagonal;
      const Point a = family.evaluate(s, x - h, y, tol).point, b = family.evaluate(s, x + h, y, tol).point;
      const Point c = family.evaluate(s, x, y - h, tol).point, e = family.evaluate(s, x, y + h, tol).point;
      const Point p = family.evaluate(s, x, y, tol).point;
      CHECK(distance(p, d.point) <= 1e-12 * diagonal);
      for (int k = 0; k < 3; ++k) {
        worst = std::max(worst, std::fabs((b[k] - a[k]) / (2 * h) - d.du[k]) * size / diagonal);
        worst = std::max(worst, std::fabs((e[k] - c[k]) / (2 * h) - d.dv[k]) * size / diagonal);
      }
    }
    CHECK(worst < 1e-7);
  }
}

TEST_CASE("a tolerance below what doubles resolve is raised to 1e-14 of the extent, and the query ends",
          "[runtime][distance]") {
  // A fit of points a millionth of the control mesh's size asked for 1e-15 of
  // the mesh, and its first query never ended.
  const auto tables = Tables::load(generated_table("catmull-clark", "--valence 3-8 --n 8", "sgs").string());
  const Mesh mesh = read_obj((kMeshes / "cube.obj").string());
  const Surface surface = surface_of(tables, mesh);
  ClosestPointOptions options;
  options.tolerance = 1e-20;
  const ClosestPointQuery query(surface, options);
  // The prepared control points of the unit cube span between 1 and sqrt(3).
  CHECK(query.tolerance() >= 1e-14);
  CHECK(query.tolerance() <= 2e-14);
  const ClosestPointQuery usual(surface);
  for (const Point& q : {Point{0.1, 0.2, 0.9}, Point{0.3, -0.45, 0.1}, Point{2, 3, -1}}) {
    const ClosestPoint tight = query.find(q), loose = usual.find(q);
    CHECK(tight.distance <= loose.distance + 1e-12);
    CHECK(tight.accuracy <= 1e-12);
  }
}

TEST_CASE("the default tolerance is 1e-9 of the control points' diagonal on a mesh with boundaries too",
          "[runtime][distance][boundary]") {
  // A boundary's phantom points lie beyond the control points, and the default
  // tolerance used to be taken from the prepared points' box: 1.7 times the
  // promise on a CGAL mesh with six boundary edges, one query 1.27e-9 of the
  // diagonal above brute force.
  for (const bool loop : {false, true}) {
    const auto tables = loop ? Tables::load(generated_table("loop", "--valence 3-8 --n 8", "sgt").string())
                             : Tables::load(generated_table("catmull-clark", "--valence 3-8 --n 8", "sgs").string());
    Mesh mesh = test_meshes::open_grid(5, 4);
    if (loop) {  // each quad as two triangles
      Mesh t;
      t.positions = mesh.positions;
      for (std::size_t f = 0; f < mesh.face_count(); ++f) {
        const int* v = &mesh.face_vertices[4 * f];
        for (int tri : {v[0], v[1], v[2], v[0], v[2], v[3]}) t.face_vertices.push_back(tri);
        t.face_sizes.insert(t.face_sizes.end(), {3, 3});
      }
      mesh = t;
    }
    INFO((loop ? "Loop" : "Catmull-Clark"));
    const Surface surface = surface_of(tables, mesh);
    const double diagonal = diagonal_of(mesh);
    CHECK(surface.control_diagonal() == Approx(diagonal).epsilon(1e-14));
    // The premise: the prepared points reach beyond the control points here.
    Point lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
    for (const Point& p : surface.prepared_positions())
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
    CHECK(std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) > 1.05 * diagonal);
    const ClosestPointQuery query(surface);
    CHECK(query.tolerance() <= 1e-9 * diagonal * (1 + 1e-12));
    CHECK(query.tolerance() >= 1e-9 * diagonal * (1 - 1e-12));
  }
}

TEST_CASE("stencildist answers as the library does and refuses bad points files by line", "[runtime][distance][cli]") {
  const std::string tables = generated_table("catmull-clark", "--valence 3-8 --n 8", "sgs").string();
  const std::string cube = (kMeshes / "cube.obj").string();
  const auto dir = scratch_dir("stencildist");
  auto write = [&](const char* name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return (dir / name).string();
  };
  auto dist = [&](const std::string& points, const std::string& extra) {
    return run_command(STENCILDIST_EXE, "--tables " + tables + " --mesh " + cube + " --points " + points + " " + extra);
  };
  const std::string good = write("q.xyz", "# queries\n0.1 0.2 0.9\n\n3 -1 0.5\n0 0 0\n");
  const std::string out = (dir / "r.txt").string();
  const CliResult r = dist(good, "--signed --normals --out " + out);
  INFO(r.output);
  REQUIRE(r.status == 0);
  CHECK(r.output.find("3 points") != std::string::npos);
  std::ifstream lines(out);
  const Surface surface = surface_of(Tables::load(tables), read_obj(cube));
  const ClosestPointQuery query(surface);
  for (const Point& q : {Point{0.1, 0.2, 0.9}, Point{3, -1, 0.5}, Point{0, 0, 0}}) {
    std::size_t face = 0;
    double u = 0, v = 0, d = 0;
    Point p{}, n{};
    REQUIRE(lines >> face >> u >> v >> p[0] >> p[1] >> p[2] >> d >> n[0] >> n[1] >> n[2]);
    const ClosestPoint expected = query.find(q);
    CHECK(face == expected.face);
    CHECK(d == Approx(expected.signed_distance).margin(1e-12));
    CHECK(distance(n, expected.normal) < 1e-9);
  }
  CHECK(query.find(Point{0, 0, 0}).signed_distance < 0);  // inside the cube
  CHECK(query.find(Point{3, -1, 0.5}).signed_distance > 0);
  std::filesystem::remove(out);
  auto refused = [&](const std::string& points, const std::string& message) {
    const CliResult bad = dist(points, "--out " + out);
    INFO(bad.output);
    CHECK(bad.status == 1);
    CHECK(bad.output.find(message) != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(out));
  };
  refused(write("nan.xyz", "0 0 0\nnan 1 2\n"), "nan.xyz:2");
  refused(write("cols.xyz", "0 0 0\n1 2\n"), "cols.xyz:2: expected three numbers");
  refused(write("empty.xyz", "# nothing\n\n"), "no points");
  refused(write("trunc.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\nend_header\nabc"),
          "truncated");
  // A header that declares fewer points than the file holds, as text and in binary, and a line with a value too many.
  const std::string header = "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
  refused(write("more.ply", header + "0 0 0\n1 1 1\n2 2 2\n"), "more.ply:10: more lines than the header's 2 points declare");
  refused(write("wide.ply", header + "0 0 0\n1 1 1 1\n"), "wide.ply:9: more than the 3 values the header declares");
  // A property declared twice (which x is meant?), and faces cut short, as text and in binary.
  refused(write("twice.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
                             "property double x\nend_header\n0 0 0 1\n"),
          "twice.ply:7: vertex property 'x' is declared twice");
  const std::string faces = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                            "element face 2\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n";
  refused(write("cut-faces.ply", faces + "3 0 1 2\n"), "truncated: the file ends after 1 of the 2 lines of the elements after the points (face");
  {
    std::string binary = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                         "element face 2\nproperty list uchar int vertex_indices\nend_header\n";
    const float xyz[9] = {0.1f, 0.2f, 0.9f, 3, -1, 0.5f, 0, 0, 0};
    binary.append(reinterpret_cast<const char*>(xyz), sizeof xyz);
    const int triangle[3] = {0, 1, 2};
    std::string face(1, '\3');
    face.append(reinterpret_cast<const char*>(triangle), sizeof triangle);
    refused(write("cut-faces-binary.ply", binary + face), "truncated: the file ends within face 2 of 2 (binary)");
    refused(write("long-faces-binary.ply", binary + face + face + "x"), "1 bytes after the 3 points the header declares and the elements after them");
    // Both faces whole: read, and the same points as the text file.
    const std::string whole = write("faces-binary.ply", binary + face + face);
    const CliResult r = dist(whole, "--out " + out);
    INFO(r.output);
    CHECK(r.status == 0);
    std::filesystem::remove(out);
  }
  {
    std::string binary = "ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
    const float xyz[9] = {0, 0, 0, 1, 1, 1, 2, 2, 2};
    binary.append(reinterpret_cast<const char*>(xyz), sizeof xyz);
    refused(write("more-binary.ply", binary), "12 bytes after the 2 points the header declares");
    // A coordinate that is not a number is named by its point, counted from 1 as the text files' lines are.
    std::string nan = "ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
    const float values[6] = {0, 0, 0, 1, std::nanf(""), 1};
    nan.append(reinterpret_cast<const char*>(values), sizeof values);
    refused(write("nan-binary.ply", nan), "nan-binary.ply: point 2 of 2 (binary): coordinate");
  }
  {
    const CliResult bad = dist(good, "--out " + good);
    CHECK(bad.status == 1);
    CHECK(bad.output.find("is an input and the output") != std::string::npos);
  }
  refused(good + " --tolerance 1e-300", "at least 1e-14");
  // --signed on a surface that is open: by a boundary, or cut open at a
  // non-manifold edge (it used to say "boundary" for both).
  {
    const std::string vertices = "v -0.5 -0.5 -0.5\nv -0.5 -0.5 0.5\nv -0.5 0.5 -0.5\nv -0.5 0.5 0.5\n"
                                 "v 0.5 -0.5 -0.5\nv 0.5 -0.5 0.5\nv 0.5 0.5 -0.5\nv 0.5 0.5 0.5\n";
    const std::string faces = "f 1 3 7 5\nf 2 6 8 4\nf 1 5 6 2\nf 3 4 8 7\nf 1 2 4 3\n";
    auto signed_on = [&](const char* name, const std::string& obj) {
      return run_command(STENCILDIST_EXE, "--tables " + tables + " --mesh " + write(name, obj) + " --points " + good + " --signed");
    };
    CliResult r = signed_on("open.obj", vertices + faces);
    CHECK(r.status == 1);
    CHECK_THAT(r.output, Catch::Contains("--signed needs a closed surface, and this mesh has a boundary (edge"));
    r = signed_on("three.obj", vertices + faces + "f 5 7 8 6\nf 6 8 7 5\n");  // the last face twice, once flipped
    CHECK(r.status == 1);
    CHECK_THAT(r.output, Catch::Contains("has non-manifold edges (edge") && Catch::Contains("is in 3 faces"));
  }
  // Files from Windows: a byte-order mark and CRLF line ends, in .xyz and in a PLY header, read as the plain file.
  const std::string crlf_ply = write("w.ply", "ply\r\nformat ascii 1.0\r\nelement vertex 3\r\nproperty float x\r\nproperty float y\r\n"
                                               "property float z\r\nend_header\r\n0.1 0.2 0.9\r\n3 -1 0.5\r\n0 0 0\r\n");
  const std::string bom_xyz = write("b.xyz", "\xEF\xBB\xBF" "0.1 0.2 0.9\r\n3 -1 0.5\r\n0 0 0\r\n");
  auto result = [&](const std::string& points) {
    const std::string path = (dir / "result.txt").string();
    const CliResult run = dist(points, "--out " + path);
    INFO(run.output);
    CHECK(run.status == 0);
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    std::filesystem::remove(path);
    return text.str();
  };
  const std::string expected = result(good);
  CHECK(!expected.empty());
  CHECK(result(crlf_ply) == expected);
  CHECK(result(bom_xyz) == expected);
  // Binary PLY in both byte orders (older scanners and the Stanford archive
  // write big-endian): doubles read as the text's numbers; floats alike in
  // both orders. A uchar before x and a face list with 2-byte counts after
  // the points check that every field is read in the file's order.
  {
    const auto in_order = [](const void* value, std::size_t bytes, bool big) {
      std::string raw(static_cast<const char*>(value), bytes);
      if (big != (std::endian::native == std::endian::big)) std::reverse(raw.begin(), raw.end());
      return raw;
    };
    const double xyz[9] = {0.1, 0.2, 0.9, 3, -1, 0.5, 0, 0, 0};
    const auto binary = [&](bool big, bool doubles) {
      const std::string type = doubles ? "double" : "float";
      std::string file = std::string("ply\nformat ") + (big ? "binary_big_endian" : "binary_little_endian") +
                         " 1.0\nelement vertex 3\nproperty uchar flag\nproperty " + type + " x\nproperty " + type +
                         " y\nproperty " + type + " z\nelement face 1\nproperty list ushort int vertex_indices\nend_header\n";
      for (int p = 0; p < 3; ++p) {
        file += '\7';
        for (int k = 0; k < 3; ++k) {
          const float f = static_cast<float>(xyz[3 * p + k]);
          file += doubles ? in_order(&xyz[3 * p + k], 8, big) : in_order(&f, 4, big);
        }
      }
      const std::uint16_t three = 3;
      file += in_order(&three, 2, big);
      for (const std::int32_t v : {0, 1, 2}) file += in_order(&v, 4, big);
      return file;
    };
    CHECK(result(write("be-double.ply", binary(true, true))) == expected);
    CHECK(result(write("le-double.ply", binary(false, true))) == expected);
    const std::string floats = result(write("le-float.ply", binary(false, false)));
    CHECK(!floats.empty());
    CHECK(result(write("be-float.ply", binary(true, false))) == floats);
    // Cut short within the face list: its big-endian count (3) is what the walk reads.
    const std::string whole = binary(true, true);
    refused(write("be-cut.ply", whole.substr(0, whole.size() - 1)), "truncated: the file ends within face 1 of 1 (binary)");
  }
  const std::string with_normals = write("n.xyz", "0.1 0.2 0.9 0 0 1\n3 -1 0.5 1 0 0\n0 0 0 0 1 0\n");
  CHECK(result(with_normals) == expected);  // scanners' `x y z nx ny nz`: the normals are not used
  refused(write("badnormal.xyz", "0 0 0 0 0 1\n1 2 3 0 nan 1\n"), "badnormal.xyz:2");
  std::filesystem::remove_all(dir);
}

TEST_CASE("closest points at a boundary vertex in 3..8 faces, on it and just off it", "[runtime][distance][boundary]") {
  // Newton used to converge to within 2^-64 of the vertex, where the patch
  // descent has no derivative in doubles, and the whole query failed.
  const auto tables = Tables::load(generated_table("catmull-clark", "--valence 3-8 --n 8", "sgs").string());
  for (int k = 3; k <= 8; ++k)
    for (const BoundaryInterpolation option : {BoundaryInterpolation::EdgeOnly, BoundaryInterpolation::EdgeAndCorner}) {
      // k quads fanned round vertex 0 over a half-disc, their outer corners lifted.
      Mesh mesh;
      mesh.positions.push_back({0, 0, 0});
      for (int i = 0; i <= k; ++i) mesh.positions.push_back({std::cos(M_PI * i / k), std::sin(M_PI * i / k), 0});
      for (int i = 0; i < k; ++i) {
        const double a = M_PI * (i + 0.5) / k;
        mesh.positions.push_back({1.5 * std::cos(a), 1.5 * std::sin(a), 0.2 + 0.05 * i});
        mesh.face_sizes.push_back(4);
        for (int v : {0, 1 + i, k + 2 + i, 2 + i}) mesh.face_vertices.push_back(v);
      }
      mesh.tags.boundary = option;
      INFO(k << " faces, " << (option == BoundaryInterpolation::EdgeOnly ? "edge-only" : "edge-and-corner"));
      const Surface surface = surface_of(tables, mesh);
      const ClosestPointQuery query(surface);
      const double diagonal = diagonal_of(mesh);
      const Point limit = surface.evaluate(0, ExactParameter{});  // corner 0 of face 0: the vertex
      // Dense exact limit points: no answer may be farther than their nearest by more than the tolerance.
      std::vector<Point> dense;
      const long n = 48;
      for (std::size_t f = 0; f < mesh.face_count(); ++f)
        for (long j = 0; j <= n; ++j)
          for (long i = 0; i <= n; ++i) dense.push_back(test_runtime::at_grid(surface, f, i, j, n));
      for (const double lift : {0.0, 1e-9, 1e-3, 0.1}) {
        const Point q{limit[0] + 0.3 * lift, limit[1] - lift, limit[2] + lift};
        ClosestPoint c;
        REQUIRE_NOTHROW(c = query.find(q));
        REQUIRE(c.found);
        double nearest = INFINITY;
        for (const Point& p : dense) nearest = std::min(nearest, distance(p, q));
        CHECK(c.distance <= nearest + 1e-9 * diagonal);
        CHECK(distance(surface.evaluate(c.face, c.u, c.v, 0).point, c.point) <= 1e-12 * diagonal);
        if (lift == 0) CHECK(c.distance <= 1e-9 * diagonal);
      }
    }
}
