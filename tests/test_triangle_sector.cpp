// Loop patches at boundary vertices (generator/triangle/triangle_sector.hpp)
// against OpenSubdiv's Loop limit surface (Bfr), which shares no code with the
// generator: a wedge of k faces round the vertex, cut from the triangular
// lattice, with random positions; every grid node's stencil, gathered by
// vertex, equals Bfr's.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <optional>
#include <random>
#include <thread>

#include "bfr_reference.hpp"
#include "base/error.hpp"
#include "cli.hpp"
#include "tables/triangle_tables.hpp"
#include "triangle/triangle_masks.hpp"
#include "triangle/triangle_patch.hpp"
#include "triangle/triangle_scheme_loader.hpp"
#include "triangle/triangle_sector.hpp"

namespace {

// f.operator()<T>() with T the arithmetic the sector's rules allow: exact
// rationals, or 80 digits (a dart where Loop's smooth weight is irrational).
template <class F>
auto in_sector_arithmetic(const sg::TriangleScheme& scheme, const sg::BoundarySector& sector, F&& f) {
  return sg::exact_triangle_sector(scheme, sector) ? f.template operator()<sg::Rational>() : f.template operator()<sg::Real>();
}

// The wedge's real points within `rings` of B, as a triangle mesh. `closed`:
// ray k is ray 0 again (a dart's ring; its slit, ray 0, is tagged sharp by
// the caller), the ray's points known by both names.
struct WedgeMesh {
  std::map<sg::WedgePoint, int> vertex;
  std::vector<int> sizes, indices;
  std::map<int, int> patch_face;  // position p -> face (B, e_p, e_{p+1})

  WedgeMesh(const sg::BoundaryWedge& wedge, long rings, bool closed = false) {
    const int k = wedge.faces();
    auto id = [&](int s, long a, long b) {
      const auto q = wedge.canonical(s, a, b);
      REQUIRE(q);
      REQUIRE(!wedge.phantom(*q));
      if (closed && q->sector == k && q->b == 0) {  // the same vertex as ray 0's
        const int v = vertex.emplace(sg::WedgePoint{0, q->a, 0}, static_cast<int>(vertex.size())).first->second;
        vertex.emplace(*q, v);
        return v;
      }
      return vertex.emplace(*q, static_cast<int>(vertex.size())).first->second;
    };
    auto face = [&](int s, long a0, long b0, long a1, long b1, long a2, long b2) {
      indices.push_back(id(s, a0, b0)), indices.push_back(id(s, a1, b1)), indices.push_back(id(s, a2, b2));
      sizes.push_back(3);
    };
    for (int s = 0; s < k; ++s)
      for (long a = 0; a < rings; ++a)
        for (long b = 0; b <= a; ++b) {
          if (a == 0) patch_face[s] = static_cast<int>(sizes.size());
          face(s, a, b, a + 1, b, a + 1, b + 1);                   // up
          if (b + 1 <= a) face(s, a, b, a + 1, b + 1, a, b + 1);  // down
        }
  }
};

// A dart's slit: ray 0 from B to the mesh's rim, infinitely sharp.
bfr_reference::Creasing slit(const WedgeMesh& mesh, long rings) {
  bfr_reference::Creasing creasing;
  for (long a = 0; a < rings; ++a) {
    creasing.crease_pairs.push_back(mesh.vertex.at(sg::WedgePoint{0, a, 0}));
    creasing.crease_pairs.push_back(mesh.vertex.at(sg::WedgePoint{0, a + 1, 0}));
    creasing.crease_sharpness.push_back(10.0f);
  }
  return creasing;
}

// Every node but B's own where the sector is a dart: OpenSubdiv's limit at a
// dart vertex is the smooth one, not the dart's (the next test).
template <class T = sg::Rational>
double worst_difference(const sg::TriangleScheme& loop, const sg::BoundarySector& sector, long n, bool corner_tag) {
  const sg::BoundaryWedge wedge(sector.faces);
  const bool dart = sector.kind == sg::SectorKind::Dart;
  const long rings = dart ? 6 : 5;
  WedgeMesh mesh(wedge, rings, dart || sector.kind == sg::SectorKind::Cone);  // a cone point's ring is closed
  std::mt19937 rng(77u + 31u * static_cast<unsigned>(sector.faces) + static_cast<unsigned>(sector.position));
  std::uniform_real_distribution<double> U(-1, 1);
  std::vector<std::array<double, 3>> positions(mesh.vertex.size());
  for (auto& p : positions) p = {U(rng), U(rng), U(rng)};
  bfr_reference::Creasing creasing = dart ? slit(mesh, rings) : bfr_reference::Creasing{};
  if (corner_tag) creasing.corners = {0}, creasing.corner_sharpness = {10.0f};  // B is vertex 0
  bfr_reference::BfrLimit bfr(positions, mesh.sizes, mesh.indices, OpenSubdiv::Sdc::SCHEME_LOOP, {}, creasing);
  const auto patch = sg::solve_triangle_sector<T>(loop, sector, n, sg::solve_regular(loop, n));
  const int face = mesh.patch_face.at(sector.position);
  double worst = 0;
  for (long j = 0; j <= n; ++j)
    for (long i = 0; i + j <= n; ++i) {
      if (dart && i == 0 && j == 0) continue;
      std::map<int, double> ours;
      const auto& w = patch.at(i, j);
      for (std::size_t h = 0; h < w.size(); ++h)
        if (w[h] != 0) ours[mesh.vertex.at(patch.layout[h])] += sg::to_double(w[h]);
      auto ref = bfr.stencil(face, double(i) / n, double(j) / n);
      for (const auto& [v, x] : ours) ref[v] -= x;
      for (const auto& [v, x] : ref) worst = std::max(worst, std::fabs(x));
    }
  return worst;
}

using Vec = std::array<double, 3>;
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec unit(const Vec& a) {
  const double n = std::sqrt(dot(a, a));
  return {a[0] / n, a[1] / n, a[2] / n};
}

// Far's exact limit position and tangents of every vertex after one uniform step.
struct FarLimit {
  std::vector<Vec> position, tan1, tan2;
};
FarLimit far_limit(const std::vector<Vec>& positions, const WedgeMesh& mesh) {
  namespace osd = OpenSubdiv;
  auto refiner = bfr_reference::make_refiner(static_cast<int>(positions.size()), mesh.sizes, mesh.indices,
                                             osd::Sdc::SCHEME_LOOP);
  osd::Far::TopologyRefiner::UniformOptions options(1);
  options.fullTopologyInLastLevel = true;
  refiner->RefineUniform(options);
  struct Primvar {
    double p[3];
    void Clear() { p[0] = p[1] = p[2] = 0; }
    void AddWithWeight(const Primvar& s, double w) {
      for (int c = 0; c < 3; ++c) p[c] += w * s.p[c];
    }
  };
  std::vector<Primvar> coarse(positions.size()), fine(static_cast<std::size_t>(refiner->GetLevel(1).GetNumVertices()));
  for (std::size_t v = 0; v < positions.size(); ++v)
    for (int c = 0; c < 3; ++c) coarse[v].p[c] = positions[v][static_cast<std::size_t>(c)];
  osd::Far::PrimvarRefinerReal<double> primvars(*refiner);
  Primvar* src = coarse.data();
  Primvar* dst = fine.data();
  primvars.Interpolate(1, src, dst);
  std::vector<Primvar> pos(fine.size()), t1(fine.size()), t2(fine.size());
  Primvar *p = pos.data(), *d1 = t1.data(), *d2 = t2.data();
  primvars.Limit(dst, p, d1, d2);
  FarLimit out;
  for (std::size_t v = 0; v < fine.size(); ++v) {
    out.position.push_back({pos[v].p[0], pos[v].p[1], pos[v].p[2]});
    out.tan1.push_back({t1[v].p[0], t1[v].p[1], t1[v].p[2]});
    out.tan2.push_back({t2[v].p[0], t2[v].p[1], t2[v].p[2]});
  }
  return out;
}

}  // namespace

// The tangent plane at B, where A0's spectrum gives one (k = 1..5: its two
// leading eigenvalues below 1 are real with a gap below them; at k >= 6 the
// boundary curve's 1/2 is double and the spectrum alone gives none). Against
// the normals of OpenSubdiv's own surface as they approach B (Bfr a distance
// 1e-8 into the face), and for k <= 3 against Far's limit tangents exactly. At
// k = 4, 5 Far's limit tangent masks are not the tangent plane of the surface
// it subdivides to: Bfr's normals converge to ours and differ from Far's by up
// to 13 degrees.
TEST_CASE("Loop boundary sectors' tangent planes at the vertex are OpenSubdiv's", "[triangle][sector][opensubdiv]") {
  const sg::TriangleScheme loop = sg::load_triangle_scheme("loop");
  for (int k = 1; k <= 8; ++k)
    for (int p = 0; p < k; ++p) {
      INFO("k = " << k << ", p = " << p);
      const sg::BoundaryWedge wedge(k);
      WedgeMesh mesh(wedge, 5);
      std::mt19937 rng(501u + 17u * static_cast<unsigned>(k) + static_cast<unsigned>(p));
      std::uniform_real_distribution<double> U(-1, 1);
      std::vector<Vec> positions(mesh.vertex.size());
      for (auto& x : positions) x = {U(rng), U(rng), U(rng)};
      const auto patch = sg::solve_triangle_sector(loop, {sg::SectorKind::Crease, k, p}, 8, sg::solve_regular(loop, 8));
      std::string why;
      const auto t = sg::triangle_sector_tangents(patch, why);
      INFO(why);
      if (k >= 6) {
        CHECK(!t);
        continue;
      }
      REQUIRE(t);
      auto apply = [&](auto weight) {
        Vec out{0, 0, 0};
        for (std::size_t h = 0; h < patch.layout.size(); ++h)
          for (std::size_t c = 0; c < 3; ++c)
            out[c] += weight(h) * positions[static_cast<std::size_t>(mesh.vertex.at(patch.layout[h]))][c];
        return out;
      };
      const Vec normal = unit(cross(apply([&](std::size_t h) { return sg::to_double(t->u[h]); }),
                                    apply([&](std::size_t h) { return sg::to_double(t->v[h]); })));
      bfr_reference::BfrLimit bfr(positions, mesh.sizes, mesh.indices, OpenSubdiv::Sdc::SCHEME_LOOP);
      const auto d = bfr.derivatives(mesh.patch_face.at(p), 1e-8, 1e-8);
      CHECK(dot(normal, unit(cross(d[1], d[2]))) > 1 - 1e-6);  // oriented as du x dv
      if (k <= 3) {  // Far's limit at B's child after one step: the same limit point and plane
        const Vec limit = apply([&](std::size_t h) { return sg::to_double(patch.at(0, 0)[h]); });
        const FarLimit far = far_limit(positions, mesh);
        std::size_t at = far.position.size();
        for (std::size_t v = 0; v < far.position.size(); ++v) {
          const Vec e{far.position[v][0] - limit[0], far.position[v][1] - limit[1], far.position[v][2] - limit[2]};
          if (std::sqrt(dot(e, e)) < 1e-12) at = v;
        }
        REQUIRE(at < far.position.size());
        CHECK(std::fabs(std::fabs(dot(normal, unit(cross(far.tan1[at], far.tan2[at])))) - 1) < 1e-12);
      }
    }
}

TEST_CASE("Loop boundary sectors of 1..8 faces equal Bfr at rates 1..8", "[triangle][sector][opensubdiv]") {
  const sg::TriangleScheme loop = sg::load_triangle_scheme("loop");
  for (int k = 1; k <= 8; ++k)
    for (int p = 0; p < k; ++p)
      for (long n : {1L, 2L, 3L, 5L, 8L}) {
        INFO("k = " << k << ", p = " << p << ", n = " << n);
        CHECK(worst_difference(loop, {sg::SectorKind::Crease, k, p}, n, false) < 1e-13);
      }
}

TEST_CASE("Loop corner sectors of 1..8 faces equal Bfr with a sharp corner", "[triangle][sector][opensubdiv]") {
  const sg::TriangleScheme loop = sg::load_triangle_scheme("loop");
  for (int k = 1; k <= 8; ++k)
    for (int p = 0; p < k; ++p)
      for (long n : {1L, 4L, 7L}) {
        INFO("k = " << k << ", p = " << p << ", n = " << n);
        CHECK(worst_difference(loop, {sg::SectorKind::Corner, k, p}, n, true) < 1e-13);
      }
}

TEST_CASE("Loop dart sectors of valence 3..8 equal Bfr at rates 1..8, but at the dart vertex", "[triangle][sector][dart][opensubdiv]") {
  const sg::TriangleScheme loop = sg::load_triangle_scheme("loop");
  for (int k = 3; k <= 8; ++k)
    for (int p = 0; p < k; ++p)
      for (long n : {1L, 2L, 3L, 5L, 8L}) {
        INFO("k = " << k << ", p = " << p << ", n = " << n);
        const sg::BoundarySector dart{sg::SectorKind::Dart, k, p};
        // Loop's smooth rule is rational at valences 3, 4 and 6 only.
        CHECK(sg::exact_triangle_sector(loop, dart) == (k == 3 || k == 4 || k == 6));
        const double worst = in_sector_arithmetic(loop, dart, [&]<class T>() { return worst_difference<T>(loop, dart, n, false); });
        CHECK(worst < 1e-13);
      }
  CHECK_THROWS_WITH(sg::solve_triangle_sector(loop, {sg::SectorKind::Dart, 5, 0}, 2, sg::solve_regular(loop, 2)),
                    Catch::Contains("irrational"));
}

namespace {

// The dart's layout points one Loop step on (its child at B, same chart
// positions in half units) among OpenSubdiv's refined vertices, found by
// Far's parent-to-child relations: the point at even (a, b) is the child of
// the coarse vertex there, any other the child of the coarse edge it halves.
std::vector<int> refined_layout(const OpenSubdiv::Far::TopologyRefiner& refiner, const WedgeMesh& mesh,
                                const sg::BoundaryWedge& wedge, const std::vector<sg::WedgePoint>& layout) {
  const auto& level = refiner.GetLevel(0);
  auto coarse = [&](int s, long a, long b) {
    const auto q = wedge.canonical(s, a, b);
    REQUIRE(q);
    return mesh.vertex.at(*q);
  };
  std::vector<int> out;
  for (const sg::WedgePoint& x : layout) {
    if (x.a % 2 == 0 && x.b % 2 == 0) {
      out.push_back(level.GetVertexChildVertex(coarse(x.sector, x.a / 2, x.b / 2)));
      continue;
    }
    int child = -1;
    for (const auto& d : sg::kTriangleNeighbours) {
      if ((x.a - d[0]) % 2 != 0 || (x.b - d[1]) % 2 != 0) continue;
      const long qa = (x.a - d[0]) / 2, qb = (x.b - d[1]) / 2;
      const int edge = level.FindEdge(coarse(x.sector, qa, qb), coarse(x.sector, qa + d[0], qb + d[1]));
      REQUIRE(edge >= 0);
      child = level.GetEdgeChildVertex(edge);
      break;
    }
    REQUIRE(child >= 0);
    out.push_back(child);
  }
  return out;
}

template <class T>
void check_dart_limit_and_plane(const sg::TriangleScheme& loop, int k, int p) {
  namespace osd = OpenSubdiv;
  const sg::BoundarySector dart{sg::SectorKind::Dart, k, p};
  const sg::BoundaryWedge wedge(k);
  const long rings = 5;
  WedgeMesh mesh(wedge, rings, true);
  const bfr_reference::Creasing creasing = slit(mesh, rings);
  std::mt19937 rng(901u + 13u * static_cast<unsigned>(k) + static_cast<unsigned>(p));
  std::uniform_real_distribution<double> U(-1, 1);
  const std::size_t nv = static_cast<std::size_t>(std::max_element(mesh.vertex.begin(), mesh.vertex.end(), [](const auto& x, const auto& y) {
                                                   return x.second < y.second;
                                                 })->second) + 1;
  std::vector<Vec> positions(nv);
  for (auto& x : positions) x = {U(rng), U(rng), U(rng)};
  auto refiner = bfr_reference::make_refiner(static_cast<int>(nv), mesh.sizes, mesh.indices, osd::Sdc::SCHEME_LOOP, {}, creasing);
  refiner->RefineUniform(osd::Far::TopologyRefiner::UniformOptions(1));
  struct Primvar {
    double p[3];
    void Clear() { p[0] = p[1] = p[2] = 0; }
    void AddWithWeight(const Primvar& s, double w) {
      for (int c = 0; c < 3; ++c) p[c] += w * s.p[c];
    }
  };
  std::vector<Primvar> coarse(nv), fine(static_cast<std::size_t>(refiner->GetLevel(1).GetNumVertices()));
  for (std::size_t v = 0; v < nv; ++v)
    for (int c = 0; c < 3; ++c) coarse[v].p[c] = positions[v][static_cast<std::size_t>(c)];
  osd::Far::PrimvarRefinerReal<double> primvars(*refiner);
  Primvar* src = coarse.data();
  Primvar* dst = fine.data();
  primvars.Interpolate(1, src, dst);

  const auto patch = sg::solve_triangle_sector<T>(loop, dart, 8, sg::solve_regular(loop, 8));
  const std::vector<int> child = refined_layout(*refiner, mesh, wedge, patch.layout);
  auto at_coarse = [&](std::size_t h) { return positions[static_cast<std::size_t>(mesh.vertex.at(patch.layout[h]))]; };
  auto at_fine = [&](std::size_t h) {
    const Primvar& x = fine[static_cast<std::size_t>(child[h])];
    return Vec{x.p[0], x.p[1], x.p[2]};
  };
  auto apply = [&](const auto& weights, auto point) {
    Vec out{0, 0, 0};
    for (std::size_t h = 0; h < patch.layout.size(); ++h)
      for (std::size_t c = 0; c < 3; ++c) out[c] += sg::to_double(weights[h]) * point(h)[c];
    return out;
  };
  // The limit stencil is the left eigenvector of OpenSubdiv's own step: the
  // same point from the coarse and the refined points.
  const Vec l0 = apply(patch.at(0, 0), at_coarse), l1 = apply(patch.at(0, 0), at_fine);
  const Vec d{l1[0] - l0[0], l1[1] - l0[1], l1[2] - l0[2]};
  CHECK(std::sqrt(dot(d, d)) < 1e-13);
  // The tangent plane (the slit folded shut) is kept by OpenSubdiv's step: the
  // refined tangent vectors lie in the coarse ones' plane.
  std::string why;
  const auto t = sg::triangle_sector_tangents(patch, why);
  INFO(why);
  REQUIRE(t);
  const Vec u0 = apply(t->u, at_coarse), v0 = apply(t->v, at_coarse);
  const Vec normal = unit(cross(u0, v0));
  for (const Vec& x : {apply(t->u, at_fine), apply(t->v, at_fine)}) CHECK(std::fabs(dot(normal, x)) < 1e-12 * std::sqrt(dot(x, x)));
  bfr_reference::BfrLimit bfr(positions, mesh.sizes, mesh.indices, osd::Sdc::SCHEME_LOOP, {}, creasing);
  // Oriented as du x dv next to B: Bfr's normal 1e-3 into the face (not
  // nearer: below its approximation level Bfr's patch ends at the smooth
  // limit, not the dart's, and its normals there turn away from both; that
  // the normals of our surface next to B converge to this plane is
  // test_loop_creases.cpp's check).
  const auto near = bfr.derivatives(mesh.patch_face.at(p), 1e-3, 1e-3);
  CHECK(dot(normal, unit(cross(near[1], near[2]))) > 0.5);
}

}  // namespace

// OpenSubdiv's own limit at a dart vertex is its smooth limit mask (wrong
// there: test_creases.cpp shows it for Catmull-Clark); its refinement rules
// are right. So the dart's limit stencil and tangent plane are checked
// against one step of Far's refinement: a left eigenvector for 1, and a
// plane that step keeps, oriented as Bfr's surface near B.
TEST_CASE("Loop darts' limit stencils and tangent planes are kept by OpenSubdiv's refinement", "[triangle][sector][dart][opensubdiv]") {
  const sg::TriangleScheme loop = sg::load_triangle_scheme("loop");
  for (int k = 3; k <= 8; ++k)
    for (int p = 0; p < k; ++p) {
      INFO("k = " << k << ", p = " << p);
      in_sector_arithmetic(loop, {sg::SectorKind::Dart, k, p}, [&]<class T>() { check_dart_limit_and_plane<T>(loop, k, p); });
    }
}

// Every face round a dart gives the same tangent plane (each position's
// stencils are solved apart, over its own layout).
TEST_CASE("the faces round a Loop dart agree on its tangent plane", "[triangle][sector][dart]") {
  const sg::TriangleScheme loop = sg::load_triangle_scheme("loop");
  for (int k = 3; k <= 8; ++k) {
    const sg::BoundaryWedge wedge(k);
    WedgeMesh mesh(wedge, 5, true);
    std::mt19937 rng(33u + static_cast<unsigned>(k));
    std::uniform_real_distribution<double> U(-1, 1);
    std::vector<Vec> positions(mesh.vertex.size());
    for (auto& x : positions) x = {U(rng), U(rng), U(rng)};
    std::optional<Vec> first;
    for (int p = 0; p < k; ++p) {
      INFO("k = " << k << ", p = " << p);
      const sg::BoundarySector dart{sg::SectorKind::Dart, k, p};
      std::string why;
      std::optional<sg::TangentStencils> t;
      std::vector<sg::WedgePoint> layout;
      in_sector_arithmetic(loop, dart, [&]<class T>() {
        const auto patch = sg::solve_triangle_sector<T>(loop, dart, 8, sg::solve_regular(loop, 8));
        t = sg::triangle_sector_tangents(patch, why), layout = patch.layout;
      });
      INFO(why);
      REQUIRE(t);
      auto apply = [&](const std::vector<sg::Real>& w) {
        Vec out{0, 0, 0};
        for (std::size_t h = 0; h < layout.size(); ++h)
          for (std::size_t c = 0; c < 3; ++c) out[c] += sg::to_double(w[h]) * positions[static_cast<std::size_t>(mesh.vertex.at(layout[h]))][c];
        return out;
      };
      const Vec n = unit(cross(apply(t->u), apply(t->v)));
      if (!first) first = n;
      CHECK(dot(n, *first) > 1 - 1e-12);
    }
  }
}

// A cone point: B held, everything round it smooth (OpenSubdiv's corner rule
// on a vertex inside the mesh on no sharp edge). Bfr's limit there is the
// vertex itself, as ours.
TEST_CASE("Loop cone points of valence 3..8 equal Bfr with a sharp vertex", "[triangle][sector][cone][opensubdiv]") {
  const sg::TriangleScheme loop = sg::load_triangle_scheme("loop");
  for (int k = 3; k <= 8; ++k)
    for (long n : {1L, 2L, 3L, 5L, 8L}) {
      INFO("k = " << k << ", n = " << n);
      const sg::BoundarySector cone{sg::SectorKind::Cone, k, 0};
      CHECK(sg::exact_triangle_sector(loop, cone));
      CHECK(worst_difference(loop, cone, n, true) < 1e-13);
    }
  std::string why;
  const auto patch = sg::solve_triangle_sector(loop, {sg::SectorKind::Cone, 5, 0}, 2, sg::solve_regular(loop, 2));
  CHECK(patch.layout.size() >= 6);
  CHECK(!sg::triangle_sector_tangents(patch, why));
  CHECK(why == "a cone point has no tangent plane");
  CHECK_THROWS_WITH(sg::solve_triangle_sector(loop, {sg::SectorKind::Cone, 5, 1}, 2, sg::solve_regular(loop, 2)),
                    Catch::Contains("position 0 only"));
}

// The tables keep a sector's cells, not its stencils; the runtime makes the
// stencils from them (TriangleTables::expand_sector). They equal the
// generator's exact stencils at every node and centre of every rate.
TEST_CASE("Loop sector stencils made by the runtime equal the generator's exact ones", "[triangle][sector][tables]") {
  const auto dir = scratch_dir("loop-sectors");
  const CliResult r = run_stencilgen("--scheme loop --valence 3-7 --n 1-6 --out " + dir.string() + " -q");
  INFO(r.output);
  REQUIRE(r.status == 0);
  const auto tables = stencil_runtime::TriangleTables::load((dir / "loop" / "loop.sgt").string());
  const sg::TriangleScheme loop = sg::load_triangle_scheme("loop");
  int sectors = 0;
  for (const auto kind : {sg::SectorKind::Crease, sg::SectorKind::Corner, sg::SectorKind::Dart, sg::SectorKind::Cone})
    for (int k = kind >= sg::SectorKind::Dart ? 3 : 1; k <= 7; ++k)
      for (int p = 0; p < (kind == sg::SectorKind::Cone ? 1 : k); ++p) {
        const stencil_runtime::SectorKey key{static_cast<stencil_runtime::SectorRule>(kind), k, p};
        const auto code = tables.sector_code(key);
        if (k == 3 && kind == sg::SectorKind::Crease) {  // a regular boundary patch: not stored
          CHECK(!code);
          continue;
        }
        REQUIRE(code);
        ++sectors;
        INFO(key.name());
        for (int n : {1, 2, 5, 6}) {
          const sg::BoundarySector sector{kind, k, p};
          const auto exact = sg::solve_triangle_sector<sg::Real>(loop, sector, 3 * n, sg::solve_regular(loop, 3 * n));
          const auto& layout = tables.layout(*code);
          REQUIRE(layout.size() == exact.layout.size());
          for (std::size_t h = 0; h < layout.size(); ++h)
            REQUIRE((layout[h].sector == exact.layout[h].sector && layout[h].a == exact.layout[h].a && layout[h].b == exact.layout[h].b));
          const auto grid = tables.grid(*code, n);
          double worst = 0;
          for (int g = 0; g < 3; ++g)
            for (int j = 0; j + g <= n; ++j)
              for (int i = 0; i + j + g <= n; ++i) {
                const double* w = grid.weights(static_cast<stencil_runtime::TriangleTables::GridPoint>(g), i, j);
                const auto& e = exact.at(3 * i + g, 3 * j + g);
                for (std::size_t h = 0; h < layout.size(); ++h) worst = std::max(worst, std::fabs(w[h] - sg::to_double(e[h])));
              }
          CHECK(worst < 1e-14);
        }
      }
  CHECK(sectors == 2 * 28 - 3 + (28 - 3) + 5);
}

// Threads that ask for a sector's stencils at once all get the same ones (the
// first use makes them, once), equal to those of tables used by one thread.
TEST_CASE("Loop sector stencils made on first use are made once for threads asking together", "[triangle][sector][tables]") {
  const auto dir = scratch_dir("loop-sectors-threads");
  const CliResult r = run_stencilgen("--scheme loop --valence 3-6 --n 2-5 --out " + dir.string() + " -q");
  INFO(r.output);
  REQUIRE(r.status == 0);
  const std::string path = (dir / "loop" / "loop.sgt").string();
  const auto shared = stencil_runtime::TriangleTables::load(path), alone = stencil_runtime::TriangleTables::load(path);
  const int code = *shared.sector_code({stencil_runtime::SectorRule::Crease, 5, 2});
  const std::size_t m = shared.layout(code).size();
  std::vector<std::vector<double>> seen(8);
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < seen.size(); ++t)
    threads.emplace_back([&, t] {
      const auto grid = shared.grid(code, 2 + static_cast<int>(t % 4));
      const double* w = grid.weights(stencil_runtime::TriangleTables::GridPoint::Up, 0, 1);
      seen[t].assign(w, w + m);
    });
  for (auto& t : threads) t.join();
  for (std::size_t t = 0; t < seen.size(); ++t) {
    const double* w = alone.grid(code, 2 + static_cast<int>(t % 4)).weights(stencil_runtime::TriangleTables::GridPoint::Up, 0, 1);
    CHECK(seen[t] == std::vector<double>(w, w + m));
  }
}
