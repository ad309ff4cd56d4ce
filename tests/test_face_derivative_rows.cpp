// The triangle tessellation's fast routes to normals, against what does not
// use them: Loop's row-by-row derivative polynomials (face_derivative_rows)
// against the chain rule through the tables' patch polynomial, and the whole
// tessellation's normals at rates that take that route against
// Surface::normal (the descent); sqrt(3)'s sparse derivative stencils against
// the dense ones they were made from.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "bundled_meshes.hpp"
#include "cli.hpp"
#include "runtime_api.hpp"
#include "runtime_checks.hpp"
#include "triangle/face_derivative_rows.hpp"
#include "triangle/triangle_family.hpp"

using namespace stencil_runtime;
using namespace test_runtime;
using test_meshes::bundled;

namespace {

double norm(const Point& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

// The patch polynomial's partials at (x, y), written out term by term from the
// tables' coefficients (f-major: f = 0..d, e = 0..d-f).
void patch_partials(const TriangleTables& t, const std::vector<Point>& control, double x, double y, Point& px, Point& py) {
  const int d = t.polynomial_degree();
  const std::size_t terms = static_cast<std::size_t>((d + 1) * (d + 2) / 2);
  px = py = {0, 0, 0};
  for (std::size_t h = 0; h < control.size(); ++h) {
    std::size_t k = 0;
    for (int f = 0; f <= d; ++f)
      for (int e = 0; e + f <= d; ++e, ++k) {
        const double c = t.polynomial()[h * terms + k];
        const double dx = e == 0 ? 0 : e * std::pow(x, e - 1) * std::pow(y, f);
        const double dy = f == 0 ? 0 : f * std::pow(x, e) * std::pow(y, f - 1);
        for (std::size_t i = 0; i < 3; ++i) px[i] += c * dx * control[h][i], py[i] += c * dy * control[h][i];
      }
  }
}

}  // namespace

TEST_CASE("Loop's row-by-row face derivatives equal the patch polynomial's by the chain rule, for every rotation",
          "[runtime][derivatives][triangle]") {
  const auto tables = Tables::load(generated_table("loop", "--valence 3-8 --n 1-8", "sgt").string());
  const TriangleTables& t = tables->triangle();
  REQUIRE(t.polynomial_degree() == 4);
  const std::size_t m = t.layout(6).size();
  const FaceDerivativeRows rows(t.polynomial_degree(), t.polynomial(), m);
  REQUIRE(rows.points() == m);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> coordinate(-3, 3), unit(0, 1);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Point> control(m);
    for (Point& q : control) q = {coordinate(rng), coordinate(rng), coordinate(rng)};
    for (int rotation = 0; rotation < 3; ++rotation) {
      FaceDerivativeRows::Face face(rows, rotation, control.data());
      for (int sample = 0; sample < 10; ++sample) {
        const double t_row = unit(rng), s = unit(rng) * (1 - t_row);
        face.start_row(t_row);
        Point ds, dt;
        face.at(s, ds, dt);
        // The patch's (x, y) of the face's (s, t) (TrianglePatch::to_patch), and its Jacobian.
        double x = s, y = t_row, xs = 1, xt = 0, ys = 0, yt = 1;
        if (rotation == 1) x = t_row, y = 1 - s - t_row, xs = 0, xt = 1, ys = -1, yt = -1;
        if (rotation == 2) x = 1 - s - t_row, y = s, xs = -1, xt = -1, ys = 1, yt = 0;
        Point px, py;
        patch_partials(t, control, x, y, px, py);
        INFO("trial " << trial << " rotation " << rotation << " at (" << s << ", " << t_row << ")");
        for (std::size_t i = 0; i < 3; ++i) {
          const double scale = 1 + norm(px) + norm(py);
          CHECK(std::fabs(ds[i] - (px[i] * xs + py[i] * ys)) < 1e-12 * scale);
          CHECK(std::fabs(dt[i] - (px[i] * xt + py[i] * yt)) < 1e-12 * scale);
        }
      }
    }
  }
}

TEST_CASE("Loop tessellation normals at rates that go row by row equal Surface::normal, face by face",
          "[runtime][derivatives][triangle][tessellation]") {
  const auto tables = Tables::load(generated_table("loop", "--valence 3-8 --n 1-8", "sgt").string());
  for (const char* name : {"tri-mix", "tri-torus"}) {
    const Mesh mesh = bundled(name);
    const Surface surface = surface_of(tables, mesh);
    const auto& family = dynamic_cast<const TriangleFamily&>(surface.topology().family());
    // Prepared rate 8 (from rate 6 up the normals of regular faces go row by row).
    const int rate = 8 << family.refinement_steps();
    const std::vector<int> prepared = family.hierarchy().prepared_rates(std::vector<int>(mesh.face_count(), rate));
    const PolygonSoup soup = tessellate(surface, std::vector<int>(mesh.face_count(), rate), {}, true);
    REQUIRE(soup.normals.size() == soup.positions.size());
    std::size_t regular = 0, checked = 0, k = 0;
    for (std::size_t pf = 0; pf < prepared.size(); ++pf) {
      const long n = prepared[pf];
      REQUIRE(n == 8);
      regular += family.patch(pf).valence == 6 && family.patch(pf).region == 0;
      auto check = [&](long a, long b) {
        const FaceParameterReal o = family.original(pf, static_cast<double>(a) / (3.0 * n), static_cast<double>(b) / (3.0 * n));
        const Point expected = surface.normal(o.face, o.u, o.v);
        const auto& got = soup.normals[k++];
        INFO(name << " prepared face " << pf << " point " << k - 1);
        REQUIRE(distance(expected, {got[0], got[1], got[2]}) < 1e-6);
        ++checked;
      };
      for (long j = 0; j < n; ++j)
        for (long i = 0; i + j <= n - 1; ++i) check(3 * i + 1, 3 * j + 1);
      for (long j = 0; j + 1 < n; ++j)
        for (long i = 0; i + j <= n - 2; ++i) check(3 * i + 2, 3 * j + 2);
    }
    INFO(name);
    CHECK(regular >= prepared.size() / 4);  // the row route is what is tested (tri-mix: 18 of 72 faces)
    CHECK(checked == prepared.size() * 64);
  }
}

TEST_CASE("sqrt(3)'s sparse jets hold every nonzero value and derivative weight of the dense stencils, and only those",
          "[runtime][derivatives][sqrt3]") {
  const auto tables = Tables::load(generated_table("sqrt3", "--valence 3-8 --n 1-9", "sgt").string());
  const TriangleTables& t = tables->triangle();
  const std::size_t m = t.layout(6).size();
  std::size_t dropped = 0;
  for (int n = 1; n <= 9; ++n) {
    const TriangleTables::Grid grid = t.grid(6, n);
    for (int kind = 0; kind < 3; ++kind)
      for (long j = 0; j + kind <= n; ++j)
        for (long i = 0; i + j + kind <= n; ++i) {
          const auto at = static_cast<TriangleTables::GridPoint>(kind);
          const double *du = nullptr, *dv = nullptr;
          TriangleTables::Grid::SparseJet s;
          REQUIRE(grid.derivative_weights(at, i, j, du, dv));
          REQUIRE(grid.sparse_jet(at, i, j, s));
          const double* w = grid.weights(at, i, j);
          std::vector<double> value(m, 0.0), u(m, 0.0), v(m, 0.0);
          for (std::size_t k = 0; k < s.count; ++k) {
            REQUIRE(s.column[k] < m);
            REQUIRE((k == 0 || s.column[k] > s.column[k - 1]));  // ascending: the value's sum keeps the dense order
            const double* c = s.wuv + 3 * k;
            REQUIRE((c[0] != 0 || c[1] != 0 || c[2] != 0));
            value[s.column[k]] = c[0], u[s.column[k]] = c[1], v[s.column[k]] = c[2];
          }
          for (std::size_t h = 0; h < m; ++h) REQUIRE((value[h] == w[h] && u[h] == du[h] && v[h] == dv[h]));
          dropped += m - s.count;
        }
  }
  CHECK(dropped > 0);  // the regular basis reaches 2.5 rings of the 3 its layout holds
}
