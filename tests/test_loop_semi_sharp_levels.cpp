// Loop meshes refined round their semi-sharp features only (family/semi_sharp_levels.hpp,
// TriangleFamily's tree), against the same meshes refined whole (every face
// subdivided until the sharpness has decayed, checked against OpenSubdiv in
// test_creases.cpp) and against OpenSubdiv's Bfr directly: the nodes of every
// face, the tessellation's points and normals, closed tessellations and closest points.
#include <catch2/catch.hpp>
#include <filesystem>
#include <random>
#include <set>

#include "cli.hpp"
#include "family/recentre.hpp"
#include "closest_point_checks.hpp"
#include "loop_meshes.hpp"
#include "runtime_api.hpp"
#include "runtime_checks.hpp"
#include "semi_sharp_checks.hpp"
#include "sharp_features.hpp"
#include "triangle/triangle_family.hpp"

using namespace stencil_runtime;
using namespace test_runtime;
namespace fs = std::filesystem;

namespace {

Mesh load(const std::string& name) { return read_obj((fs::path(STENCIL_SOURCE_DIR) / "meshes" / (name + ".obj")).string()); }

std::shared_ptr<const Tables> loop_tables() {
  return Tables::load(generated_table("loop", "--valence 3-8 --n 8", "sgt").string());
}

std::vector<std::pair<int, int>> triangle_edges(const Mesh& m) {
  std::set<std::pair<int, int>> out;
  for (std::size_t f = 0; f < m.face_count(); ++f)
    for (int c = 0; c < 3; ++c) {
      const int a = m.face_vertices[3 * f + c], b = m.face_vertices[3 * f + (c + 1) % 3];
      out.insert({std::min(a, b), std::max(a, b)});
    }
  return {out.begin(), out.end()};
}

struct Case {
  std::string name;
  Mesh mesh;
  SharpFeatures f;
  bool closed = true;
};

std::vector<Case> cases(std::mt19937& rng) {
  std::vector<Case> out;
  {
    Case c{"icosahedron, an edge of 2.5, a corner of 1.5", load("icosahedron"), {}};
    const auto edges = triangle_edges(c.mesh);
    c.f.crease(edges[0].first, edges[0].second, 2.5f);
    c.f.corner(c.mesh.face_vertices[7], 1.5f);
    out.push_back(c);
  }
  for (bool chaikin : {false, true}) {
    Case c{std::string("tri-torus, creases up to 3.75 and an infinitely sharp one, ") + (chaikin ? "Chaikin" : "uniform"),
           load("tri-torus"), {}};
    const auto edges = triangle_edges(c.mesh);
    for (int k = 0; k < 6; ++k) {
      const auto& [a, b] = edges[rng() % edges.size()];
      c.f.crease(a, b, k == 0 ? 10.0f : 0.75f + static_cast<float>(rng() % 4));
    }
    c.f.corner(static_cast<int>(rng() % c.mesh.vertex_count()), 2.5f);
    if (chaikin) c.f.chaikin();
    out.push_back(c);
  }
  {
    // A tube: rim vertices in three faces (regular boundary patches), a crease of 3 round it
    // and one of 1.5 along it to the rim, edge-and-corner.
    Case c{"triangulated tube 12x6 with creases, edge-and-corner", loop_meshes::triangle_tube(12, 6), {}, false};
    for (int i = 0; i < 12; ++i) c.f.crease(3 * 12 + i, 3 * 12 + (i + 1) % 12, 3.0f);
    for (int j = 0; j < 3; ++j) c.f.crease(j * 12 + 5, (j + 1) * 12 + 5, 1.5f);
    c.f.boundary(BoundaryInterpolation::EdgeAndCorner);
    out.push_back(c);
  }
  {
    Case c{"tri-mix (valences 3 to 8), two creases of 2 and 4.5", load("tri-mix"), {}};
    const auto edges = triangle_edges(c.mesh);
    c.f.crease(edges[3].first, edges[3].second, 2.0f);
    c.f.crease(edges[11].first, edges[11].second, 4.5f);
    out.push_back(c);
  }
  return out;
}

}  // namespace

TEST_CASE("Loop surfaces refined round their semi-sharp features equal those refined whole, and Bfr's",
          "[runtime][creases][opensubdiv]") {
  const auto tables = loop_tables();
  std::mt19937 rng(20261203u);
  for (const Case& c : cases(rng)) {
    INFO(c.name);
    const Surface whole = surface_by(CreaseRefinementChoice::WholeMesh, tables, c.mesh, c.f);
    const Surface local = surface_by(CreaseRefinementChoice::RoundFeatures, tables, c.mesh, c.f);
    INFO("whole: " << whole.topology().preparation() << "; local: " << local.topology().preparation());
    CHECK(local.topology().preparation().find("refined round the semi-sharp features") != std::string::npos);
    CHECK(whole.topology().preparation().find("refined round") == std::string::npos);
    CHECK(node_difference(local, whole, c.mesh) < 1e-13);
    // Bfr approximates next to the ends of infinitely sharp creases (darts: tests/test_creases.cpp).
    if (c.name.find("infinitely") == std::string::npos) CHECK(bfr_node_difference(local, c.mesh, c.f, 4) < 1e-10);
    // Derivatives and normals through the tree: equal to the whole-mesh surface's.
    double worst_derivative = 0;
    for (std::size_t face = 0; face < c.mesh.face_count(); face += 2) {
      const double u = 0.1 + 0.7 * static_cast<double>(rng() % 1000) / 1000.0, v = (1 - u) * static_cast<double>(rng() % 1000) / 1001.0;
      const Derivatives a = local.derivatives(face, u, v), b = whole.derivatives(face, u, v);
      worst_derivative = std::max({worst_derivative, distance(a.du, b.du), distance(a.dv, b.dv)});
    }
    CHECK(worst_derivative / extent(c.mesh) < 1e-11);
    // Tessellations: closed where the mesh is, every point the whole-mesh surface's at its
    // parameter (to float rounding), normals too.
    for (bool normals : {false, true}) {
      std::vector<int> rates(c.mesh.face_count());
      for (int& r : rates) r = 1 + static_cast<int>(rng() % 8);
      const PolygonSoup a = tessellate(local, rates, {1}, normals);
      if (c.closed) CHECK(closed(a));
      if (c.closed) CHECK(tessellation_defect(a, euler_characteristic(c.mesh)) == "");
      if (normals) CHECK(a.normals.size() == a.positions.size());
    }
    std::vector<int> rates(c.mesh.face_count());
    for (int& r : rates) r = 1 + static_cast<int>(rng() % 8);
    const TessellationPlan plan(local.shared_topology(), rates, {1});
    PolygonSoup soup = plan.make_soup();
    soup.normals.resize(soup.positions.size());
    plan.evaluate(local, soup.positions.data(), soup.normals.data());
    const auto& family = dynamic_cast<const TriangleFamily&>(local.topology().family());
    double worst = 0, worst_normal = 0;
    std::size_t at = 0;
    for (std::size_t f = 0; f < plan.prepared_rates().size(); ++f) {
      const long n = plan.prepared_rates()[f];
      // The face's n^2 centres: up centres row by row, then down centres (triangle_family.hpp).
      std::vector<std::pair<long, long>> centres;
      for (long j = 0; j < n; ++j)
        for (long i = 0; i + j <= n - 1; ++i) centres.push_back({3 * i + 1, 3 * j + 1});
      for (long j = 0; j + 1 < n; ++j)
        for (long i = 0; i + j <= n - 2; ++i) centres.push_back({3 * i + 2, 3 * j + 2});
      for (const auto& [a, b] : centres) {
        long x = 0, y = 0;
        family.patch(f).to_patch(a, b, 3 * n, x, y);
        const FaceParameterReal o = family.original(f, static_cast<double>(x) / (3.0 * n), static_cast<double>(y) / (3.0 * n));
        const Point exact = whole.evaluate(o.face, o.u, o.v, 1e-12).point;
        const auto& q = soup.positions[at];
        worst = std::max(worst, distance(exact, {q[0], q[1], q[2]}));
        const Point normal = whole.normal(o.face, o.u, o.v);
        const auto& m = soup.normals[at];
        worst_normal = std::max(worst_normal, distance(normal, {m[0], m[1], m[2]}));
        ++at;
      }
    }
    CHECK(at == (c.closed ? soup.positions.size() : at));  // an open mesh's rim points come after the faces'
    CHECK(at <= soup.positions.size());
    CHECK(worst / extent(c.mesh) < 1e-6);
    CHECK(worst_normal < 1e-5);  // unit normals in float
    check_closest_points(local, whole, c.mesh, rng);
  }
}

TEST_CASE("Loop: sharpness 9.5 on the icosahedron, beyond whole-mesh steps, is refined round the crease and equals Bfr's",
          "[runtime][creases][opensubdiv]") {
  // Ten whole-mesh steps from 20 faces would make 21 million faces (over the limit, test_creases.cpp);
  // round the crease the levels stay small.
  const auto tables = loop_tables();
  const Mesh ico = load("icosahedron");
  SharpFeatures f;
  const auto edges = triangle_edges(ico);
  f.crease(edges[0].first, edges[0].second, 9.5f);
  f.crease(edges[5].first, edges[5].second, 7.0f);
  const Surface surface = surface_of(tables, ico, f);
  INFO(surface.topology().preparation());
  CHECK(surface.topology().preparation().find("refined round the semi-sharp features") != std::string::npos);
  const double bfr = bfr_node_difference(surface, ico, f, 4);
  CHECK(bfr < 1e-10);
  std::vector<int> rates(ico.face_count(), 4);
  const PolygonSoup soup = tessellate(surface, rates, {1}, true);
  CHECK(closed(soup));
  const ClosestPointQuery query(surface);
  const std::vector<Point> dense = surface_nodes(surface, ico, 8);
  std::mt19937 rng(3u);
  for (int k = 0; k < 100; ++k) {
    const Point q = k % 2 ? random_query(dense, 0.5 * extent(ico), rng) : dense[rng() % dense.size()];
    INFO("query " << k);
    CHECK(closest_point_defect(surface, q, query.find(q), dense, extent(ico), 1e-9 * extent(ico)) == "");
  }
  WARN("Loop, sharpness 9.5 on the icosahedron: " << surface.topology().preparation() << "; Bfr at the rate-4 nodes "
                                                  << bfr << " of the size");
}

namespace {

// Largest distance over the size between the surface and a family's sub-patches below every
// prepared face, each sub-patch's points moved to an origin near them as the closest-point
// search does (face_search.cpp), its evaluations and derivatives' points moved back: the
// sub-patches below a tree node must be in its frame.
double recentred_sub_patch_difference(const Surface& surface, const Family& family, std::size_t faces, std::mt19937& rng) {
  const Point* pos = surface.prepared_positions().data();
  double worst = 0;
  for (std::size_t f = 0; f < faces; ++f) {
    SubPatch root;
    family.root(f, pos, root);
    std::vector<std::pair<SubPatch, Point>> stack{{root, Point{0, 0, 0}}};
    for (int visited = 0; !stack.empty() && visited < 400; ++visited) {
      auto [s, offset] = stack.back();
      stack.pop_back();
      recentre(s.points, offset);
      for (int k = 0; k < 3; ++k) {
        double X = static_cast<double>(rng() % 101) / 100.0, Y = static_cast<double>(rng() % 101) / 100.0;
        if (s.domain.triangle && X + Y > 1) X = 1 - X, Y = 1 - Y;
        const auto at = s.domain.at(X, Y);
        Point a = family.evaluate(s, at[0], at[1], 1e-13).point;
        const FaceParameterReal o = family.original(s.face, at[0], at[1]);
        const Point b = surface.evaluate(o.face, o.u, o.v, 1e-13).point;
        for (int i = 0; i < 3; ++i) a[i] += offset[i];
        worst = std::max(worst, distance(a, b));
        double x = at[0], y = at[1];
        Point n = family.nearby_point(s, x, y, 1e-13).point;
        for (int i = 0; i < 3; ++i) n[i] += offset[i];
        const FaceParameterReal o2 = family.original(s.face, x, y);
        worst = std::max(worst, distance(n, surface.evaluate(o2.face, o2.u, o2.v, 1e-13).point));
      }
      if (s.domain.size() > 0.05) {
        SubPatch children[kMaxSubPatchChildren];
        const int n = family.split(s, children);
        for (int i = 0; i < n; ++i) stack.push_back({children[i], offset});
      }
    }
  }
  return worst;
}

}  // namespace

TEST_CASE("sub-patches below faces refined round semi-sharp features are in their tree node's frame, Loop and "
          "Catmull-Clark",
          "[runtime][creases][distance]") {
  std::mt19937 rng(8u);
  const auto loop = loop_tables();
  for (const Case& c : cases(rng)) {
    INFO(c.name);
    const Surface local = surface_by(CreaseRefinementChoice::RoundFeatures, loop, c.mesh, c.f);
    const auto& family = dynamic_cast<const TriangleFamily&>(local.topology().family());
    CHECK(recentred_sub_patch_difference(local, family, family.topology().faces(), rng) / extent(c.mesh) < 1e-12);
  }
  const auto cc = Tables::load(generated_table("catmull-clark", "--valence 3-8 --n 8", "sgs").string());
  Mesh cube = load("cube");
  SharpFeatures f;
  f.crease(cube.face_vertices[0], cube.face_vertices[1], 3.5f);
  f.corner(cube.face_vertices[6], 2.25f);
  const Surface local = surface_by(CreaseRefinementChoice::RoundFeatures, cc, cube, f);
  const auto& family = local.topology().family();
  CHECK(recentred_sub_patch_difference(local, family, local.topology().prepared_face_count(), rng) / extent(cube) < 1e-12);
}
