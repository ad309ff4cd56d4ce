// Loop meshes with infinitely sharp creases (sharpness >= 10): the mesh is cut
// along them (family/sharp_cut.hpp) and each side is a mesh with a boundary
// there, whose vertices on it are in three faces (a crease straight through
// regular vertices), so every face takes a regular or extraordinary patch of
// its side. Against OpenSubdiv's Bfr with the same sharpness: positions at
// every node at rates 1..8 and first derivatives, on tori and tubes with
// crease rings, extraordinary vertices next to a crease, and semi-sharp
// features beside them; creases that bend (a hexagonal loop), corners on a
// ring and crossings (boundary sectors of the cut mesh). Also: tessellations
// closed across creases; darts (the ends of creases inside the mesh, of
// valence 3..8), cone points (a sharp vertex on no sharp edge), and the
// refusal that remains (sharp boundary edges under `none`).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <random>

#include "bfr_reference.hpp"
#include "cli.hpp"
#include "closest_point_checks.hpp"
#include "loop_bfr_difference.hpp"
#include "bundled_meshes.hpp"
#include "loop_meshes.hpp"
#include "open_meshes.hpp"
#include "runtime_api.hpp"
#include "runtime_checks.hpp"
#include "stencil_runtime/closest_point.hpp"
#include "stencil_runtime/mesh_io.hpp"
#include "stencil_runtime/tessellation.hpp"

using namespace stencil_runtime;
using namespace test_runtime;
using loop_meshes::triangle_torus;
using loop_meshes::triangle_tube;
using loop_meshes::with_flip;
using test_meshes::kMeshes;

namespace {

using Features = SharpFeatures;

// The ring of edges (i, j) - (i + 1, j) of an `around`-wide lattice (loop_meshes.hpp), or the meridian
// (i, j) - (i, j + 1) of a torus with `rows` rows, with sharpness s.
void ring(Features& f, int around, int j, float s) {
  for (int i = 0; i < around; ++i) f.crease(j * around + i, j * around + (i + 1) % around, s);
}
void meridian(Features& f, int around, int rows, int i, float s) {
  for (int j = 0; j < rows; ++j) f.crease(j * around + i, ((j + 1) % rows) * around + i, s);
}

Surface surface_with(const std::shared_ptr<const Tables>& tables, const Mesh& m, const Features& f) {
  return Surface(SurfaceTopology::create(tables, m.vertex_count(), m.face_sizes, m.face_vertices, {}, f.ours), m.positions);
}

std::shared_ptr<const Tables> loop_tables() { return Tables::load(generated_table("loop", "--valence 3-8 --n 1-8", "sgt").string()); }

struct Case {
  std::string name;
  Mesh mesh;
  Features features;
  std::set<int> darts;  // OpenSubdiv's limit at a dart vertex is the smooth one: their own nodes are compared elsewhere
  std::set<int> cones;
};

// For each vertex in `from`, one infinitely sharp edge to a neighbour (the
// first in the mesh's faces that is not in `from`); the darts are the
// vertices on one such edge only (two edges may share an end: a crease vertex).
void sharp_edges_from(Case& c, const std::vector<int>& from) {
  std::map<int, int> edges_at;
  for (int v : from) {
    const auto& fv = c.mesh.face_vertices;
    for (std::size_t h = 0; h < fv.size(); ++h) {
      const int w = fv[3 * (h / 3) + (h + 1) % 3];
      if (fv[h] != v || std::find(from.begin(), from.end(), w) != from.end()) continue;
      c.features.crease(v, w, 10);
      ++edges_at[v], ++edges_at[w];
      break;
    }
  }
  for (const auto& [v, n] : edges_at)
    if (n == 1) c.darts.insert(v);
}

// The first vertex of each valence in `valences`.
std::vector<int> vertices_of_valence(const Mesh& m, const std::vector<int>& valences) {
  std::vector<int> count(m.vertex_count(), 0), out;
  for (int v : m.face_vertices) ++count[static_cast<std::size_t>(v)];
  for (int k : valences)
    for (std::size_t v = 0; v < count.size(); ++v)
      if (count[v] == k) {
        out.push_back(static_cast<int>(v));
        break;
      }
  REQUIRE(out.size() == valences.size());
  return out;
}

std::vector<Case> crease_cases() {
  std::vector<Case> out;
  {
    Case c{"torus 8x6, one ring", triangle_torus(8, 6), {}, {}, {}};
    ring(c.features, 8, 2, 10);
    out.push_back(c);
  }
  {
    Case c{"torus 8x6, two rings and a semi-sharp edge between them", triangle_torus(8, 6), {}, {}, {}};
    ring(c.features, 8, 1, 10);
    ring(c.features, 8, 4, 12);
    c.features.crease(2 * 8 + 3, 3 * 8 + 3, 1.5f);
    out.push_back(c);
  }
  {
    Case c{"torus 6x5, one meridian", triangle_torus(6, 5), {}, {}, {}};
    meridian(c.features, 6, 5, 2, 10);
    out.push_back(c);
  }
  {
    // The flipped quad (0, 3) has corners on row 3 and 4: valence 5 and 7 on the crease's side.
    Case c{"torus 7x7 with valence 5 and 7 next to a ring", with_flip(triangle_torus(7, 7), 7, 3), {}, {}, {}};
    ring(c.features, 7, 2, 10);
    ring(c.features, 7, 5, 10);
    out.push_back(c);
  }
  {
    // The ring round vertex 3 * 8 + 3: the loop's vertices have two faces
    // inside and four outside (boundary sectors of the cut mesh).
    Case c{"torus 8x6, a hexagonal loop", triangle_torus(8, 6), {}, {}, {}};
    const int centre = 3 * 8 + 3;
    const int hexagon[6] = {centre + 1, centre + 9, centre + 8, centre - 1, centre - 9, centre - 8};
    for (int k = 0; k < 6; ++k) c.features.crease(hexagon[k], hexagon[(k + 1) % 6], 10);
    out.push_back(c);
  }
  {
    Case c{"torus 8x6, a ring with an infinitely sharp corner on it", triangle_torus(8, 6), {}, {}, {}};
    ring(c.features, 8, 2, 10);
    c.features.corner(2 * 8 + 3, 10);
    out.push_back(c);
  }
  {
    // Four sharp edges where they cross: a corner whose sides have one and two faces.
    Case c{"torus 8x6, a ring crossing a meridian", triangle_torus(8, 6), {}, {}, {}};
    ring(c.features, 8, 2, 10);
    meridian(c.features, 8, 6, 0, 10);
    out.push_back(c);
  }
  {
    Case c{"tube 8x4 with a ring inside, edge-only", triangle_tube(8, 4), {}, {}, {}};
    ring(c.features, 8, 2, 10);
    out.push_back(c);
  }
  {
    Case c{"tube 8x4 with a ring inside, edge-and-corner, a semi-sharp corner on the ring", triangle_tube(8, 4), {}, {}, {}};
    c.features.boundary(BoundaryInterpolation::EdgeAndCorner);
    ring(c.features, 8, 2, 10);
    c.features.corner(2 * 8 + 5, 2.0f);
    out.push_back(c);
  }
  {
    // Corners where it meets the rims: sectors of four faces on one side and two on the other.
    Case c{"tube 8x4 with a meridian from rim to rim, edge-only", triangle_tube(8, 4), {}, {}, {}};
    for (int j = 0; j < 4; ++j) c.features.crease(j * 8 + 3, (j + 1) * 8 + 3, 10);
    out.push_back(c);
  }
  {
    // Under `none`: the crease loop's vertices are sectors of the cut mesh (two faces inside, four outside), not of its boundary.
    Case c{"tube 8x5 with a hexagonal loop inside, none", triangle_tube(8, 5), {}, {}, {}};
    c.features.boundary(BoundaryInterpolation::None);
    const int centre = 2 * 8 + 3;
    const int hexagon[6] = {centre + 1, centre + 9, centre + 8, centre - 1, centre - 9, centre - 8};
    for (int k = 0; k < 6; ++k) c.features.crease(hexagon[k], hexagon[(k + 1) % 6], 10);
    out.push_back(c);
  }
  {
    Case c{"tube 8x4 with a ring one row from the rim, none", triangle_tube(8, 4), {}, {}, {}};
    c.features.boundary(BoundaryInterpolation::None);
    ring(c.features, 8, 1, 10);
    out.push_back(c);
  }
  // Darts: the ends of infinitely sharp creases inside the mesh (sector patches with Loop's smooth rule at B).
  {
    Case c{"torus 8x6, two edges of a ring (darts of valence 6 at its ends)", triangle_torus(8, 6), {}, {}, {}};
    c.features.crease(16, 17, 10);
    c.features.crease(17, 18, 10);
    c.darts = {16, 18};
    out.push_back(c);
  }
  {
    Case c{"torus 8x6, one sharp edge (two darts next to each other)", triangle_torus(8, 6), {}, {}, {}};
    sharp_edges_from(c, {3 * 8 + 2});
    out.push_back(c);
  }
  {
    Case c{"icosahedron, a sharp path of two edges (darts of valence 5)", read_obj((kMeshes / "icosahedron.obj").string()), {}, {}, {}};
    const auto& fv = c.mesh.face_vertices;  // the path a - b - c along the first face's two edges
    c.features.crease(fv[0], fv[1], 10);
    c.features.crease(fv[1], fv[2], 10);
    c.darts = {fv[0], fv[2]};
    out.push_back(c);
  }
  {
    Case c{"tri-mix, a sharp edge at a vertex of valence 3, 4 and 8 each", read_obj((kMeshes / "tri-mix.obj").string()), {}, {}, {}};
    sharp_edges_from(c, vertices_of_valence(c.mesh, {3, 4, 8}));
    out.push_back(c);
  }
  {
    Case c{"tri-torus, a sharp edge at a vertex of valence 5 and 7", read_obj((kMeshes / "tri-torus.obj").string()), {}, {}, {}};
    sharp_edges_from(c, vertices_of_valence(c.mesh, {5, 7}));
    out.push_back(c);
  }
  {
    // The edge from the rim's vertex 3 inward: a corner on the rim (two boundary edges and it), a dart inside.
    Case c{"tube 8x4, a sharp edge from the rim inward, edge-only", triangle_tube(8, 4), {}, {}, {}};
    c.features.crease(3, 8 + 3, 10);
    c.darts = {8 + 3};
    out.push_back(c);
  }
  // Cone points: sharp vertices on no sharp edge (B held, the smooth rules round it).
  {
    Case c{"torus 8x6, a cone point of valence 6 next to a sharp ring", triangle_torus(8, 6), {}, {}, {}};
    ring(c.features, 8, 2, 10);
    c.features.corner(3 * 8 + 3, 10);
    c.cones = {3 * 8 + 3};
    out.push_back(c);
  }
  {
    Case c{"icosahedron, a cone point of valence 5", read_obj((kMeshes / "icosahedron.obj").string()), {}, {}, {}};
    c.features.corner(c.mesh.face_vertices[0], 10);
    c.cones = {c.mesh.face_vertices[0]};
    out.push_back(c);
  }
  {
    Case c{"tri-mix, cone points of valence 3, 4 and 8", read_obj((kMeshes / "tri-mix.obj").string()), {}, {}, {}};
    for (int v : vertices_of_valence(c.mesh, {3, 4, 8})) c.features.corner(v, 10), c.cones.insert(v);
    out.push_back(c);
  }
  return out;
}

}  // namespace

TEST_CASE("Loop: infinitely sharp crease rings equal OpenSubdiv's Bfr, positions and derivatives",
          "[runtime][creases][loop][opensubdiv]") {
  const auto tables = loop_tables();
  for (const Case& c : crease_cases()) {
    INFO(c.name);
    const auto [positions, derivatives] = loop_bfr_difference(tables, c.mesh, c.features, c.darts);
    CHECK(positions < 1e-14);
    CHECK(derivatives < 1e-13);
  }
}

TEST_CASE("Loop: the smooth surface of a mesh with a sharp ring is far from Bfr's creased one", "[runtime][creases][loop][opensubdiv]") {
  // The check above can fail: ignoring the creases moves the surface by more than its tolerance.
  const auto tables = loop_tables();
  const Case c = crease_cases().front();
  const Surface smooth(SurfaceTopology::create(tables, c.mesh.vertex_count(), c.mesh.face_sizes, c.mesh.face_vertices), c.mesh.positions);
  bfr_reference::BfrLimit reference(c.mesh.positions, c.mesh.face_sizes, c.mesh.face_vertices, bfr_reference::osd::Sdc::SCHEME_LOOP,
                                    {}, c.features.osd);
  double worst = 0;
  for (std::size_t f = 0; f < c.mesh.face_count(); ++f)
    worst = std::max(worst, distance(smooth.evaluate(f, grid(1, 1, 3)), reference.evaluate(static_cast<int>(f), 1.0 / 3, 1.0 / 3)));
  CHECK(worst > 1e-3 * extent(c.mesh));
}

TEST_CASE("Loop: tessellations stay closed across infinitely sharp creases", "[runtime][creases][loop][tessellation]") {
  const auto tables = loop_tables();
  std::mt19937 rng(20261127u);
  for (const Case& c : crease_cases()) {
    if (c.features.ours.boundary == BoundaryInterpolation::None) continue;
    const Surface surface = surface_with(tables, c.mesh, c.features);
    const bool tube = c.name.rfind("tube", 0) == 0;
    const bool sphere = c.name.rfind("icosahedron", 0) == 0 || c.name.rfind("tri-mix", 0) == 0;
    for (int trial = 0; trial < 3; ++trial) {
      std::vector<int> rates(c.mesh.face_count());
      for (int& r : rates) r = std::uniform_int_distribution<int>(1, 8)(rng);
      INFO(c.name << ", trial " << trial);
      check_rimmed_manifold(tessellate(surface, rates), tube ? 2 : 0, tube || sphere ? 0 : 1);
    }
  }
}

TEST_CASE("boundary edges tagged infinitely sharp under `none` give the faces at their ends a surface, as Bfr's",
          "[runtime][creases][loop][boundaries][opensubdiv]") {
  // OpenSubdiv's `none` holes the faces at a boundary vertex unless every
  // boundary edge there is tagged infinitely sharp: one rim tagged, the other
  // not, then one edge of a rim (its ends keep an untagged edge each).
  const auto tables = loop_tables();
  const auto quad_tables = Tables::load(generated_table("catmull-clark", "--valence 3-8 --n 4", "sgs").string());
  for (int tagged : {8, 1, 3, -8, -3}) {  // negative: with a semi-sharp edge too, whose steps the tags must outlive
    Features rim;
    rim.boundary(BoundaryInterpolation::None);
    for (int i = 0; i < std::abs(tagged); ++i) rim.crease(i, (i + 1) % 8, 10);
    if (tagged < 0) rim.crease(8 + 2, 16 + 2, 1.5f);
    INFO(tagged << " edges of the rim tagged");
    const Mesh tube = triangle_tube(8, 4);
    const auto [positions, derivatives] = loop_bfr_difference(tables, tube, rim, {});
    CHECK(positions < 1e-14);
    CHECK(derivatives < 1e-13);
    const Mesh quads = test_meshes::tube(8, 4);
    const Surface surface = surface_with(quad_tables, quads, rim);
    bfr_reference::BfrLimit reference(quads.positions, quads.face_sizes, quads.face_vertices, bfr_reference::osd::Sdc::SCHEME_CATMARK,
                                      {}, rim.osd);
    std::size_t with_surface = 0;
    double worst = 0;
    for (std::size_t face = 0; face < quads.face_count(); ++face) {
      const bool hole = surface.topology().is_hole(face);
      CHECK(hole == !reference.has_surface(static_cast<int>(face)));
      if (hole) continue;
      ++with_surface;
      for (long j = 0; j <= 4; ++j)
        for (long i = 0; i <= 4; ++i)
          worst = std::max(worst, distance(surface.evaluate(face, grid(i, j, 4)), reference.evaluate(static_cast<int>(face), i / 4.0, j / 4.0)));
    }
    CHECK(worst < 1e-12);
    CHECK(with_surface == (std::abs(tagged) == 8 ? 24u : tagged == 1 ? 16u : 17u));  // the inner rows, and the rim faces whose rim vertices have only tagged edges
  }
}

// At a dart the surface meets its limit point, and the normal there (the
// tables' tangent stencils: the slit folded shut) is the limit of the normals
// next to it, from every face round it: a check of the tangent stencils
// against the derivatives of the recursion, which do not use them.
TEST_CASE("Loop: at a dart the surface reaches its limit point and the normal is the limit of the normals next to it",
          "[runtime][creases][loop][dart]") {
  const auto tables = loop_tables();
  auto angle = [](const Point& p, const Point& q) {
    const Point x{p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
    return std::atan2(std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]), p[0] * q[0] + p[1] * q[1] + p[2] * q[2]);
  };
  int darts = 0;
  for (const Case& c : crease_cases()) {
    if (c.darts.empty()) continue;
    const Surface surface = surface_with(tables, c.mesh, c.features);
    const double size = extent(c.mesh);
    for (int dart : c.darts) {
      INFO(c.name << ", dart " << dart);
      ++darts;
      std::optional<Point> first_normal, limit;
      for (std::size_t f = 0; f < c.mesh.face_count(); ++f)
        for (int k = 0; k < 3; ++k) {
          if (c.mesh.face_vertices[3 * f + static_cast<std::size_t>(k)] != dart) continue;
          const double cu = k == 1, cv = k == 2;
          const Point p = surface.evaluate(f, grid(k == 1, k == 2, 1));
          if (!limit) limit = p;
          CHECK(distance(p, *limit) / size < 1e-14);  // one point from every face
          const Point n = surface.normal(f, cu, cv);
          if (!first_normal) first_normal = n;
          CHECK(angle(n, *first_normal) < 1e-10);
          std::vector<double> off, gap;
          for (int depth : {5, 10, 20, 40}) {
            const double d = std::ldexp(1.0, -depth);
            // Towards the corner along the face's inside: (1-2d, d), (d, 1-2d) or (d, d).
            const double u = k == 1 ? 1 - 2 * d : d, v = k == 2 ? 1 - 2 * d : d;
            if (depth <= 20) off.push_back(angle(surface.derivatives(f, u, v).normal(), n));
            gap.push_back(distance(surface.evaluate(f, u, v, 1e-15).point, p) / size);
          }
          // Normals converge slowly at some darts (the third eigenvalue near
          // the second: by about 7x every 10 levels); points fast.
          CHECK(off[2] < 0.02);
          CHECK(off[2] < off[1] / 3);
          CHECK(gap[2] < 1e-5);
          CHECK(gap[2] < gap[1] / 100);
          CHECK(gap[3] < 1e-10);
        }
    }
  }
  CHECK(darts >= 9);
}

// A cone point stays where its control vertex is, from every face round it,
// and has no normal (no tangent plane); next to it the surface is Bfr's (the
// cases above).
TEST_CASE("Loop: a cone point's limit is its control vertex and it has no normal", "[runtime][creases][loop][cone]") {
  const auto tables = loop_tables();
  int cones = 0;
  for (const Case& c : crease_cases()) {
    if (c.cones.empty()) continue;
    const Surface surface = surface_with(tables, c.mesh, c.features);
    for (int cone : c.cones) {
      INFO(c.name << ", cone point " << cone);
      ++cones;
      for (std::size_t f = 0; f < c.mesh.face_count(); ++f)
        for (int k = 0; k < 3; ++k) {
          if (c.mesh.face_vertices[3 * f + static_cast<std::size_t>(k)] != cone) continue;
          CHECK(distance(surface.evaluate(f, grid(k == 1, k == 2, 1)), c.mesh.positions[static_cast<std::size_t>(cone)]) <
                1e-14 * extent(c.mesh));
          CHECK_THROWS_WITH(surface.normal(f, k == 1, k == 2), Catch::Contains("a cone point has no tangent plane"));
        }
    }
  }
  CHECK(cones >= 5);
}

// Closest points on meshes with darts and cone points (their sectors' hulls
// bound the search as a boundary sector's do): on the surface, and no farther
// than dense exact samples.
TEST_CASE("Loop: closest points on meshes with darts and cone points lie on the surface and no farther than dense samples",
          "[runtime][creases][loop][distance]") {
  const auto tables = loop_tables();
  std::mt19937 rng(31);
  int meshes = 0;
  for (const Case& c : crease_cases()) {
    if (c.darts.empty() && c.cones.empty()) continue;
    if (c.name.rfind("tri-torus", 0) == 0) continue;  // 192 faces: the smaller ones cover the same sectors
    ++meshes;
    const Surface surface = surface_with(tables, c.mesh, c.features);
    const double size = extent(c.mesh);
    const std::vector<Point> samples = surface_nodes(surface, c.mesh, 10);
    const ClosestPointQuery query(surface);
    for (int k = 0; k < 60; ++k) {
      const Point q = random_query(samples, 0.3 * size, rng);
      INFO(c.name << ", query " << k);
      CHECK(closest_point_defect(surface, q, query.find(q), samples, size, 1e-9 * size) == "");
    }
  }
  CHECK(meshes >= 6);
}
