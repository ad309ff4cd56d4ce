// Derivatives through the runtime (Surface::derivatives): the descent into a
// regular patch and the chain rule through isolation steps, patch rotations and
// the polygon step's sub-faces, against independent references: OpenSubdiv
// Bfr's derivatives of the Catmull-Clark limit surface on every bundled mesh
// and on a mesh with triangles; for nonpoly, agreement of the unit normals of
// the two faces at every edge, and central difference quotients of exact
// limit points converging to du and dv.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "bfr_reference.hpp"
#include "cli.hpp"
#include "mesh/uniform_topology.hpp"
#include "runtime_api.hpp"
#include "runtime_checks.hpp"
#include "stencil_runtime/closest_point.hpp"

using namespace stencil_runtime;
using namespace test_runtime;
namespace fs = std::filesystem;

namespace {

const fs::path kMeshes = fs::path(STENCIL_SOURCE_DIR) / "meshes";
const char* kBundled[] = {"cube", "torus-3-5", "chess-piece", "bumpy-sphere"};

fs::path tables_for(const std::string& scheme) { return generated_table(scheme, "--valence 3-8 --n 24", "sgs"); }

Mesh load(const std::string& name) { return read_obj((kMeshes / (name + ".obj")).string()); }



// The first vertex of each face in face_vertices.
std::vector<std::size_t> face_starts(const Mesh& m) {
  std::vector<std::size_t> s(m.face_count() + 1, 0);
  for (std::size_t f = 0; f < m.face_count(); ++f) s[f + 1] = s[f] + static_cast<std::size_t>(m.face_sizes[f]);
  return s;
}

// Parameters of a face's domain to test: the grid (i/n, j/n) of a quad, the
// same grid in every tile of an N-gon (tiles at (s % U, s / U), half a unit wide).
std::vector<ExactParameter> grid_parameters(const FaceDomain& d, long n) {
  std::vector<ExactParameter> out;
  const int tiles = d.kind == FaceDomain::Kind::Quad ? 1 : d.corners;
  for (int s = 0; s < tiles; ++s)
    for (long j = 0; j <= n; ++j)
      for (long i = 0; i <= n; ++i) {
        if (tiles == 1) out.push_back(grid(i, j, n));
        else
          out.push_back({add(Fraction{s % d.u_tiles, 1}, Fraction::make(i, 2 * n)),
                         add(Fraction{s / d.u_tiles, 1}, Fraction::make(j, 2 * n))});
      }
  return out;
}

// Whether (u, v) is corner c of a quad face whose vertex is extraordinary (no parametric derivative there).
bool at_extraordinary_corner(const Mesh& m, const std::vector<int>& valence, const std::vector<std::size_t>& start,
                             std::size_t f, const ExactParameter& at) {
  const Fraction zero{0, 1}, one{1, 1};
  if (m.face_sizes[f] != 4) {  // sub-face s: (0, 0) is the face's corner s, (1, 1) its centre (a vertex of valence N)
    ExactParameter local;
    const int s = FaceDomain::of(SchemeFamily::Quad, m.face_sizes[f]).subface(at, local);
    if (local.u == one && local.v == one) return true;
    return local.u == zero && local.v == zero &&
           valence[static_cast<std::size_t>(m.face_vertices[start[f] + static_cast<std::size_t>(s)])] != 4;
  }
  int corner = -1;
  if (at.u == zero && at.v == zero) corner = 0;
  if (at.u == one && at.v == zero) corner = 1;
  if (at.u == one && at.v == one) corner = 2;
  if (at.u == zero && at.v == one) corner = 3;
  return corner >= 0 && valence[static_cast<std::size_t>(m.face_vertices[start[f] + static_cast<std::size_t>(corner)])] != 4;
}

// Second derivatives (Surface::second_derivatives) against Bfr's at the same
// face and parameter; their first derivatives must be the same as without.
void check_second_derivatives(const Surface& surface, bfr_reference::BfrLimit& reference, std::size_t f, double u, double v,
                              double size, double& worst) {
  const SecondDerivatives ours = surface.second_derivatives(f, u, v);
  const auto ref = reference.second_derivatives(static_cast<int>(f), u, v);
  const Derivatives first = surface.derivatives(f, u, v);
  CHECK(distance(ours.du, first.du) <= 1e-14 * size);
  CHECK(distance(ours.dv, first.dv) <= 1e-14 * size);
  const double e = std::max({distance(ours.duu, ref[3]), distance(ours.duv, ref[4]), distance(ours.dvv, ref[5])}) / size;
  worst = std::max(worst, e);
  REQUIRE(e < 1e-11);
}

void check_against_bfr(const std::shared_ptr<const Tables>& tables, const Mesh& mesh, const std::string& name, std::size_t stride) {
  const Surface surface = surface_of(tables, mesh);
  bfr_reference::BfrLimit reference(mesh.positions, mesh.face_sizes, mesh.face_vertices);
  const double size = extent(mesh);
  const auto valence = vertex_valences(mesh);
  const auto start = face_starts(mesh);
  std::mt19937 rng(20261124u);
  double worst = 0, worst_second = 0, worst_vertex_normal = 0;
  std::size_t refused = 0;
  for (std::size_t f = 0; f < mesh.face_count(); f += stride) {
    const FaceDomain domain = surface.topology().domain(f);
    std::vector<ExactParameter> at;
    for (long n : {1L, 2L, 3L, 5L})
      for (const auto& p : grid_parameters(domain, n)) at.push_back(p);
    for (const ExactParameter& p : at) {
      INFO(name << " face " << f << " at " << p.str());
      if (at_extraordinary_corner(mesh, valence, start, f, p)) {
        REQUIRE_THROWS_WITH(surface.derivatives(f, p), Catch::Contains("extraordinary vertex"));
        ++refused;
        // No parametric derivative, but a normal: the tangent stencils' (left
        // eigenvectors of A0) against Bfr's tangent plane there. Bfr's
        // irregular patches only approximate the limit there (up to 1.7e-6 on
        // torus-3-5, where two extraordinary vertices are close); the exact
        // oracle is Far's limit tangents (test_ev_normals.cpp, 2e-16).
        const auto ref = reference.derivatives(static_cast<int>(f), p.u.to_double(), p.v.to_double());
        Derivatives bfr;
        bfr.du = ref[1], bfr.dv = ref[2];
        const double e = distance(surface.normal(f, p), bfr.normal());
        worst_vertex_normal = std::max(worst_vertex_normal, e);
        REQUIRE(e < 1e-5);
        continue;
      }
      const Derivatives ours = surface.derivatives(f, p);
      const auto ref = reference.derivatives(static_cast<int>(f), p.u.to_double(), p.v.to_double());
      const double e = std::max({distance(ours.point, ref[0]), distance(ours.du, ref[1]), distance(ours.dv, ref[2])}) / size;
      worst = std::max(worst, e);
      REQUIRE(e < 1e-10);
      check_second_derivatives(surface, reference, f, p.u.to_double(), p.v.to_double(), size, worst_second);
    }
    if (domain.kind == FaceDomain::Kind::Quad)
      for (int k = 0; k < 3; ++k) {  // real parameters: Catmull-Clark's regular patches are polynomial
        const double u = std::uniform_real_distribution<double>(0.01, 0.99)(rng), v = std::uniform_real_distribution<double>(0.01, 0.99)(rng);
        INFO(name << " face " << f << " at (" << u << ", " << v << ")");
        const Derivatives ours = surface.derivatives(f, u, v);
        const auto ref = reference.derivatives(static_cast<int>(f), u, v);
        const double e = std::max({distance(ours.point, ref[0]), distance(ours.du, ref[1]), distance(ours.dv, ref[2])}) / size;
        worst = std::max(worst, e);
        REQUIRE(e < 1e-10);
        check_second_derivatives(surface, reference, f, u, v, size, worst_second);
      }
  }
  CHECK(refused > 0);
  WARN(name << ": largest difference to Bfr's point and derivatives, over the mesh size: " << worst
            << "; second derivatives: " << worst_second << "; normals at extraordinary vertices: " << worst_vertex_normal);
}

}  // namespace

TEST_CASE("Catmull-Clark derivatives through the runtime equal OpenSubdiv's on every bundled mesh", "[runtime][derivatives][opensubdiv]") {
  const auto tables = Tables::load(tables_for("catmull-clark").string());
  for (const char* name : kBundled) {
    const Mesh mesh = load(name);
    check_against_bfr(tables, mesh, name, mesh.face_count() > 100 ? 7 : 1);
  }
  check_against_bfr(tables, prism(), "prism", 1);  // the polygon step's sub-faces
}

TEST_CASE("nonpoly unit normals agree on both sides of every edge of the bundled meshes", "[runtime][derivatives]") {
  const auto tables = Tables::load(tables_for("nonpoly").string());
  for (const char* name : kBundled) {
    const Mesh mesh = load(name);
    const Surface surface = surface_of(tables, mesh);
    const QuadTopology topo(Connectivity{mesh.vertex_count(), mesh.face_sizes, mesh.face_vertices});
    const auto valence = vertex_valences(mesh);
    const long n = 6;
    auto on_edge = [&](std::size_t f, int c, long t) {  // edge c -> c+1 of face f at t/n from corner c
      const long u[4] = {t, n, n - t, 0}, v[4] = {0, t, n, n - t};
      return surface.derivatives(f, grid(u[c & 3], v[c & 3], n));
    };
    double worst = 0;
    for (std::uint32_t h = 0; h < 4 * topo.faces(); ++h) {
      const std::uint32_t o = topo.twin(h);
      const std::size_t f = QuadTopology::face_of(h), g = QuadTopology::face_of(o);
      const int from = mesh.face_vertices[4 * f + static_cast<std::size_t>(QuadTopology::corner_of(h))];
      const int to = mesh.face_vertices[4 * f + static_cast<std::size_t>((QuadTopology::corner_of(h) + 1) % 4)];
      for (long t = 0; t <= n; ++t) {
        if ((t == 0 && valence[static_cast<std::size_t>(from)] != 4) || (t == n && valence[static_cast<std::size_t>(to)] != 4)) continue;
        const Derivatives a = on_edge(f, QuadTopology::corner_of(h), t), b = on_edge(g, QuadTopology::corner_of(o), n - t);
        INFO(name << " half-edge " << h << " t = " << t << "/" << n);
        REQUIRE(distance(a.point, b.point) < 1e-12 * extent(mesh));
        const double e = distance(a.normal(), b.normal());
        worst = std::max(worst, e);
        REQUIRE(e < 1e-12);
      }
    }
    WARN(name << ": largest difference of the two faces' unit normals on an edge: " << worst);
  }
}

TEST_CASE("nonpoly du and dv are the limits of difference quotients of exact limit points", "[runtime][derivatives]") {
  // (P(u + h) - P(u - h)) / 2h at exact parameters (u = 1/3 + h is reached exactly by the descent),
  // h = 2^-8, 2^-12, 2^-16: the error to du must shrink, and end small.
  const auto tables = Tables::load(tables_for("nonpoly").string());
  for (const auto& [name, mesh] : {std::pair<std::string, Mesh>{"cube", load("cube")}, {"chess-piece", load("chess-piece")},
                                   {"prism", prism()}}) {
    const Surface surface = surface_of(tables, mesh);
    const double size = extent(mesh);
    for (std::size_t f = 0; f < mesh.face_count(); f += mesh.face_count() > 100 ? 37 : 1) {
      const FaceDomain domain = surface.topology().domain(f);
      const Fraction u0 = Fraction::make(1, 3), v0 = domain.kind == FaceDomain::Kind::Quad ? Fraction::make(2, 3) : Fraction::make(1, 6);
      const Derivatives d = surface.derivatives(f, ExactParameter{u0, v0});
      std::vector<double> errors;
      for (int bits : {8, 12, 16}) {
        const Fraction h = Fraction::make(1, std::int64_t{1} << bits);
        const auto [qu, qv] = central_quotients(surface, f, {u0, v0}, h, static_cast<double>(std::int64_t{1} << bits) / 2);
        errors.push_back(std::max(distance(qu, d.du), distance(qv, d.dv)) / size);
      }
      INFO(name << " face " << f << ": errors " << errors[0] << " " << errors[1] << " " << errors[2]);
      REQUIRE(errors[1] < errors[0]);
      REQUIRE(errors[2] < errors[1]);
      REQUIRE(errors[2] < 1e-3);
    }
  }
}

// Towards an extraordinary vertex the descent takes differences of points
// whose spread shrinks while their coordinates do not: rounded at the size of
// the coordinates, the normal 2^-45 from the vertex had no right digit (a
// review found (-0.13, -0.06, -0.99) where the vertex's is (0.58, 0.58, -0.58)).
// Re-centred at every level it converges to the vertex normal, which comes
// from the tangent stencils (the eigenvectors), another route.
TEST_CASE("normals next to an extraordinary vertex keep their digits down to 2^-45 from it", "[runtime][derivatives]") {
  struct Case {
    const char* scheme;
    std::filesystem::path tables;
    const char* mesh;
    std::size_t face;
    double corner_u, corner_v;  // the vertex, a corner of the face's domain
  };
  for (const Case& c : {Case{"catmull-clark", tables_for("catmull-clark"), "cube", 0, 1, 1},
                        Case{"nonpoly", tables_for("nonpoly"), "cube", 0, 1, 1},
                        Case{"loop", generated_table("loop", "--valence 3-8 --n 4", "sgt"), "icosahedron", 4, 0, 1}}) {
    CAPTURE(c.scheme);
    const Surface surface = surface_of(Tables::load(c.tables.string()), load(c.mesh));
    const Point vertex = surface.normal(c.face, c.corner_u, c.corner_v);
    for (int k : {30, 36, 40, 45}) {
      CAPTURE(k);
      const double h = std::ldexp(1.0, -k);  // towards the face's inside along both parameters
      const double u = c.corner_u == 0 ? h : c.corner_u - h, v = c.corner_v == 0 ? h : c.corner_v - h;
      CHECK(distance(surface.normal(c.face, u, v), vertex) < 1e-8);
    }
  }
}

TEST_CASE("derivatives are refused where they do not exist or are not exact, with a reason", "[runtime][derivatives][errors]") {
  const auto nonpoly = Tables::load(tables_for("nonpoly").string());
  const Mesh cube = load("cube");
  const Surface surface = surface_of(nonpoly, cube);
  CHECK_THROWS_WITH(surface.derivatives(0, grid(0, 0, 1)), Catch::Contains("extraordinary vertex"));
  // Any parameter is reached through its orbit under halving, unless the orbit is longer than the stated limit
  // (the order of 2 modulo 3000017 is 1500008).
  CHECK_NOTHROW(surface.derivatives(0, 0.3, 0.7));
  CHECK_THROWS_WITH(surface.derivatives(0, ExactParameter{Fraction::make(1, 3000017), Fraction::make(1, 3)}),
                    Catch::Contains("orbit under halving is longer than 1048576 steps"));
  CHECK_THROWS_WITH(surface.derivatives(0, grid(1, 2, 1)), Catch::Contains("outside face"));
  CHECK_THROWS_WITH(surface.second_derivatives(0, grid(1, 2, 3)), Catch::Contains("are not, and its tables hold no"));
  const Surface cc = surface_of(Tables::load(tables_for("catmull-clark").string()), cube);
  CHECK_THROWS_WITH(cc.second_derivatives(0, grid(0, 0, 1)), Catch::Contains("extraordinary vertex"));
  const auto loop = Tables::load(generated_table("loop", "--valence 3-8 --n 4", "sgt").string());
  const Surface ico = surface_of(loop, load("icosahedron"));
  CHECK_THROWS_WITH(ico.second_derivatives(0, 0.0, 0.0), Catch::Contains("extraordinary vertex"));
  CHECK_THROWS_WITH(ico.derivatives(0, 0.0, 0.0), Catch::Contains("extraordinary vertex"));
  const auto sqrt3 = Tables::load(generated_table("sqrt3", "--valence 3-8 --n 3", "sgt").string());
  const Surface torus = surface_of(sqrt3, load("tri-torus"));
  // sqrt(3): exact derivatives at the tables' grid points (test_sqrt3_derivatives.cpp), none elsewhere.
  CHECK_NOTHROW(torus.derivatives(0, grid(1, 1, 3)));
  CHECK_THROWS_WITH(torus.derivatives(0, 0.25, 0.25), Catch::Contains("derivatives only at exact parameters on its tables' grids"));
  CHECK_THROWS_WITH(torus.derivatives(0, 0.1, 0.2), Catch::Contains("(0.100000, 0.200000) is not one"));
  CHECK_THROWS_WITH(torus.derivatives(0, ExactParameter{Fraction::make(1, 25), Fraction::make(1, 25)}),
                    Catch::Contains("which no stored rate holds"));
  CHECK_THROWS_WITH(torus.second_derivatives(0, grid(1, 1, 3)), Catch::Contains("not a polynomial"));
}

TEST_CASE("Loop tessellation normals: unit, outward, and orthogonal to the tessellation's edges", "[runtime][derivatives][tessellation]") {
  // The icosahedron's limit surface is close to a sphere about the origin:
  // outward means along the position, and an edge of the rate-16 tessellation
  // (a chord of length h) leaves the tangent plane by about h / (2 R).
  const auto loop = Tables::load(generated_table("loop", "--valence 3-8 --n 16", "sgt").string());
  const Surface surface = surface_of(loop, load("icosahedron"));
  const PolygonSoup soup = tessellate(surface, std::vector<int>(surface.topology().face_count(), 16), {}, true);
  REQUIRE(soup.normals.size() == soup.positions.size());
  auto vec = [](const std::array<float, 3>& a) { return Point{a[0], a[1], a[2]}; };
  auto dot = [](const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  for (std::size_t k = 0; k < soup.positions.size(); ++k) {
    const Point n = vec(soup.normals[k]), p = vec(soup.positions[k]);
    INFO("vertex " << k);
    REQUIRE(std::abs(dot(n, n) - 1) < 1e-6);
    REQUIRE(dot(n, p) > 0.9 * std::sqrt(dot(p, p)));
  }
  double worst = 0;
  auto edge = [&](int a, int b) {
    const Point pa = vec(soup.positions[static_cast<std::size_t>(a)]), pb = vec(soup.positions[static_cast<std::size_t>(b)]);
    Point chord{pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]};
    const double l = std::sqrt(dot(chord, chord));
    for (double& x : chord) x /= l;
    worst = std::max({worst, std::abs(dot(chord, vec(soup.normals[static_cast<std::size_t>(a)]))),
                      std::abs(dot(chord, vec(soup.normals[static_cast<std::size_t>(b)])))});
  };
  for (const auto& t : soup.triangles) edge(t[0], t[1]), edge(t[1], t[2]), edge(t[2], t[0]);
  for (const auto& q : soup.quads) edge(q[0], q[1]), edge(q[1], q[2]), edge(q[2], q[3]), edge(q[3], q[0]);
  CHECK(worst < 0.1);
}

TEST_CASE("Loop first and second derivatives through the runtime equal OpenSubdiv's on the bundled triangle meshes",
          "[runtime][derivatives][opensubdiv]") {
  const auto loop = Tables::load(generated_table("loop", "--valence 3-8 --n 4", "sgt").string());
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> uniform(0, 1);
  for (const char* name : {"icosahedron", "tri-torus", "tri-mix"}) {
    INFO(name);
    const Mesh mesh = load(name);
    const Surface surface = surface_of(loop, mesh);
    bfr_reference::BfrLimit reference(mesh.positions, mesh.face_sizes, mesh.face_vertices,
                                      OpenSubdiv::OPENSUBDIV_VERSION::Sdc::SCHEME_LOOP);
    double scale = 0;
    for (const Point& p : mesh.positions) scale = std::max({scale, std::abs(p[0]), std::abs(p[1]), std::abs(p[2])});
    for (std::size_t f = 0; f < mesh.face_count(); ++f)
      for (int s = 0; s < 6; ++s) {
        double u = uniform(rng), v = uniform(rng);
        if (u + v > 1) u = 1 - u, v = 1 - v;
        if (s == 0) u = 1e-3, v = 2e-3;  // next to corner 0, deep in the descent where it is extraordinary
        const Derivatives ours = surface.derivatives(f, u, v);
        const auto bfr = reference.derivatives(static_cast<int>(f), u, v);
        INFO("face " << f << " at (" << u << ", " << v << ")");
        for (int k = 0; k < 3; ++k) {
          CHECK(std::abs(ours.point[k] - bfr[0][k]) <= 1e-12 * scale);
          CHECK(std::abs(ours.du[k] - bfr[1][k]) <= 1e-11 * scale);
          CHECK(std::abs(ours.dv[k] - bfr[2][k]) <= 1e-11 * scale);
        }
        // Second derivatives: central differences of Bfr's first derivatives
        // (Bfr 3.5.0's own second derivatives of Loop patches come out with
        // the opposite sign here, against those same differences), and the
        // first derivatives the same as without them.
        const SecondDerivatives second = surface.second_derivatives(f, u, v);
        for (int k = 0; k < 3; ++k) {
          CHECK(second.du[k] == ours.du[k]);
          CHECK(second.dv[k] == ours.dv[k]);
        }
        // The step: 1e-4 of the distance to the nearest corner (the second
        // derivatives vary on the scale of the distance to an extraordinary
        // vertex), which leaves the differences good to about 1e-6 relative.
        const double corner = std::min({std::hypot(u, v), std::hypot(1 - u, v), std::hypot(u, 1 - v)});
        const double h = 1e-4 * corner;
        if (u < 2 * h || v < 2 * h || u + v > 1 - 2 * h) continue;
        const auto ua = reference.derivatives(static_cast<int>(f), u + h, v), ub = reference.derivatives(static_cast<int>(f), u - h, v);
        const auto va = reference.derivatives(static_cast<int>(f), u, v + h), vb = reference.derivatives(static_cast<int>(f), u, v - h);
        for (int k = 0; k < 3; ++k) {
          const double duu = (ua[1][k] - ub[1][k]) / (2 * h), duv = (va[1][k] - vb[1][k]) / (2 * h),
                       dvu = (ua[2][k] - ub[2][k]) / (2 * h), dvv = (va[2][k] - vb[2][k]) / (2 * h);
          const double tolerance = 1e-6 * (scale + std::max({std::abs(duu), std::abs(duv), std::abs(dvv)}));
          CHECK(std::abs(second.duu[k] - duu) <= tolerance);
          CHECK(std::abs(second.duv[k] - duv) <= tolerance);
          CHECK(std::abs(second.duv[k] - dvu) <= tolerance);
          CHECK(std::abs(second.dvv[k] - dvv) <= tolerance);
        }
      }
  }
}

TEST_CASE("stencileval --second-derivatives prints Bfr's second derivatives, and refuses nonpoly with the reason",
          "[runtime][derivatives][cli]") {
  const Mesh mesh = load("chess-piece");
  bfr_reference::BfrLimit reference(mesh.positions, mesh.face_sizes, mesh.face_vertices);
  const std::string common = " --mesh " + (kMeshes / "chess-piece.obj").string() + " --face 17 --uv 0.3,0.7";
  const CliResult r = run_stencileval("--tables " + tables_for("catmull-clark").string() + common +
                                      " --derivatives --second-derivatives");
  REQUIRE(r.status == 0);
  // The last line: x y z, du, dv, duu, duv, dvv.
  std::istringstream last(r.output.substr(r.output.rfind('\n', r.output.size() - 2) + 1));
  std::array<Point, 6> got{};
  for (Point& p : got) REQUIRE(static_cast<bool>(last >> p[0] >> p[1] >> p[2]));
  const auto ref = reference.second_derivatives(17, 0.3, 0.7);
  for (std::size_t k = 0; k < 6; ++k) CHECK(distance(got[k], ref[k]) < 1e-12 * extent(mesh));
  const CliResult refused = run_stencileval("--tables " + tables_for("nonpoly").string() + common + " --second-derivatives");
  CHECK(refused.status == 1);
  CHECK_THAT(refused.output, Catch::Contains("polynomial"));
}

TEST_CASE("tessellation normals equal stencileval --normal and, for Catmull-Clark, Bfr's at the same parameters",
          "[runtime][derivatives][tessellation]") {
  // Original rate 6 on the torus -> prepared faces at rate 3 after one isolation
  // step; point k is a cell centre on the original face's grid 1/12.
  const Mesh mesh = load("torus-3-5");
  const long n = 3;
  for (const std::string scheme : {"nonpoly", "catmull-clark"}) {
    const fs::path table = tables_for(scheme);
    const Surface surface = surface_of(Tables::load(table.string()), mesh);
    REQUIRE(surface.topology().refinement_steps() == 1);
    const PolygonSoup soup = tessellate(surface, std::vector<int>(mesh.face_count(), 6), {}, true);
    REQUIRE(soup.normals.size() == soup.positions.size());
    const fs::path dir = scratch_dir("tess-normals");
    std::ofstream queries(dir / "q.txt");
    std::vector<std::size_t> sample;
    for (std::size_t k = 0; k < soup.positions.size(); k += 5) {
      const TessellationParameter t = tessellation_parameter(k, n);
      queries << t.face << " " << t.u << "/" << t.denominator << " " << t.v << "/" << t.denominator << "\n";
      sample.push_back(k);
    }
    queries.close();
    const CliResult r = run_stencileval("--tables " + table.string() + " --mesh " + (kMeshes / "torus-3-5.obj").string() +
                                        " --batch " + (dir / "q.txt").string() + " --normal");
    REQUIRE(r.status == 0);
    std::istringstream lines(r.output);
    bfr_reference::BfrLimit reference(mesh.positions, mesh.face_sizes, mesh.face_vertices);
    for (std::size_t k : sample) {
      Point p{}, normal{};
      REQUIRE(static_cast<bool>(lines >> p[0] >> p[1] >> p[2] >> normal[0] >> normal[1] >> normal[2]));
      const auto& q = soup.positions[k];
      const auto& m = soup.normals[k];
      INFO(scheme << " vertex " << k);
      REQUIRE(distance(p, {q[0], q[1], q[2]}) < 1e-6);
      REQUIRE(distance(normal, {m[0], m[1], m[2]}) < 1e-6);
      if (scheme == "catmull-clark") {
        const TessellationParameter t = tessellation_parameter(k, n);
        Derivatives d;
        const auto ref = reference.derivatives(static_cast<int>(t.face), double(t.u) / t.denominator, double(t.v) / t.denominator);
        d.du = ref[1], d.dv = ref[2];
        REQUIRE(distance(d.normal(), {m[0], m[1], m[2]}) < 1e-6);
      }
    }
    fs::remove_all(dir);
  }
  // The tool writes them: one `vn` per vertex, and PLY's nx ny nz.
  const fs::path dir = scratch_dir("tess-normals-cli");
  const CliResult obj = run_stenciltess("--tables " + tables_for("nonpoly").string() + " --mesh " +
                                        (kMeshes / "cube.obj").string() + " --rate 4 --normals --out " + (dir / "c.obj").string());
  REQUIRE(obj.status == 0);
  std::ifstream in(dir / "c.obj");
  std::string line;
  std::size_t v = 0, vn = 0;
  while (std::getline(in, line)) v += line.rfind("v ", 0) == 0, vn += line.rfind("vn ", 0) == 0;
  CHECK(v > 0);
  CHECK(vn == v);
  const CliResult tri = run_stenciltess("--tables " + generated_table("sqrt3", "--valence 3-8 --n 3", "sgt").string() +
                                        " --mesh " + (kMeshes / "tri-torus.obj").string() + " --rate 3 --normals --out " +
                                        (dir / "i.ply").string());
  CHECK(tri.status == 0);  // sqrt(3) too (version 6 tables)
  CHECK(fs::exists(dir / "i.ply"));
  fs::remove_all(dir);
}

TEST_CASE("a directory of exact JSON tables gives the binary file's derivatives", "[runtime][derivatives][tables]") {
  const fs::path sgs = tables_for("nonpoly");
  const Mesh mesh = load("chess-piece");
  const Surface binary = surface_of(Tables::load(sgs.string()), mesh);
  // The JSON alone: Tables::load prefers the .sgs file where a directory holds one.
  const fs::path json_dir = scratch_dir("json-derivatives") / "nonpoly";
  fs::copy(sgs.parent_path(), json_dir, fs::copy_options::recursive);
  fs::remove(json_dir / sgs.filename());
  const Surface json = surface_of(Tables::load(json_dir.string()), mesh);
  const double size = extent(mesh);
  for (std::size_t f = 0; f < mesh.face_count(); f += 11)
    for (const ExactParameter& at : {grid(1, 2, 3), grid(5, 1, 8), grid(7, 24, 24)}) {
      const Derivatives a = binary.derivatives(f, at), b = json.derivatives(f, at);
      INFO("face " << f << " at " << at.str());
      REQUIRE(std::max({distance(a.point, b.point), distance(a.du, b.du), distance(a.dv, b.dv)}) < 1e-14 * size);
    }
  // Normals at the corners, extraordinary vertices included (tangent stencils in descent.json).
  for (std::size_t f = 0; f < mesh.face_count(); ++f)
    for (const ExactParameter& at : {grid(0, 0, 1), grid(1, 0, 1), grid(1, 1, 1), grid(0, 1, 1)}) {
      INFO("face " << f << " at " << at.str());
      REQUIRE(distance(binary.normal(f, at), json.normal(f, at)) < 1e-14);
    }
  fs::remove_all(json_dir.parent_path());
}

TEST_CASE("a tiny mesh has the normals of the same mesh at unit size, and closest points refuse one below 1e-100",
          "[runtime][derivatives][tessellation]") {
  // du x dv of tangents of 1e-100 is 1e-200, whose square underflows: the
  // normals were not unit (1e-100), zero (1e-150 and below, `vn 0 0 0`) or
  // off by 1e-5 (1e-80). A mesh scaled down has the same normals.
  struct Case {
    fs::path table;
    std::string mesh;
  };
  for (const Case& c : {Case{tables_for("catmull-clark"), "cube"}, Case{tables_for("nonpoly"), "chess-piece"},
                        Case{generated_table("loop", "--valence 3-8 --n 4", "sgt"), "icosahedron"}}) {
    const auto tables = Tables::load(c.table.string());
    const Mesh unit = load(c.mesh);
    const Surface reference = surface_of(tables, unit);
    const std::vector<int> rates(unit.face_count(), 4);
    const PolygonSoup expected = tessellate(reference, rates, {}, true);
    for (const double scale : {1e-80, 1e-100, 1e-150, 1e-200, 1e-300}) {
      Mesh tiny = unit;
      for (Point& p : tiny.positions)
        for (double& x : p) x *= scale;
      const Surface surface = surface_of(tables, tiny);
      INFO(c.mesh << " scaled by " << scale);
      for (std::size_t f = 0; f < unit.face_count(); f += 3)
        for (const auto& [u, v] : {std::pair{1.0 / 3, 0.25}, std::pair{0.1, 0.2}, std::pair{0.5, 0.3}}) {
          const Point n = surface.normal(f, u, v), m = reference.normal(f, u, v);
          INFO("face " << f << " at " << u << ", " << v);
          REQUIRE(distance(n, m) < 1e-12);
        }
      const PolygonSoup soup = tessellate(surface, rates, {}, true);
      REQUIRE(soup.normals.size() == expected.normals.size());
      double worst = 0;
      for (std::size_t k = 0; k < soup.normals.size(); ++k)
        for (int i = 0; i < 3; ++i) worst = std::max(worst, static_cast<double>(std::abs(soup.normals[k][i] - expected.normals[k][i])));
      CHECK(worst < 1e-6);
      if (scale < 1e-100)
        CHECK_THROWS_WITH(ClosestPointQuery(surface), Catch::Contains("below 1e-100") && Catch::Contains("scale the mesh up"));
    }
  }
  // All control points at the origin: no extent to measure distances by.
  Mesh flat = load("cube");
  for (Point& p : flat.positions) p = {0, 0, 0};
  CHECK_THROWS_WITH(ClosestPointQuery(surface_of(Tables::load(tables_for("catmull-clark").string()), flat)),
                    Catch::Contains("the control points all coincide"));
}
