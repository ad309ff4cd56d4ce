// sqrt(3) derivatives through the runtime (version 6 tables: the regular
// patch's derivative stencils, reached by the descent through the patch's
// children), against what does not use them: the two faces' unit normals along
// every edge, central difference quotients of exact limit points, the tangent
// stencils at the extraordinary vertices (subdominant eigenvectors), and the
// tessellation's normals against stencileval --normal at the same parameters.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "bundled_meshes.hpp"
#include "cli.hpp"
#include "runtime_api.hpp"
#include "runtime_checks.hpp"
#include "triangle/triangle_family.hpp"

using namespace stencil_runtime;
using namespace test_runtime;
namespace fs = std::filesystem;
using test_meshes::bundled;
using test_meshes::kMeshes;
using test_meshes::kTriangleMeshes;

namespace {

fs::path sqrt3_tables() { return generated_table("sqrt3", "--valence 3-8 --n 1-9", "sgt"); }
double dot(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// The point t/n along edge c (corner c -> c+1) of a triangle face.
ExactParameter on_edge(int c, long t, long n) {
  switch (c) {
    case 0: return grid(t, 0, n);
    case 1: return grid(n - t, t, n);
    default: return grid(0, n - t, n);
  }
}

}  // namespace

TEST_CASE("sqrt(3) unit normals agree on both sides of every edge of the bundled triangle meshes", "[runtime][derivatives][sqrt3]") {
  const auto tables = Tables::load(sqrt3_tables().string());
  for (const char* name : kTriangleMeshes) {
    const Mesh mesh = bundled(name);
    const Surface surface = surface_of(tables, mesh);
    const auto valence = vertex_valences(mesh);
    std::map<std::pair<int, int>, std::pair<std::size_t, int>> half_edges;  // (from, to) -> (face, corner)
    for (std::size_t f = 0; f < mesh.face_count(); ++f)
      for (int c = 0; c < 3; ++c)
        half_edges[{mesh.face_vertices[3 * f + static_cast<std::size_t>(c)], mesh.face_vertices[3 * f + static_cast<std::size_t>((c + 1) % 3)]}] = {f, c};
    const long n = 6;
    double worst = 0;
    std::size_t checked = 0;
    for (const auto& [edge, here] : half_edges) {
      const auto& [from, to] = edge;
      const auto& [g, d] = half_edges.at({to, from});
      for (long t = 0; t <= n; ++t) {
        const bool ev = (t == 0 && valence[static_cast<std::size_t>(from)] != 6) || (t == n && valence[static_cast<std::size_t>(to)] != 6);
        INFO(name << " edge " << from << "->" << to << " at " << t << "/" << n);
        const ExactParameter a = on_edge(here.second, t, n), b = on_edge(d, n - t, n);
        Point na{}, nb{};
        if (ev) {  // no parametric derivative: the tangent stencils' normal, from both faces
          REQUIRE_THROWS_WITH(surface.derivatives(here.first, a), Catch::Contains("extraordinary vertex"));
          na = surface.normal(here.first, a), nb = surface.normal(g, b);
        } else {
          const Derivatives da = surface.derivatives(here.first, a), db = surface.derivatives(g, b);
          REQUIRE(distance(da.point, db.point) < 1e-12 * extent(mesh));
          na = da.normal(), nb = db.normal();
          REQUIRE(distance(na, surface.normal(here.first, a)) < 1e-15);
        }
        const double e = distance(na, nb);
        worst = std::max(worst, e);
        REQUIRE(e < 1e-12);
        ++checked;
      }
    }
    CHECK(checked == half_edges.size() * static_cast<std::size_t>(n + 1));
    WARN(name << ": largest difference of the two faces' sqrt(3) unit normals on an edge: " << worst);
  }
}

TEST_CASE("sqrt(3) du and dv are the limits of difference quotients of exact limit points", "[runtime][derivatives][sqrt3]") {
  // (P(u + h) - P(u - h)) / 2h with h = 3^-3, 3^-5, 3^-7: the descent reaches
  // such thirds exactly, so the quotients carry no evaluation error, and
  // their error to du (and dv) must shrink and end small.
  const auto tables = Tables::load(sqrt3_tables().string());
  for (const char* name : kTriangleMeshes) {
    const Mesh mesh = bundled(name);
    const Surface surface = surface_of(tables, mesh);
    const double size = extent(mesh);
    for (std::size_t f = 0; f < mesh.face_count(); f += 3) {
      for (const auto& [u0, v0] : {std::pair{Fraction::make(2, 9), Fraction::make(4, 9)}, {Fraction::make(1, 9), Fraction::make(1, 9)},
                                   {Fraction::make(1, 2), Fraction::make(1, 6)}}) {
        const Derivatives d = surface.derivatives(f, ExactParameter{u0, v0});
        std::vector<double> errors;
        for (int k : {3, 5, 7}) {
          const std::int64_t power = static_cast<std::int64_t>(std::pow(3, k));
          const Fraction h = Fraction::make(1, power);
          const auto [qu, qv] = central_quotients(surface, f, {u0, v0}, h, static_cast<double>(power) / 2);
          errors.push_back(std::max(distance(qu, d.du), distance(qv, d.dv)) / size);
        }
        INFO(name << " face " << f << " at (" << u0.str() << ", " << v0.str() << "): errors " << errors[0] << " " << errors[1]
                  << " " << errors[2]);
        REQUIRE(errors[1] < errors[0] / 4);
        REQUIRE(errors[2] < errors[1] / 4);
        REQUIRE(errors[2] < 1e-5);
      }
    }
  }
}

TEST_CASE("sqrt(3) normals next to an extraordinary vertex converge to its tangent stencils' normal", "[runtime][derivatives][sqrt3]") {
  // The derivative stencils and the tangent stencils (subdominant
  // eigenvectors, computed by separate code) meet in the limit.
  const auto tables = Tables::load(sqrt3_tables().string());
  for (const char* name : kTriangleMeshes) {
    const Mesh mesh = bundled(name);
    const Surface surface = surface_of(tables, mesh);
    const auto valence = vertex_valences(mesh);
    std::size_t checked = 0;
    for (std::size_t f = 0; f < mesh.face_count(); ++f)
      for (int c = 0; c < 3; ++c) {
        if (valence[static_cast<std::size_t>(mesh.face_vertices[3 * f + static_cast<std::size_t>(c)])] == 6) continue;
        auto near = [&](long k) {  // 3^-k from corner c, inside the face
          const std::int64_t p = static_cast<std::int64_t>(std::pow(3, k));
          const ExactParameter at[3] = {grid(1, 1, p), grid(p - 2, 1, p), grid(1, p - 2, p)};
          return at[c];
        };
        const Point vertex = surface.normal(f, grid(c == 1 ? 1 : 0, c == 2 ? 1 : 0, 1));
        std::vector<double> gaps;
        for (long k : {2L, 4L, 6L, 8L}) gaps.push_back(1 - dot(surface.derivatives(f, near(k)).normal(), vertex));
        INFO(name << " face " << f << " corner " << c << " (valence " << valence[static_cast<std::size_t>(mesh.face_vertices[3 * f + static_cast<std::size_t>(c)])]
                  << "): 1 - cos " << gaps[0] << " " << gaps[1] << " " << gaps[2] << " " << gaps[3]);
        REQUIRE(gaps[1] < gaps[0]);
        REQUIRE(gaps[2] < gaps[1]);
        REQUIRE(gaps[3] < gaps[2]);
        REQUIRE(gaps[3] < 1e-4);
        ++checked;
      }
    CHECK(checked > 0);
  }
}

TEST_CASE("sqrt(3) and Loop tessellation normals equal stencileval --normal at the same parameters",
          "[runtime][derivatives][sqrt3][tessellation]") {
  // Regular faces take the tables' derivative stencils (sqrt(3): stored; Loop:
  // made at load from its polynomial), the others the descent; Surface::normal
  // and the tool reach every point through the descent.
  struct Case {
    fs::path table;
    int rate, scale;  // per original face; the preparation's step divides parameters by `scale`
  };
  for (const Case& c : {Case{sqrt3_tables(), 9, 3}, Case{generated_table("loop", "--valence 3-8 --n 1-8", "sgt"), 8, 2}})
  for (const char* name : {"icosahedron", "tri-mix"}) {
    const fs::path& table = c.table;
    const auto tables = Tables::load(table.string());
    const Mesh mesh = bundled(name);
    const Surface surface = surface_of(tables, mesh);
    const auto& family = dynamic_cast<const TriangleFamily&>(surface.topology().family());
    const std::vector<int> rates(mesh.face_count(), c.rate);
    const std::vector<int> prepared = family.hierarchy().prepared_rates(rates);
    const long n = prepared.front();
    const PolygonSoup soup = tessellate(surface, rates, {}, true);
    REQUIRE(soup.normals.size() == soup.positions.size());
    REQUIRE(soup.positions.size() >= prepared.size() * static_cast<std::size_t>(n * n));
    // Prepared face pf's points: n^2 centres, the up ones then the down ones, row by row.
    const long den = 3 * n * static_cast<long>(std::pow(c.scale, family.refinement_steps()));
    const fs::path dir = scratch_dir("sqrt3-tess-normals");
    std::ofstream queries(dir / "q.txt");
    std::vector<std::size_t> sample;
    for (std::size_t pf = 0; pf < prepared.size(); ++pf) {
      REQUIRE(prepared[pf] == n);
      std::size_t k = pf * static_cast<std::size_t>(n * n);
      auto put = [&](long a, long b) {
        const FaceParameterReal o = family.original(pf, static_cast<double>(a) / (3.0 * n), static_cast<double>(b) / (3.0 * n));
        const ExactParameter at{Fraction::make(std::llround(o.u * den), den), Fraction::make(std::llround(o.v * den), den)};
        const auto& q = soup.positions[k];
        const auto& m = soup.normals[k];
        INFO(table.filename() << " " << name << " point " << k << ": face " << o.face << " at " << at.str());
        REQUIRE(distance(surface.evaluate(o.face, at), {q[0], q[1], q[2]}) < 1e-6 * extent(mesh));
        REQUIRE(distance(surface.normal(o.face, at), {m[0], m[1], m[2]}) < 1e-6);
        if (k % 23 == 0) {
          queries << o.face << " " << at.u.str() << " " << at.v.str() << "\n";
          sample.push_back(k);
        }
        ++k;
      };
      for (long j = 0; j < n; ++j)
        for (long i = 0; i + j <= n - 1; ++i) put(3 * i + 1, 3 * j + 1);
      for (long j = 0; j + 1 < n; ++j)
        for (long i = 0; i + j <= n - 2; ++i) put(3 * i + 2, 3 * j + 2);
    }
    queries.close();
    const CliResult r = run_stencileval("--tables " + table.string() + " --mesh " + (kMeshes / (std::string(name) + ".obj")).string() +
                                        " --batch " + (dir / "q.txt").string() + " --normal");
    REQUIRE(r.status == 0);
    std::istringstream lines(r.output);
    for (std::size_t k : sample) {
      Point p{}, normal{};
      REQUIRE(static_cast<bool>(lines >> p[0] >> p[1] >> p[2] >> normal[0] >> normal[1] >> normal[2]));
      const auto& m = soup.normals[k];
      INFO(name << " point " << k);
      REQUIRE(distance(normal, {m[0], m[1], m[2]}) < 1e-6);
    }
    CHECK(sample.size() > 10);
    fs::remove_all(dir);
  }
}
