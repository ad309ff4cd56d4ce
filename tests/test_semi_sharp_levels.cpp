// Refinement round semi-sharp features only (quad/semi_sharp_levels.hpp),
// against OpenSubdiv's Far: every point the levels claim exact (the vertices of
// their exact faces and of those faces' 1-rings) is one of Far's points of
// uniform refinement at that level, and the faces left at each level cover
// the mesh once.
#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <map>
#include <random>
#include <set>

#include "bfr_reference.hpp"
#include "cli.hpp"
#include "closest_point_checks.hpp"
#include "open_meshes.hpp"
#include "runtime_api.hpp"
#include "runtime_checks.hpp"
#include "semi_sharp_checks.hpp"
#include "sharp_features.hpp"
#include "quad/quad_creases.hpp"
#include "quad/quad_family.hpp"
#include "quad/semi_sharp_levels.hpp"

using namespace stencil_runtime;
using namespace test_runtime;
namespace fs = std::filesystem;

namespace {

Mesh load(const std::string& name) { return read_obj((fs::path(STENCIL_SOURCE_DIR) / "meshes" / (name + ".obj")).string()); }

Connectivity connectivity(const Mesh& m) { return {m.vertex_count(), m.face_sizes, m.face_vertices}; }

std::shared_ptr<const Tables> catmull_clark() {
  return Tables::load(generated_table("catmull-clark", "--valence 3-8 --n 8", "sgs").string());
}

SemiSharpRefinement levels_of(const Tables& tables, const Mesh& mesh, const SharpFeatures& f) {
  const Connectivity c = connectivity(mesh);
  const QuadTables& t = tables.quad();
  const CurveCreaseRule crease = quad_crease_rule(t, tables.scheme());
  const bool corners = f.ours.boundary == BoundaryInterpolation::EdgeAndCorner;
  return refine_round_semi_sharp(c, LevelSharpness::of(c, f.ours, true), t, crease, {crease.centre, crease.neighbour, corners},
                                 corners);
}

// The vertices of the exact faces of `mesh` and of the faces sharing a vertex with one.
std::vector<int> claimed_exact(const Connectivity& mesh, const std::vector<char>& exact) {
  std::vector<char> at(mesh.vertex_count, 0), claimed(mesh.vertex_count, 0);
  for (std::size_t f = 0; f < mesh.face_count(); ++f)
    if (exact[f])
      for (int c = 0; c < 4; ++c) at[static_cast<std::size_t>(mesh.face_vertices[4 * f + c])] = 1;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    bool ring = false;
    for (int c = 0; c < 4; ++c) ring |= at[static_cast<std::size_t>(mesh.face_vertices[4 * f + c])] != 0;
    if (ring)
      for (int c = 0; c < 4; ++c) claimed[static_cast<std::size_t>(mesh.face_vertices[4 * f + c])] = 1;
  }
  std::vector<int> out;
  for (std::size_t v = 0; v < claimed.size(); ++v)
    if (claimed[v]) out.push_back(static_cast<int>(v));
  return out;
}

// Largest distance, over the mesh size, from a claimed-exact point of any level
// to the nearest of Far's points at that level; `checked` counts the points.
double far_level_difference(const Mesh& mesh, const SharpFeatures& f, const SemiSharpRefinement& r, std::size_t& checked) {
  const double size = extent(mesh);
  std::vector<Point> level = mesh.positions;
  double worst = 0;
  for (std::size_t l = 0; l < r.levels.size(); ++l) {
    const SemiSharpLevel& s = r.levels[l];
    std::vector<Point> next(s.step.rows());
    s.step.apply(level.data(), next.data());
    level = std::move(next);
    std::vector<Point> far = bfr_reference::far_points(mesh.positions, mesh.face_sizes, mesh.face_vertices,
                                                       bfr_reference::osd::Sdc::SCHEME_CATMARK, f.osd, static_cast<int>(l) + 1, false);
    std::sort(far.begin(), far.end());
    for (int v : claimed_exact(s.mesh, s.exact)) {
      const Point& p = level[static_cast<std::size_t>(v)];
      const auto first = std::lower_bound(far.begin(), far.end(), Point{p[0] - 1e-6 * size, -1e300, -1e300});
      double nearest = 1e300;
      for (auto it = first; it != far.end() && (*it)[0] <= p[0] + 1e-6 * size; ++it) nearest = std::min(nearest, distance(p, *it));
      worst = std::max(worst, nearest / size);
      ++checked;
    }
  }
  return worst;
}

// The area (in input faces) of the faces each level leaves: exact and not refined again.
double leaf_area(const SemiSharpRefinement& r) {
  double area = 0, unit = 1;
  for (char refined : r.refined) area += refined ? 0 : 1;
  for (const SemiSharpLevel& s : r.levels) {
    unit /= 4;
    for (std::size_t f = 0; f < s.mesh.face_count(); ++f) area += s.exact[f] && !s.refined[f] ? unit : 0;
  }
  return area;
}

std::vector<std::pair<int, int>> edges_of(const Mesh& m) {
  std::set<std::pair<int, int>> out;
  for (std::size_t f = 0; f < m.face_count(); ++f)
    for (int c = 0; c < 4; ++c) {
      const int a = m.face_vertices[4 * f + c], b = m.face_vertices[4 * f + (c + 1) % 4];
      out.insert({std::min(a, b), std::max(a, b)});
    }
  return {out.begin(), out.end()};
}

// Every 40th edge of `mesh` (12 on the chess piece) creased with sharpness s.
SharpFeatures every_40th_edge(const Mesh& mesh, float s) {
  SharpFeatures f;
  const auto edges = edges_of(mesh);
  for (std::size_t k = 0; k < edges.size(); k += 40) f.crease(edges[k].first, edges[k].second, s);
  return f;
}

struct Case {
  std::string name;
  Mesh mesh;
  SharpFeatures f;
};

Case creased_cube() {
  Case c{"cube, an edge of 3.5, a corner of 2.25", load("cube"), {}};
  c.f.crease(c.mesh.face_vertices[0], c.mesh.face_vertices[1], 3.5f);
  c.f.corner(c.mesh.face_vertices[6], 2.25f);
  return c;
}

Case creased_open_grid() {
  Case c{"open grid 6x5 with creases across it and at its corners, edge-and-corner", test_meshes::open_grid(6, 5), {}};
  for (int i = 0; i < 6; ++i) c.f.crease(2 * 7 + i, 2 * 7 + i + 1, 3.0f);  // row 2 of the 7-wide vertex grid
  c.f.crease(0, 1, 2.0f);
  c.f.crease(5, 6, 1.5f);    // at the corner that is its face's corner 1
  c.f.crease(34, 41, 2.5f);  // and at the one that is corner 2
  c.f.boundary(BoundaryInterpolation::EdgeAndCorner);
  return c;
}

}  // namespace

TEST_CASE("refinement round semi-sharp features: every point it keeps is Far's at its level, and its leaves cover the "
          "mesh once",
          "[runtime][creases][opensubdiv]") {
  const auto tables = catmull_clark();
  std::mt19937 rng(20261203u);
  std::vector<Case> cases;
  cases.push_back(creased_cube());
  for (bool chaikin : {false, true}) {
    Case c{std::string("chess piece, a few creases up to 3.75, ") + (chaikin ? "Chaikin" : "uniform"), load("chess-piece"), {}};
    const auto edges = edges_of(c.mesh);
    for (int k = 0; k < 6; ++k) {
      const auto& [a, b] = edges[rng() % edges.size()];
      c.f.crease(a, b, 0.75f + static_cast<float>(rng() % 4));
    }
    c.f.corner(static_cast<int>(rng() % c.mesh.vertex_count()), 2.5f);
    if (chaikin) c.f.chaikin();
    cases.push_back(c);
  }
  cases.push_back(creased_open_grid());
  for (const Case& c : cases) {
    INFO(c.name);
    const SemiSharpRefinement r = levels_of(*tables, c.mesh, c.f);
    REQUIRE(!r.levels.empty());
    std::size_t checked = 0;
    const double far = far_level_difference(c.mesh, c.f, r, checked);
    CHECK(far < 1e-13);
    CHECK(checked > 100);
    CHECK(leaf_area(r) == Approx(static_cast<double>(c.mesh.face_count())).epsilon(1e-12));
    // The last level has nothing left to refine, and sharpness decays by one a level.
    CHECK(std::none_of(r.levels.back().refined.begin(), r.levels.back().refined.end(), [](char x) { return x != 0; }));
    WARN(c.name << ": " << r.levels.size() << " levels, " << r.faces() << " faces in all (whole-mesh steps: "
                << c.mesh.face_count() * (1u << (2 * r.levels.size())) << "), " << checked
                << " points against Far, largest difference over the size " << far);
  }
}

TEST_CASE("refinement round semi-sharp features stays small at sharpness 9 (the chess piece)",
          "[runtime][creases]") {
  const auto tables = catmull_clark();
  const Mesh mesh = load("chess-piece");
  const SharpFeatures f = every_40th_edge(mesh, 9.0f);
  const SemiSharpRefinement r = levels_of(*tables, mesh, f);
  CHECK(r.levels.size() == 9);
  // Whole-mesh steps would make 224 * 4^9 = 58.7 million faces; round the creases the
  // refined strip halves in width each level, so each level has about twice the faces of
  // the one before (a strip of some 24 faces across each crease edge's 2^9 at the last).
  CHECK(r.faces() < 587000);  // 1% of them
  CHECK(leaf_area(r) == Approx(224.0).epsilon(1e-12));
  WARN("sharpness 9 on " << f.ours.edges.size() << " edges of the chess piece: " << r.faces() << " faces in 9 levels");
}

TEST_CASE("appended refinement steps read the prepared vertices before them, and fold through them to the control "
          "vertices",
          "[runtime][creases]") {
  std::mt19937 rng(7u);
  auto random_step = [&](std::size_t in, std::size_t rows) {
    RefinementStep s;
    s.input_vertices = in;
    for (std::size_t r = 0; r < rows; ++r) {
      SparseEntries row;
      for (int k = 0; k < 3; ++k) row.emplace_back(static_cast<std::uint32_t>(rng() % in), 0.1 + 0.01 * static_cast<double>(rng() % 50));
      s.add_row(row);
    }
    return s;
  };
  const RefinementStep chain = random_step(5, 8), first = random_step(6, 7), second = random_step(10, 4);
  Refinement refinement(5);
  refinement.add(chain);
  refinement.append(first, 2);    // reads chain vertices 2..7, makes 8..14
  refinement.append(second, 5);   // reads 5..14, makes 15..18
  CHECK(refinement.prepared_vertices() == 19);
  CHECK_THROWS_AS(refinement.add(random_step(8, 3)), EvaluationError);
  CHECK_THROWS_AS(refinement.append(random_step(10, 1), 10), EvaluationError);  // 10..19: beyond the 19
  std::vector<Point> control;
  for (int v = 0; v < 5; ++v) control.push_back({1.0 * v, 0.5 * v * v, std::sin(1.0 * v)});
  std::vector<std::vector<Point>> levels;
  std::vector<Point> prepared;
  refinement.apply(control.data(), levels, prepared);
  REQUIRE(prepared.size() == 19);
  // By hand: each block's rows summed over the vertices they read.
  std::vector<Point> expect(19, Point{0, 0, 0});
  auto by_hand = [&](const RefinementStep& s, std::size_t in, std::size_t out, const std::vector<Point>& from) {
    for (std::size_t r = 0; r < s.rows(); ++r)
      for (std::size_t e = s.offsets[r]; e < s.offsets[r + 1]; ++e)
        for (std::size_t i = 0; i < 3; ++i) expect[out + r][i] += s.weights[e] * from[in + s.columns[e]][i];
  };
  by_hand(chain, 0, 0, control);
  by_hand(first, 2, 8, expect);
  by_hand(second, 5, 15, expect);
  for (std::size_t v = 0; v < 19; ++v) {
    INFO("prepared vertex " << v);
    CHECK(distance(prepared[v], expect[v]) < 1e-14);
    // As a row over the prepared vertices (itself alone), folded to the control vertices.
    SparseEntries row{{static_cast<std::uint32_t>(v), 1.0}};
    refinement.fold(row);
    Point p{0, 0, 0};
    for (const auto& [c, w] : row) {
      REQUIRE(c < 5);
      for (std::size_t i = 0; i < 3; ++i) p[i] += w * control[c][i];
    }
    CHECK(distance(p, expect[v]) < 1e-14);
  }
}

TEST_CASE("surfaces refined round their semi-sharp features equal those refined whole, and Bfr's", "[runtime][creases][opensubdiv]") {
  const auto tables = catmull_clark();
  std::mt19937 rng(20261203u);
  std::vector<Case> cases;
  cases.push_back(creased_cube());
  {
    Case c{"chess piece, creases up to 3.75 and an infinitely sharp one", load("chess-piece"), {}};
    const auto edges = edges_of(c.mesh);
    for (int k = 0; k < 8; ++k) {
      const auto& [a, b] = edges[rng() % edges.size()];
      c.f.crease(a, b, k == 0 ? 10.0f : 0.75f + static_cast<float>(rng() % 4));
    }
    c.f.corner(static_cast<int>(rng() % c.mesh.vertex_count()), 2.5f);
    cases.push_back(c);
  }
  cases.push_back(creased_open_grid());
  {
    // A 4x4 grid less its top right quadrant: the inner corner (vertex 12) is on the boundary in three
    // faces, whose sector patches are turned (the corner is not their first), and no step is needed first.
    Case c{"open L of 12 quads with creases at its inner corner", test_meshes::open_grid(4, 4), {}};
    Mesh& m = c.mesh;
    std::vector<int> sizes, vertices;
    for (std::size_t f = 0; f < m.face_count(); ++f)
      if (!(f % 4 >= 2 && f / 4 >= 2)) {
        sizes.push_back(4);
        vertices.insert(vertices.end(), m.face_vertices.begin() + static_cast<long>(4 * f), m.face_vertices.begin() + static_cast<long>(4 * f + 4));
      }
    m.face_sizes = sizes, m.face_vertices = vertices;
    // (3, 3), (4, 3), (3, 4) and (4, 4) are in no face now: ignored, as OpenSubdiv does.
    c.f.crease(11, 12, 2.5f);
    c.f.crease(7, 12, 1.5f);
    cases.push_back(c);
  }
  {
    Case c{"open grid 8x7 with a crease of 3 through it, boundary none", test_meshes::open_grid(8, 7), {}};
    for (int i = 0; i < 8; ++i) c.f.crease(3 * 9 + i, 3 * 9 + i + 1, 3.0f);
    c.f.boundary_none();
    cases.push_back(c);
  }
  for (const Case& c : cases) {
    INFO(c.name);
    const Surface whole = surface_by(CreaseRefinementChoice::WholeMesh, tables, c.mesh, c.f);
    const Surface local = surface_by(CreaseRefinementChoice::RoundFeatures, tables, c.mesh, c.f);
    INFO("whole: " << whole.topology().preparation() << "; local: " << local.topology().preparation());
    CHECK(local.topology().preparation().find("refined round the semi-sharp features") != std::string::npos);
    CHECK(whole.topology().preparation().find("refined round") == std::string::npos);
    CHECK(node_difference(local, whole, c.mesh) < 1e-13);
    // Bfr approximates next to the ends of infinitely sharp creases (darts: tests/test_creases.cpp).
    if (c.name.find("infinitely") == std::string::npos) CHECK(bfr_node_difference(local, c.mesh, c.f, 4) < 1e-10);
    // Tessellations: closed where the mesh is, and their points on the surface.
    for (bool normals : {false, true}) {
      std::vector<int> rates(c.mesh.face_count());
      for (int& r : rates) r = 1 + static_cast<int>(rng() % 8);
      const PolygonSoup a = tessellate(local, rates, {1}, normals), b = tessellate(whole, rates, {1}, normals);
      if (c.name.rfind("open", 0) != 0) CHECK(closed(a));
      CHECK(a.triangle_count() > 0);
      CHECK(b.triangle_count() > 0);
      if (normals) CHECK(a.normals.size() == a.positions.size());
    }
    // Every point of a tessellation of ours is the whole-mesh surface's at its parameter (to float rounding):
    // prepared face f's n^2 cell centres come first, face by face.
    std::vector<int> rates(c.mesh.face_count());
    for (int& r : rates) r = 1 + static_cast<int>(rng() % 8);
    const TessellationPlan plan(local.shared_topology(), rates, {1});
    PolygonSoup soup = plan.make_soup();
    soup.normals.resize(soup.positions.size());
    plan.evaluate(local, soup.positions.data(), soup.normals.data());
    const auto& family = dynamic_cast<const QuadFamily&>(local.topology().family());
    double worst = 0, worst_normal = 0;
    std::size_t at = 0;
    const std::vector<char> holes = local.topology().prepared_holes();
    for (std::size_t f = 0; f < plan.prepared_rates().size(); ++f) {
      if (!holes.empty() && holes[f]) continue;  // no points
      const long n = plan.prepared_rates()[f];
      for (long j = 0; j < n; ++j)
        for (long i = 0; i < n; ++i, ++at) {
          long x = 0, y = 0;
          family.patch(f).to_patch(2 * i + 1, 2 * j + 1, 2 * n, x, y);
          const FaceParameterReal o = family.original(f, static_cast<double>(x) / (2.0 * n), static_cast<double>(y) / (2.0 * n));
          const Point exact = whole.evaluate(o.face, o.u, o.v, 1e-12).point;
          const auto& q = soup.positions[at];
          worst = std::max(worst, distance(exact, {q[0], q[1], q[2]}));
          const Point normal = whole.normal(o.face, o.u, o.v);
          const auto& m = soup.normals[at];
          worst_normal = std::max(worst_normal, distance(normal, {m[0], m[1], m[2]}));
        }
    }
    CHECK(worst / extent(c.mesh) < 1e-6);
    CHECK(worst_normal < 1e-5);  // unit normals in float
    check_closest_points(local, whole, c.mesh, rng);
  }
}

TEST_CASE("sharpness 9 on the chess piece, refused by whole-mesh steps, is refined round the creases and equals Bfr's",
          "[runtime][creases][opensubdiv]") {
  const auto tables = catmull_clark();
  const Mesh mesh = load("chess-piece");
  const SharpFeatures f = every_40th_edge(mesh, 9.0f);
  const Surface surface = surface_of(tables, mesh, f);
  INFO(surface.topology().preparation());
  // One isolation step (with the sharp rules), then the other eight round the creases.
  CHECK(surface.topology().preparation().find("8 levels refined round the semi-sharp features") != std::string::npos);
  const double bfr = bfr_node_difference(surface, mesh, f, 4);
  CHECK(bfr < 1e-10);
  std::vector<int> rates(mesh.face_count(), 4);
  const PolygonSoup soup = tessellate(surface, rates, {1}, true);
  CHECK(closed(soup));
  WARN("sharpness 9 on the chess piece: " << surface.topology().preparation() << "; Bfr at the rate-4 nodes " << bfr
                                          << " of the size; " << soup.triangle_count() << " triangles");
}

TEST_CASE("closest points on surfaces refined round their semi-sharp features equal those refined whole, and no sample "
          "is nearer",
          "[runtime][creases][distance]") {
  const auto tables = catmull_clark();
  std::mt19937 rng(31u);
  Mesh cube = load("cube");
  SharpFeatures f;
  f.crease(cube.face_vertices[0], cube.face_vertices[1], 3.5f);
  f.corner(cube.face_vertices[6], 2.25f);
  const Surface whole = surface_by(CreaseRefinementChoice::WholeMesh, tables, cube, f);
  const Surface local = surface_by(CreaseRefinementChoice::RoundFeatures, tables, cube, f);
  REQUIRE(local.topology().preparation().find("refined round") != std::string::npos);
  const ClosestPointQuery a(local), b(whole);
  const std::vector<Point> samples = surface_nodes(whole, cube, 16);
  const double size = extent(cube);
  double worst = 0;
  for (int k = 0; k < 300; ++k) {
    // Uniform in the box and on the surface, where the features are.
    const Point q = k % 2 ? random_query(samples, 0.5 * size, rng) : samples[rng() % samples.size()];
    const ClosestPoint x = a.find(q), y = b.find(q);
    INFO("query " << k);
    CHECK(closest_point_defect(local, q, x, samples, size, 1e-9 * size) == "");
    worst = std::max(worst, std::abs(x.distance - y.distance));
  }
  CHECK(worst <= 2 * a.tolerance());
  // The chess piece with sharpness 9, which whole-mesh steps cannot take.
  const Mesh piece = load("chess-piece");
  const SharpFeatures g = every_40th_edge(piece, 9.0f);
  const Surface sharp = surface_of(tables, piece, g);
  const ClosestPointQuery c(sharp);
  const std::vector<Point> dense = surface_nodes(sharp, piece, 8);
  for (int k = 0; k < 200; ++k) {
    const Point q = k % 2 ? random_query(dense, 0.5 * extent(piece), rng) : dense[rng() % dense.size()];
    INFO("chess piece, query " << k);
    CHECK(closest_point_defect(sharp, q, c.find(q), dense, extent(piece), 1e-9 * extent(piece)) == "");
  }
  WARN("closest points refined round the features against whole-mesh steps: largest difference " << worst / size
                                                                                                  << " of the size");
}

TEST_CASE("nonpoly refined round its semi-sharp features equals nonpoly refined whole", "[runtime][creases]") {
  // No reference evaluates nonpoly; the whole-mesh steps are the plain subdivision it is checked against
  // (tests/test_creases.cpp: continuous across every edge, crease rule nonpoly-curve).
  const auto tables = Tables::load(generated_table("nonpoly", "--valence 3-8 --n 8", "sgs").string());
  std::mt19937 rng(5u);
  Mesh cube = load("cube");
  SharpFeatures f;
  f.crease(cube.face_vertices[0], cube.face_vertices[1], 2.5f);
  f.crease(cube.face_vertices[1], cube.face_vertices[2], 1.5f);
  f.corner(cube.face_vertices[6], 1.25f);
  const Surface whole = surface_by(CreaseRefinementChoice::WholeMesh, tables, cube, f);
  const Surface local = surface_by(CreaseRefinementChoice::RoundFeatures, tables, cube, f);
  REQUIRE(local.topology().preparation().find("refined round") != std::string::npos);
  CHECK(node_difference(local, whole, cube) < 1e-13);
  std::vector<int> rates(cube.face_count());
  for (int& r : rates) r = 1 + static_cast<int>(rng() % 8);
  CHECK(closed(tessellate(local, rates, {1}, true)));
}

TEST_CASE("stencil rows over the control points of a surface refined round its semi-sharp features give its points",
          "[runtime][creases]") {
  // Fitting solves for control points through these rows (Refinement::fold through the appended levels).
  const auto tables = catmull_clark();
  const Mesh mesh = load("chess-piece");
  const SharpFeatures f = every_40th_edge(mesh, 6.0f);
  const RefinementChoice round(CreaseRefinementChoice::RoundFeatures);
  const Surface surface = surface_of(tables, mesh, f);
  REQUIRE(surface.topology().preparation().find("refined round") != std::string::npos);
  double worst = 0;
  for (std::size_t face = 0; face < mesh.face_count(); face += 3)
    for (long j = 0; j <= 4; ++j)
      for (long i = 0; i <= 4; ++i) {
        const StencilRows rows = surface.topology().stencil(face, grid(i, j, 4));
        REQUIRE(rows.columns == mesh.vertex_count());
        worst = std::max(worst, distance(rows.apply(mesh.positions)[0], surface.evaluate(face, grid(i, j, 4))));
      }
  CHECK(worst / extent(mesh) < 1e-13);
}
