// Refinement round semi-sharp features only (quad/semi_sharp_levels.hpp),
// against OpenSubdiv's Far: every point the levels claim exact (the vertices of
// their exact faces and of those faces' 1-rings) is one of Far's points of
// uniform refinement at that level, and the faces left at each level cover
// the mesh once.
#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <random>
#include <set>

#include "bfr_reference.hpp"
#include "cli.hpp"
#include "open_meshes.hpp"
#include "runtime_api.hpp"
#include "runtime_checks.hpp"
#include "sharp_features.hpp"
#include "quad/quad_creases.hpp"
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

}  // namespace

TEST_CASE("refinement round semi-sharp features: every point it keeps is Far's at its level, and its leaves cover the "
          "mesh once",
          "[runtime][creases][opensubdiv]") {
  const auto tables = catmull_clark();
  std::mt19937 rng(20261203u);
  struct Case {
    std::string name;
    Mesh mesh;
    SharpFeatures f;
  };
  std::vector<Case> cases;
  {
    Case c{"cube, one edge of sharpness 3.5 and a corner of 2.25", load("cube"), {}};
    c.f.crease(c.mesh.face_vertices[0], c.mesh.face_vertices[1], 3.5f);
    c.f.corner(c.mesh.face_vertices[6], 2.25f);
    cases.push_back(c);
  }
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
  {
    Case c{"open grid 6x5, a crease of 3 through it and one of 2 on its rim, edge-and-corner", test_meshes::open_grid(6, 5), {}};
    for (int i = 0; i < 6; ++i) c.f.crease(2 * 7 + i, 2 * 7 + i + 1, 3.0f);  // row 2 of the 7-wide vertex grid
    c.f.crease(0, 1, 2.0f);
    c.f.boundary(BoundaryInterpolation::EdgeAndCorner);
    cases.push_back(c);
  }
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
  SharpFeatures f;
  const auto edges = edges_of(mesh);
  for (std::size_t k = 0; k < edges.size(); k += 40) f.crease(edges[k].first, edges[k].second, 9.0f);
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
