// Semi-sharp creases and corners (OpenSubdiv's `crease` and `corner` tags,
// uniform and Chaikin methods) on closed Catmull-Clark meshes: resolved by
// whole-mesh steps with the sharp rules, then evaluated exactly from the
// smooth tables. Oracles: OpenSubdiv's Far (uniform refinement with the same
// tags, in double, to the level where every sharpness has decayed, then its
// exact limit masks) and, for the uniform method, Bfr with the same tags.
// Bfr 3.5 does not follow Far's Chaikin rule where a semi-sharp edge of
// sharpness < 1 meets a sharper one (it differs from Far's own refinement by
// 0.8% of the size on the cube below), so Chaikin is checked against Far only.

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <set>

#include "bfr_reference.hpp"
#include "cli.hpp"
#include "runtime_api.hpp"
#include "open_meshes.hpp"
#include "runtime_checks.hpp"
#include "sharp_features.hpp"
#include "quad/quad_creases.hpp"
#include "tables/triangle_tables.hpp"

using namespace stencil_runtime;
using namespace test_runtime;
namespace fs = std::filesystem;

namespace {

const fs::path kMeshes = fs::path(STENCIL_SOURCE_DIR) / "meshes";

Mesh load(const std::string& name) { return read_obj((kMeshes / (name + ".obj")).string()); }

// The cube with its first face replaced by a pyramid of four triangles: the
// polygon step then runs with creases on it.
std::vector<std::pair<int, int>> edges_of(const Mesh& m) {
  std::set<std::pair<int, int>> out;
  std::size_t corner = 0;
  for (int k : m.face_sizes) {
    for (int c = 0; c < k; ++c) {
      const int a = m.face_vertices[corner + static_cast<std::size_t>(c)], b = m.face_vertices[corner + static_cast<std::size_t>((c + 1) % k)];
      out.insert({std::min(a, b), std::max(a, b)});
    }
    corner += static_cast<std::size_t>(k);
  }
  return {out.begin(), out.end()};
}

using Features = SharpFeatures;

Surface surface_with(const std::shared_ptr<const Tables>& tables, const Mesh& mesh, const Features& f) {
  return Surface(SurfaceTopology::create(tables, mesh.vertex_count(), mesh.face_sizes, mesh.face_vertices, {}, f.ours),
                 mesh.positions);
}

bool is_loop(const std::shared_ptr<const Tables>& tables) { return tables->family() == SchemeFamily::Triangle; }

bfr_reference::osd::Sdc::SchemeType osd_scheme(const std::shared_ptr<const Tables>& tables) {
  return is_loop(tables) ? bfr_reference::osd::Sdc::SCHEME_LOOP : bfr_reference::osd::Sdc::SCHEME_CATMARK;
}

// Largest distance to Bfr over the mesh size, at every node of every quad
// (Catmull-Clark) or triangle (Loop) at rates 1..8 (but at the corners on the
// vertices `except`).
double bfr_difference(const std::shared_ptr<const Tables>& tables, const Mesh& mesh, const Features& f,
                      const std::set<int>& except = {}) {
  const Surface surface = surface_with(tables, mesh, f);
  bfr_reference::BfrLimit reference(mesh.positions, mesh.face_sizes, mesh.face_vertices, osd_scheme(tables), {}, f.osd);
  const double size = extent(mesh);
  const bool loop = is_loop(tables);
  double worst = 0;
  for (std::size_t face = 0; face < mesh.face_count(); ++face) {
    if (mesh.face_sizes[face] != (loop ? 3 : 4)) continue;
    const bool hole = surface.topology().is_hole(face);
    CHECK(hole == !reference.has_surface(static_cast<int>(face)));  // `none`: the faces at boundary vertices
    if (hole) continue;
    for (long n = 1; n <= 8; ++n)
      for (long j = 0; j <= n; ++j)
        for (long i = 0; i + (loop ? j : 0) <= n; ++i) {
          if (!except.empty() && (i == 0 || i == n) && (j == 0 || j == n)) {  // a quad's corner
            const int c = i == 0 ? (j == 0 ? 0 : 3) : (j == 0 ? 1 : 2);
            std::size_t first = 0;
            for (std::size_t g = 0; g < face; ++g) first += static_cast<std::size_t>(mesh.face_sizes[g]);
            if (except.count(mesh.face_vertices[first + static_cast<std::size_t>(c)])) continue;
          }
          const Point ours = surface.evaluate(face, grid(i, j, n));
          const auto ref = reference.evaluate(static_cast<int>(face), static_cast<double>(i) / n, static_cast<double>(j) / n);
          worst = std::max(worst, distance(ours, ref) / size);
        }
  }
  return worst;
}

// Far's vertices of uniform refinement level `level` (in double), and, with
// `limit`, their limit points (every sharpness having decayed by then).
std::vector<Point> far_points(const Mesh& mesh, const Features& f, int level, bfr_reference::osd::Sdc::SchemeType scheme,
                              bool with_limit) {
  return bfr_reference::far_points(mesh.positions, mesh.face_sizes, mesh.face_vertices, scheme, f.osd, level, with_limit);
}

// Largest distance, over the mesh size, from our surface at every node of rate
// 2^level of every quad (triangle for Loop) to the nearest of Far's limit
// points at that level (which are those nodes, in another order).
double far_difference(const std::shared_ptr<const Tables>& tables, const Mesh& mesh, const Features& f, int level) {
  const Surface surface = surface_with(tables, mesh, f);
  std::vector<Point> reference = far_points(mesh, f, level, osd_scheme(tables), true);
  std::sort(reference.begin(), reference.end());
  const double size = extent(mesh);
  const long n = 1L << level;
  const bool loop = is_loop(tables);
  double worst = 0;
  for (std::size_t face = 0; face < mesh.face_count(); ++face) {
    if (mesh.face_sizes[face] != (loop ? 3 : 4)) continue;
    for (long j = 0; j <= n; ++j)
      for (long i = 0; i + (loop ? j : 0) <= n; ++i) {
        const Point ours = surface.evaluate(face, grid(i, j, n));
        // Candidates: reference points whose x is within 1e-6 of the size (sorted by x).
        const auto first = std::lower_bound(reference.begin(), reference.end(), Point{ours[0] - 1e-6 * size, -1e300, -1e300});
        double nearest = 1e300;
        for (auto it = first; it != reference.end() && (*it)[0] <= ours[0] + 1e-6 * size; ++it)
          nearest = std::min(nearest, distance(ours, *it));
        worst = std::max(worst, std::min(nearest, 1e300) / size);
      }
  }
  return worst;
}

// Largest distance, over the mesh size, between the prepared mesh's vertices
// (every step so far is a whole-mesh step) and Far's vertices at the same
// level, matched as sets.
double far_prepared_difference(const std::shared_ptr<const Tables>& tables, const Mesh& mesh, const Features& f) {
  const Surface surface = surface_with(tables, mesh, f);
  std::vector<Point> reference = far_points(mesh, f, surface.topology().refinement_steps(), osd_scheme(tables), false);
  REQUIRE(reference.size() == surface.prepared_positions().size());
  std::sort(reference.begin(), reference.end());
  const double size = extent(mesh);
  double worst = 0;
  for (const Point& ours : surface.prepared_positions()) {
    const auto first = std::lower_bound(reference.begin(), reference.end(), Point{ours[0] - 1e-6 * size, -1e300, -1e300});
    double nearest = 1e300;
    for (auto it = first; it != reference.end() && (*it)[0] <= ours[0] + 1e-6 * size; ++it) nearest = std::min(nearest, distance(ours, *it));
    worst = std::max(worst, nearest / size);
  }
  return worst;
}

// About one edge in four creased and `corners` vertices sharp, with sharpness
// from 0.3 (uniform) or 0.25 (Chaikin: it averages the sharpness round a
// vertex in float, as OpenSubdiv does, but not necessarily in its order, so
// with non-dyadic values the results may differ at float precision: 1.3e-10
// of the size on the chess piece) to 2.25.
Features random_features(const Mesh& mesh, bool chaikin, int corners, std::mt19937& rng) {
  const float choices[] = {chaikin ? 0.25f : 0.3f, 0.5f, 1.0f, 1.5f, 2.25f};
  Features f;
  for (const auto& [a, b] : edges_of(mesh))
    if (rng() % 4 == 0) f.crease(a, b, choices[rng() % 5]);
  for (int k = 0; k < corners; ++k) f.corner(static_cast<int>(rng() % mesh.vertex_count()), choices[rng() % 5]);
  if (chaikin) f.chaikin();
  return f;
}

std::shared_ptr<const Tables> catmull_clark() {
  return Tables::load(generated_table("catmull-clark", "--valence 3-8 --n 8", "sgs").string());
}

}  // namespace

TEST_CASE("semi-sharp creases on the cube equal OpenSubdiv's, at sharpness 0.3, 0.5, 1 and 2.5 and at darts",
          "[runtime][creases][opensubdiv]") {
  const auto tables = catmull_clark();
  const Mesh cube = load("cube");
  const auto edges = edges_of(cube);
  for (float s : {0.3f, 0.5f, 1.0f, 2.5f}) {
    Features one;  // one sharp edge: both its ends are darts
    one.crease(edges[0].first, edges[0].second, s);
    INFO("one edge of sharpness " << s);
    CHECK(bfr_difference(tables, cube, one) < 1e-10);
    CHECK(far_difference(tables, cube, one, 3) < 1e-10);
  }
  // Loops round a face, of mixed sharpness: crease vertices and rule
  // transitions, and for Chaikin an edge of sharpness < 1 that stays sharp at
  // one end (0.5 next to 3).
  const std::vector<int> top(cube.face_vertices.begin(), cube.face_vertices.begin() + 4);
  for (const std::array<float, 4>& loop : {std::array<float, 4>{2.5f, 1.0f, 0.5f, 3.0f}, std::array<float, 4>{2.0f, 1.0f, 2.0f, 1.0f},
                                           std::array<float, 4>{1.5f, 0.25f, 0.0f, 0.75f}})
    for (bool chaikin : {false, true}) {
      Features f;
      for (std::size_t c = 0; c < 4; ++c)
        if (loop[c] > 0) f.crease(top[c], top[(c + 1) % 4], loop[c]);
      if (chaikin) f.chaikin();
      INFO((chaikin ? "Chaikin" : "uniform") << " loop of sharpness " << loop[0] << ", " << loop[1] << ", " << loop[2] << ", " << loop[3]);
      CHECK(far_difference(tables, cube, f, 3) < 1e-10);
      if (!chaikin) CHECK(bfr_difference(tables, cube, f) < 1e-10);
    }
}

TEST_CASE("corners: vertex sharpness and three sharp edges at a vertex equal OpenSubdiv's", "[runtime][creases][opensubdiv]") {
  const auto tables = catmull_clark();
  const Mesh cube = load("cube");
  for (float s : {0.5f, 1.5f, 3.0f}) {
    Features f;
    f.corner(0, s);
    INFO("vertex sharpness " << s);
    CHECK(bfr_difference(tables, cube, f) < 1e-10);
    CHECK(far_difference(tables, cube, f, 3) < 1e-10);
  }
  for (bool chaikin : {false, true}) {
    Features three;  // three sharp edges make vertex 0 a corner, their other ends darts
    for (const auto& [a, b] : edges_of(cube))
      if (a == 0 || b == 0) three.crease(a, b, a + b > 3 ? 2.0f : 0.75f);
    if (chaikin) three.chaikin();
    INFO((chaikin ? "Chaikin" : "uniform") << " corner of three sharp edges");
    CHECK(far_difference(tables, cube, three, 2) < 1e-10);
    if (!chaikin) CHECK(bfr_difference(tables, cube, three) < 1e-10);
  }
}

TEST_CASE("infinitely sharp creases and corners (sharpness >= 10) on quad meshes equal OpenSubdiv's, semi-sharp ones "
          "beside them too",
          "[runtime][creases][sharp][opensubdiv]") {
  const auto tables = catmull_clark();
  const Mesh cube = load("cube");
  const Mesh chess = load("chess-piece");
  const std::vector<int> top(cube.face_vertices.begin(), cube.face_vertices.begin() + 4);
  struct Case {
    std::string name;
    Mesh mesh;
    Features f;
    std::set<int> darts;  // OpenSubdiv's limit there is not the limit (see the next test): compared elsewhere
  };
  std::vector<Case> cases;
  {  // every edge: each vertex on three sharp edges, a corner; every face a patch of its own
    Case c{"cube, every edge infinitely sharp", cube, {}, {}};
    for (const auto& [a, b] : edges_of(cube)) c.f.crease(a, b, 10);
    cases.push_back(c);
  }
  {  // a loop round the top face: its vertices on two sharp edges, in one face above and two below
    Case c{"cube, a sharp loop round a face", cube, {}, {}};
    for (std::size_t k = 0; k < 4; ++k) c.f.crease(top[k], top[(k + 1) % 4], 10);
    cases.push_back(c);
  }
  {  // the loop, with a corner tag on one of its vertices and a semi-sharp edge leaving another
    Case c{"cube, a sharp loop, a sharp corner and a semi-sharp edge of 1.5 at its vertices", cube, {}, {}};
    for (std::size_t k = 0; k < 4; ++k) c.f.crease(top[k], top[(k + 1) % 4], 12.5f);
    c.f.corner(top[0], 10);
    for (const auto& [a, b] : edges_of(cube))
      if ((a == top[2]) != (b == top[2]) && std::find(top.begin(), top.end(), a + b - top[2]) == top.end()) c.f.crease(a, b, 1.5f);
    cases.push_back(c);
  }
  {  // three sharp edges at vertex 0, continued to the opposite corner: no dart
    Case c{"cube, sharp paths from vertex 0 to the opposite corner", cube, {}, {}};
    const auto e = edges_of(cube);
    std::set<int> on;
    for (const auto& [a, b] : e)
      if (a == 0 || b == 0) on.insert(a + b);
    for (const auto& [a, b] : e)
      if (a == 0 || b == 0 || (on.count(a) + on.count(b) == 1 && a != 0 && b != 0)) c.f.crease(a, b, 10);
    cases.push_back(c);
  }
  {  // the chess piece: every edge of its first face's vertex ring... its first face's edges, a sharp loop
    Case c{"chess piece, a sharp loop round a face with extraordinary corners", chess, {}, {}};
    const std::vector<int> ring(chess.face_vertices.begin(), chess.face_vertices.begin() + chess.face_sizes[0]);
    for (std::size_t k = 0; k < ring.size(); ++k) c.f.crease(ring[k], ring[(k + 1) % ring.size()], 10);
    cases.push_back(c);
  }
  {  // one sharp edge: both its ends are darts (the crease's own ends inside the mesh)
    Case c{"cube, one sharp edge (two darts)", cube, {}, {edges_of(cube)[0].first, edges_of(cube)[0].second}};
    c.f.crease(edges_of(cube)[0].first, edges_of(cube)[0].second, 10);
    cases.push_back(c);
  }
  {  // a sharp path of three edges on the chess piece: darts at its ends, crease vertices between, of any valence
    const std::vector<int> ring(chess.face_vertices.begin(), chess.face_vertices.begin() + chess.face_sizes[0]);
    Case c{"chess piece, a sharp path of three edges (darts at its ends)", chess, {}, {ring[0], ring[3]}};
    for (std::size_t k = 0; k < 3; ++k) c.f.crease(ring[k], ring[k + 1], 10);
    cases.push_back(c);
  }
  {  // cone points: sharp vertices on no sharp edge (OpenSubdiv's corner rule, smooth edges round them), valence 3
    Case c{"cube, two cone points at opposite corners", cube, {}, {}};
    c.f.corner(0, 10);
    c.f.corner(7, 10);
    cases.push_back(c);
  }
  {  // cone points of valence 4 (a regular vertex made irregular by its tag) and 5, one next to a semi-sharp edge
    std::vector<int> faces_at(chess.vertex_count(), 0);
    for (int v : chess.face_vertices) ++faces_at[static_cast<std::size_t>(v)];
    const auto four = std::find(faces_at.begin(), faces_at.end(), 4), five = std::find(faces_at.begin(), faces_at.end(), 5);
    REQUIRE(four != faces_at.end());
    REQUIRE(five != faces_at.end());
    Case c{"chess piece, cone points of valence 4 and 5, a semi-sharp edge of 1.5 at one", chess, {}, {}};
    const int v4 = static_cast<int>(four - faces_at.begin()), v5 = static_cast<int>(five - faces_at.begin());
    c.f.corner(v4, 10);
    c.f.corner(v5, 10);
    for (const auto& [a, b] : edges_of(chess))
      if (a == v5 || b == v5) {
        c.f.crease(a, b, 1.5f);
        break;
      }
    cases.push_back(c);
  }
  {  // an open grid: two cone points side by side inside, next to the boundary (they share faces until steps part them)
    Mesh grid = test_meshes::open_grid(4, 3);
    Case c{"open grid, two neighbouring cone points next to the boundary", grid, {}, {}};
    c.f.corner(1 * 5 + 1, 10);  // (1, 1)
    c.f.corner(1 * 5 + 2, 10);  // (2, 1)
    cases.push_back(c);
  }
  {  // a dart whose end is also a sharp vertex: a corner on one sharp edge
    Case c{"cube, one sharp edge with a sharp vertex at one end", cube, {}, {edges_of(cube)[0].second}};
    c.f.crease(edges_of(cube)[0].first, edges_of(cube)[0].second, 10);
    c.f.corner(edges_of(cube)[0].first, 10);
    cases.push_back(c);
  }
  {  // an open grid: a sharp line across it, boundary to boundary, and a sharp corner on its boundary in two faces
    Mesh grid = test_meshes::open_grid(4, 3);
    Case c{"open grid, a sharp line across and a sharp boundary corner", grid, {}, {}};
    for (int i = 0; i < 4; ++i) c.f.crease(1 * 5 + i, 1 * 5 + i + 1, 10);  // row j = 1, vertices (i, 1)
    c.f.corner(2, 10);                                                   // (2, 0): on the boundary in two faces
    cases.push_back(c);
  }
  for (const Case& c : cases) {
    INFO(c.name);
    const double worst = bfr_difference(tables, c.mesh, c.f, c.darts);
    CHECK(worst < 1e-10);
    if (c.darts.empty()) CHECK(far_difference(tables, c.mesh, c.f, 3) < 1e-10);
    WARN(c.name << ": largest difference to Bfr over the mesh size " << worst);
  }
}

TEST_CASE("boundary interpolation none with infinitely sharp creases, darts and cone points gives no surface at the "
          "faces at the mesh's own boundary vertices and Bfr's surface at every other face",
          "[runtime][creases][sharp][boundaries][opensubdiv]") {
  const auto tables = catmull_clark();
  {  // an open grid: a sharp line across it, boundary to boundary; a sharp edge leaving it (a corner on the line,
     // a dart inside); a cone point next to the boundary
    const Mesh grid = test_meshes::open_grid(6, 5);
    auto at = [](int i, int j) { return j * 7 + i; };
    Features f;
    f.boundary_none();
    for (int i = 0; i < 6; ++i) f.crease(at(i, 2), at(i + 1, 2), 10);
    f.crease(at(3, 2), at(3, 3), 10);
    f.corner(at(1, 4), 10);
    const Surface surface = surface_with(tables, grid, f);
    std::size_t with_surface = 0;
    for (std::size_t face = 0; face < grid.face_count(); ++face) with_surface += !surface.topology().is_hole(face);
    CHECK(with_surface == 4 * 3);  // the faces touching no boundary vertex
    check_rimmed_manifold(tessellate(surface, std::vector<int>(grid.face_count(), 3)), 1, 0);  // a disc, across the creases
    const double worst = bfr_difference(tables, grid, f, {at(3, 3)});  // but at the dart vertex (OpenSubdiv's limit misses it)
    CHECK(worst < 1e-10);
    WARN("open grid with `none`, a sharp line, a dart and a cone point: largest difference to Bfr over the size " << worst);
  }
  {  // a tube: a sharp ring round its middle, a semi-sharp edge of 1.5 beside it
    const Mesh tube = test_meshes::tube(8, 6);
    Features f;
    f.boundary_none();
    for (int i = 0; i < 8; ++i) f.crease(3 * 8 + i, 3 * 8 + (i + 1) % 8, 10);
    f.crease(3 * 8 + 2, 4 * 8 + 2, 1.5f);
    const double worst = bfr_difference(tables, tube, f);
    CHECK(worst < 1e-10);
    check_rimmed_manifold(tessellate(surface_with(tables, tube, f), std::vector<int>(tube.face_count(), 4)), 2, 0);  // a band
    WARN("tube with `none` and a sharp ring: largest difference to Bfr over the size " << worst);
  }
}

TEST_CASE("at an infinitely sharp dart the limit point is the exact one, which OpenSubdiv's refined points approach and "
          "its dart limit mask (the smooth one) misses, and the normal the limit of the normals next to it",
          "[runtime][creases][sharp][opensubdiv]") {
  const auto tables = catmull_clark();
  const Mesh cube = load("cube");
  Features f;
  const auto [a, b] = edges_of(cube)[0];
  f.crease(a, b, 10);
  const Surface surface = surface_with(tables, cube, f);
  const double size = extent(cube);
  std::size_t face = 0;  // a face at vertex a, which is its corner c
  int c = -1;
  for (; c < 0; ++face)
    for (int k = 0; k < 4; ++k)
      if (cube.face_vertices[4 * face + static_cast<std::size_t>(k)] == a) c = k;
  --face;
  const Point ours = surface.evaluate(face, grid(c == 1 || c == 2, c >= 2, 1));
  // Far's refined vertices nearest ours, level by level: the dart vertex itself, converging to the limit.
  std::vector<double> refined, mask;
  for (int level : {6, 8, 10}) {
    double r = 1e300, m = 1e300;
    for (const Point& p : far_points(cube, f, level, osd_scheme(tables), false)) r = std::min(r, distance(p, ours));
    for (const Point& p : far_points(cube, f, level, osd_scheme(tables), true)) m = std::min(m, distance(p, ours));
    refined.push_back(r / size), mask.push_back(m / size);
  }
  CHECK(refined[2] < 2e-5);
  CHECK(refined[1] < refined[0] / 3);
  CHECK(refined[2] < refined[1] / 3);
  // OpenSubdiv's limit mask at a dart is the smooth vertex's, not the dart's own eigenvector: applied at level L its
  // point is off, less so the deeper L (its refined neighbours approach the dart's own configuration); Bfr, which
  // refines to its approximation level 10 and applies the mask there, is off by the same at the vertex.
  CHECK(mask[2] > 1e-6);
  CHECK(mask[1] < mask[0]);
  CHECK(mask[2] < mask[1]);
  bfr_reference::BfrLimit reference(cube.positions, cube.face_sizes, cube.face_vertices, osd_scheme(tables), {}, f.osd);
  const double bfr = distance(reference.evaluate(static_cast<int>(face), c == 1 || c == 2, c >= 2), ours) / size;
  CHECK(std::abs(bfr - mask[2]) < 1e-3 * mask[2]);
  WARN("dart vertex: Far's refined vertex at levels 6, 8, 10 is " << refined[0] << ", " << refined[1] << ", " << refined[2]
       << " of the size from our limit point; its dart limit mask applied at those levels " << mask[0] << ", " << mask[1]
       << ", " << mask[2] << "; Bfr (level 10) " << bfr);
  // And our surface next to the vertex approaches our limit point.
  const double e = std::ldexp(1.0, -30);
  const double u = (c == 1 || c == 2) ? 1 - e : e, v = c >= 2 ? 1 - e : e;
  CHECK(distance(surface.evaluate(face, u, v, 1e-14).point, ours) / size < 1e-8);
  // The normal at the dart (its tangent stencils: the slit folded shut) is the limit of the normals next to it,
  // from every face round it.
  auto angle = [](const Point& p, const Point& q) {
    const Point x{p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
    return std::atan2(std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]), p[0] * q[0] + p[1] * q[1] + p[2] * q[2]);
  };
  for (std::size_t g = 0; g < cube.face_count(); ++g)
    for (int k = 0; k < 4; ++k) {
      if (cube.face_vertices[4 * g + static_cast<std::size_t>(k)] != a) continue;
      const double cu = k == 1 || k == 2, cv = k >= 2;
      const Point n = surface.normal(g, cu, cv);
      std::vector<double> off;
      for (int depth : {5, 10, 20}) {
        const double d = std::ldexp(1.0, -depth);
        off.push_back(angle(surface.derivatives(g, cu == 1 ? 1 - d : d, cv == 1 ? 1 - d : d).normal(), n));
      }
      CHECK(off[2] < 1e-3);
      CHECK(off[2] < off[1]);
      CHECK(off[1] < off[0]);
      CHECK(angle(n, surface.normal(face, c == 1 || c == 2, c >= 2)) < 1e-10);
    }
}

TEST_CASE("infinitely sharp creases: tessellations stay closed across them, darts and cone points too, and a cone point "
          "stays where its control vertex is and has no normal",
          "[runtime][creases][sharp]") {
  const Mesh cube = load("cube");
  const std::vector<int> top(cube.face_vertices.begin(), cube.face_vertices.begin() + 4);
  std::mt19937 rng(5);
  for (const char* scheme : {"nonpoly", "catmull-clark"}) {
    const auto tables = Tables::load(generated_table(scheme, "--valence 3-8 --n 1-8", "sgs").string());
    Features loop;  // a sharp loop round the top face, and a sharp edge going down from it (its lower end a dart)
    for (std::size_t k = 0; k < 4; ++k) loop.crease(top[k], top[(k + 1) % 4], 10);
    for (const auto& [a, b] : edges_of(cube))
      if ((a == top[0]) != (b == top[0]) && std::find(top.begin(), top.end(), a + b - top[0]) == top.end()) {
        loop.crease(a, b, 10);
        break;
      }
    // A cone point: a vertex on none of those sharp edges, tagged sharp.
    std::set<int> on_sharp;
    for (const auto& e : loop.ours.edges) on_sharp.insert(e.a), on_sharp.insert(e.b);
    int cone = 0;
    while (on_sharp.count(cone)) ++cone;
    loop.corner(cone, 10);
    const Surface surface = surface_with(tables, cube, loop);
    {  // the corner rule holds the vertex at every step: the limit there is the control vertex itself
      std::size_t face = 0;
      int corner = 0;
      while (cube.face_vertices[4 * face + static_cast<std::size_t>(corner)] != cone)
        if (++corner == 4) corner = 0, ++face;
      const Point at = surface.evaluate(face, grid(corner == 1 || corner == 2, corner >= 2, 1));
      CHECK(distance(at, cube.positions[static_cast<std::size_t>(cone)]) == 0);
      CHECK_THROWS_WITH(surface.normal(face, corner == 1 || corner == 2, corner >= 2), Catch::Contains("cone point has no tangent plane"));
    }
    for (int trial = 0; trial < 4; ++trial) {
      std::vector<int> rates(cube.face_count());
      for (int& r : rates) r = std::uniform_int_distribution<int>(1, 8)(rng);
      INFO(scheme << ", trial " << trial);
      const PolygonSoup soup = tessellate(surface, rates);
      CHECK(tessellation_defect(soup, 2).empty());  // closed, oriented, V - E + F = 2
    }
    // Positions agree across every edge, the sharp ones included.
    double worst = 0;
    for (std::size_t f = 0; f < cube.face_count(); ++f)
      for (std::size_t g = 0; g < cube.face_count(); ++g) {
        if (f == g) continue;
        for (int a = 0; a < 4; ++a)
          for (int b = 0; b < 4; ++b) {
            const int fa = cube.face_vertices[4 * f + static_cast<std::size_t>(a)], fb = cube.face_vertices[4 * f + static_cast<std::size_t>((a + 1) % 4)];
            if (cube.face_vertices[4 * g + static_cast<std::size_t>(b)] != fb || cube.face_vertices[4 * g + static_cast<std::size_t>((b + 1) % 4)] != fa) continue;
            for (long t = 0; t <= 8; ++t) {
              // Along edge a -> a+1 of f and b -> b+1 of g (reversed), in each face's own (u, v).
              auto at = [&](int corner, long k) -> ExactParameter {
                const Fraction s = Fraction::make(k, 8), one = Fraction::make(1, 1), zero = Fraction::make(0, 1);
                switch (corner) {
                  case 0: return {s, zero};
                  case 1: return {one, s};
                  case 2: return {subtract(one, s), one};
                  default: return {zero, subtract(one, s)};
                }
              };
              worst = std::max(worst, distance(surface.evaluate(f, at(a, t)), surface.evaluate(g, at(b, 8 - t))));
            }
          }
      }
    CHECK(worst < 1e-13);
  }
}

TEST_CASE("random creases and corners on the chess piece and on a mesh with triangles equal OpenSubdiv's, both methods",
          "[runtime][creases][opensubdiv]") {
  const auto tables = catmull_clark();
  std::mt19937 rng(20261125u);
  for (const Mesh& mesh : {load("chess-piece"), test_meshes::house()}) {
    for (bool chaikin : {false, true}) {
      const Features f = random_features(mesh, chaikin, 3, rng);
      INFO(mesh.face_count() << " faces, " << f.ours.edges.size() << " creases, " << (chaikin ? "Chaikin" : "uniform"));
      const double far = far_difference(tables, mesh, f, 3);
      CHECK(far < 1e-10);
      WARN(mesh.face_count() << "-face mesh, " << (chaikin ? "Chaikin" : "uniform") << ": largest difference to Far over the mesh size " << far);
      if (!chaikin) CHECK(bfr_difference(tables, mesh, f) < 1e-10);
    }
  }
}

namespace {

// The coefficient of a curve scheme's mask at `offset`, read from its scheme file ("p/q").
double mask_at(const std::string& curve, long offset) {
  std::ifstream in(fs::path(STENCIL_SOURCE_DIR) / "schemes" / (curve + ".json"));
  const nlohmann::json scheme = nlohmann::json::parse(in);
  const long first = scheme["mask"]["first"].get<long>();
  const auto& c = scheme["mask"]["coefficients"];
  if (offset < first || offset - first >= static_cast<long>(c.size())) return 0;
  const std::string q = c[static_cast<std::size_t>(offset - first)].get<std::string>();
  const auto slash = q.find('/');
  return slash == std::string::npos ? std::stod(q) : std::stod(q.substr(0, slash)) / std::stod(q.substr(slash + 1));
}

}  // namespace

TEST_CASE("the crease rule is the scheme's regular curve: the cubic B-spline for Catmull-Clark, nonpoly-curve for nonpoly",
          "[runtime][creases]") {
  for (const auto& [scheme, curve] : {std::pair{"catmull-clark", "bspline3"}, std::pair{"nonpoly", "nonpoly-curve"}}) {
    const auto tables = Tables::load(generated_table(scheme, "--valence 3-8 --n 8", "sgs").string());
    const CurveCreaseRule rule = quad_crease_rule(tables->quad(), scheme);
    INFO(scheme << " against " << curve << ".json");
    CHECK(rule.centre == Approx(mask_at(curve, 0)).epsilon(1e-15));
    CHECK(rule.neighbour == Approx(mask_at(curve, 2)).epsilon(1e-15));
    CHECK(mask_at(curve, -2) == mask_at(curve, 2));
    CHECK(mask_at(curve, 1) == 0.5);  // edge points are midpoints, as the runtime assumes
  }
  // Loop's is the crease_curve its scheme file names, carried by the .sgt file.
  const auto loop = Tables::load(generated_table("loop", "--valence 3-8 --n 8", "sgt").string());
  REQUIRE(loop->triangle().crease());
  CHECK(loop->triangle().crease()->centre == mask_at("bspline3", 0));
  CHECK(loop->triangle().crease()->neighbour == mask_at("bspline3", 2));
}

TEST_CASE("nonpoly and Catmull-Clark with creases: continuous across every edge, tessellations closed for random rate mixes",
          "[runtime][creases][tessellation]") {
  std::mt19937 rng(7u);
  const Mesh mesh = load("chess-piece");
  const auto edges = edges_of(mesh);
  Features f;
  for (const auto& [a, b] : edges)
    if (rng() % 4 == 0) f.crease(a, b, static_cast<float>(rng() % 9) / 4);
  f.corner(5, 1.5f);
  for (const char* scheme : {"nonpoly", "catmull-clark"}) {
    const auto tables = Tables::load(generated_table(scheme, "--valence 3-8 --n 8", "sgs").string());
    const Surface surface = surface_with(tables, mesh, f);
    INFO(scheme << ": " << surface.topology().preparation());
    // Each edge from both of its faces: corner c of a quad is (0,0), (1,0), (1,1), (0,1).
    const long corner_u[4] = {0, 1, 1, 0}, corner_v[4] = {0, 0, 1, 1};
    std::map<std::pair<int, int>, std::pair<std::size_t, int>> first_side;
    const double size = extent(mesh);
    double worst = 0;
    for (std::size_t face = 0; face < mesh.face_count(); ++face)
      for (int c = 0; c < 4; ++c) {
        const int a = mesh.face_vertices[4 * face + static_cast<std::size_t>(c)], b = mesh.face_vertices[4 * face + static_cast<std::size_t>((c + 1) % 4)];
        const auto other = first_side.find({b, a});
        if (other == first_side.end()) {
          first_side[{a, b}] = {face, c};
          continue;
        }
        const auto [g, d] = other->second;
        for (long t = 0; t <= 8; ++t) {  // t/8 along a -> b here, (8 - t)/8 along b -> a there
          auto along = [&](int k, long s) {
            const int k1 = (k + 1) % 4;
            return grid(corner_u[k] * (8 - s) + corner_u[k1] * s, corner_v[k] * (8 - s) + corner_v[k1] * s, 8);
          };
          worst = std::max(worst, distance(surface.evaluate(face, along(c, t)), surface.evaluate(g, along(d, 8 - t))) / size);
        }
      }
    CHECK(worst < 1e-13);
    for (int trial = 0; trial < 3; ++trial) {
      std::vector<int> rates(mesh.face_count());
      for (int& r : rates) r = 1 + static_cast<int>(rng() % 8);
      const PolygonSoup soup = tessellate(surface, rates);
      CHECK(tessellation_defect(soup, euler_characteristic(mesh)) == "");
    }
  }
}

TEST_CASE("Loop: semi-sharp creases and corners equal OpenSubdiv's, both methods", "[runtime][creases][opensubdiv]") {
  const auto tables = Tables::load(generated_table("loop", "--valence 3-8 --n 8", "sgt").string());
  std::mt19937 rng(11u);
  for (const char* name : {"icosahedron", "tri-torus", "tri-mix"}) {
    const Mesh mesh = load(name);
    for (bool chaikin : {false, true}) {
      const Features f = random_features(mesh, chaikin, 2, rng);
      INFO(name << ", " << f.ours.edges.size() << " creases, " << (chaikin ? "Chaikin" : "uniform"));
      const double far = far_difference(tables, mesh, f, 3);
      CHECK(far < 1e-10);
      WARN(name << " (Loop), " << (chaikin ? "Chaikin" : "uniform") << ": largest difference to Far over the mesh size " << far);
      if (!chaikin) CHECK(bfr_difference(tables, mesh, f) < 1e-10);
    }
  }
  // One edge at a time on the icosahedron: darts, and 0.5 next to 3 (Chaikin).
  const Mesh ico = load("icosahedron");
  const auto edges = edges_of(ico);
  for (float s : {0.5f, 1.0f, 2.5f}) {
    Features one;
    one.crease(edges[0].first, edges[0].second, s);
    CHECK(bfr_difference(tables, ico, one) < 1e-10);
    CHECK(far_difference(tables, ico, one, 3) < 1e-10);
  }
}

TEST_CASE("creases on sqrt(3) meshes and on tables without a crease rule are refused with the reason", "[runtime][creases]") {
  const auto tables = Tables::load(generated_table("sqrt3", "--valence 3-8 --n 3", "sgt").string());
  const Mesh ico = load("icosahedron");
  Features f;
  f.crease(edges_of(ico)[0].first, edges_of(ico)[0].second, 1.5f);
  CHECK_THROWS_WITH(surface_with(tables, ico, f), Catch::Contains("sqrt(3)") && Catch::Contains("no crease rule"));
  Features bad;
  bad.crease(0, 0, 1);
  CHECK_THROWS_WITH(surface_with(catmull_clark(), load("cube"), bad), Catch::Contains("edge 0-0 names no edge"));
  // Sharpness 9.5 takes 10 steps: from the icosahedron's 20 faces whole-mesh steps would make
  // 21 million faces, over the limit, so Loop refines round the crease instead, as
  // Catmull-Clark does (tests/test_loop_semi_sharp_levels.cpp, test_semi_sharp_levels.cpp).
  Features too_many;
  too_many.crease(edges_of(ico)[0].first, edges_of(ico)[0].second, 9.5f);
  const auto loop = Tables::load(generated_table("loop", "--valence 3-8 --n 3", "sgt").string());
  CHECK(surface_with(loop, ico, too_many).topology().preparation().find("refined round the semi-sharp") != std::string::npos);
  Features cube_crease;
  cube_crease.crease(0, 1, 9.5f);
  CHECK(surface_with(catmull_clark(), load("cube"), cube_crease).topology().preparation().find("refined round the semi-sharp") !=
        std::string::npos);
  Features infinite;  // on sqrt(3) infinitely sharp ones too (Loop evaluates them: test_loop_creases.cpp)
  infinite.crease(edges_of(ico)[0].first, edges_of(ico)[0].second, 10);
  CHECK_THROWS_WITH(surface_with(tables, ico, infinite), Catch::Contains("sqrt(3)") && Catch::Contains("no crease rule"));
  // Two icosahedra sharing a vertex, no tags: refused for the non-manifold vertex, named, not for "creases".
  Mesh bowtie = ico;
  const int shared = ico.face_vertices[0], offset = static_cast<int>(ico.vertex_count());
  for (const Point& p : ico.positions)
    bowtie.positions.push_back({2 * ico.positions[static_cast<std::size_t>(shared)][0] - p[0], p[1], p[2]});
  for (std::size_t k = 0; k < ico.face_vertices.size(); k += 3)
    for (const std::size_t c : {std::size_t{0}, std::size_t{2}, std::size_t{1}}) {  // mirrored: turned to keep facing out
      const int v = ico.face_vertices[k + c];
      bowtie.face_vertices.push_back(v == shared ? shared : v + offset);
    }
  bowtie.face_sizes.resize(2 * ico.face_count(), 3);
  CHECK_THROWS_WITH(surface_with(tables, bowtie, Features{}),
                    Catch::Contains("vertex " + std::to_string(shared) + " is non-manifold") && Catch::Contains("sqrt(3)"));
}

TEST_CASE("OpenSubdiv's smooth triangle rule on Catmull-Clark meshes with triangles equals Far's and Bfr's",
          "[runtime][creases][opensubdiv]") {
  const auto tables = catmull_clark();
  for (const Mesh& mesh : {test_meshes::house(), load("tri-mix")}) {
    for (bool creased : {false, true}) {
      Features f;
      f.smooth_triangles();
      if (creased) f.crease(mesh.face_vertices[0], mesh.face_vertices[1], 1.5f);
      INFO(mesh.face_count() << " faces" << (creased ? ", one crease" : ""));
      CHECK(far_prepared_difference(tables, mesh, f) < 1e-14);
      CHECK(bfr_difference(tables, mesh, f) < 1e-10);  // its quads, where it has any
      Features plain = f;
      plain.ours.smooth_triangles = plain.osd.smooth_triangles = false;
      CHECK(far_prepared_difference(tables, mesh, plain) < 1e-14);
      // The rule matters: the prepared points move by a good part of the size.
      const Surface with = surface_with(tables, mesh, f), without = surface_with(tables, mesh, plain);
      double moved = 0;
      for (std::size_t k = 0; k < with.prepared_positions().size(); ++k)
        moved = std::max(moved, distance(with.prepared_positions()[k], without.prepared_positions()[k]) / extent(mesh));
      CHECK(moved > 1e-2);
    }
  }
  // nonpoly's polygon edge rule is its own: the Catmull-Clark option is refused.
  Features f;
  f.smooth_triangles();
  const auto nonpoly = Tables::load(generated_table("nonpoly", "--valence 3-8 --n 8", "sgs").string());
  CHECK_THROWS_WITH(surface_with(nonpoly, test_meshes::house(), f), Catch::Contains("smooth triangle rule") && Catch::Contains("nonpoly"));
}

TEST_CASE("semi-sharp creases and corners on meshes with boundaries equal OpenSubdiv's (edge-only, edge-and-corner)",
          "[runtime][creases][boundaries][opensubdiv]") {
  const auto tables = catmull_clark();
  std::mt19937 rng(20261125u);
  struct Case {
    const char* name;
    Mesh mesh;
    bool corners;
  };
  for (const Case& c : {Case{"box open at the top", test_meshes::without_first_face("cube"), false},
                        Case{"open grid", test_meshes::open_grid(4, 3), true},
                        Case{"tube", test_meshes::tube(6, 3), false}}) {
    for (bool chaikin : {false, true}) {
      Features f = random_features(c.mesh, chaikin, 2, rng);
      f.ours.boundary = c.corners ? BoundaryInterpolation::EdgeAndCorner : BoundaryInterpolation::EdgeOnly;
      f.osd.boundary_corners = c.corners;
      INFO(c.name << ", " << f.ours.edges.size() << " creases, " << (chaikin ? "Chaikin" : "uniform"));
      const double far = far_difference(tables, c.mesh, f, 3);
      CHECK(far < 1e-10);
      WARN(c.name << (chaikin ? ", Chaikin" : ", uniform") << ": largest difference to Far over the mesh size " << far);
      if (!chaikin) CHECK(bfr_difference(tables, c.mesh, f) < 1e-10);
    }
  }
}

