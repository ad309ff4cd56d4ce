// Loop subdivision steps on triangle meshes with boundaries (issue 17's
// foundation for Loop boundaries): subdivide() against OpenSubdiv's Far
// uniform refinement with the same boundary option, vertex for vertex (matched
// as sets: Far numbers its refined vertices otherwise), on open meshes made for
// the test: triangulated grids (boundary vertices in 1, 2 and 3 faces), the
// icosahedron without one face or without a fan round a vertex, and fans of
// 1..8 faces round a boundary vertex.
#include <catch2/catch.hpp>
#include <opensubdiv/far/primvarRefiner.h>

#include <algorithm>
#include <cmath>

#include "bfr_reference.hpp"
#include "bundled_meshes.hpp"
#include "cli.hpp"
#include "runtime_api.hpp"
#include "runtime_checks.hpp"
#include "stencil_runtime/subdivide.hpp"

using namespace stencil_runtime;
using namespace test_runtime;
using test_meshes::bundled;

namespace {

// (columns x rows) quads with uneven heights, each split into two triangles
// along alternating diagonals: its corners are in one or two faces, its other
// boundary vertices in two or three.
Mesh triangulated_grid(int columns, int rows) {
  Mesh m;
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i <= columns; ++i)
      m.positions.push_back({i + 0.1 * std::sin(3.0 * j), j + 0.07 * i * i / columns, 0.3 * std::sin(1.3 * i + 0.7 * j)});
  auto at = [&](int i, int j) { return j * (columns + 1) + i; };
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      const int a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      const bool flip = (i + j) % 2 == 1;
      m.face_sizes.insert(m.face_sizes.end(), {3, 3});
      if (flip) m.face_vertices.insert(m.face_vertices.end(), {a, b, d, b, c, d});
      else m.face_vertices.insert(m.face_vertices.end(), {a, b, c, a, c, d});
    }
  return m;
}

// k triangles round vertex 0, which is on the boundary (its first and last
// neighbours are boundary vertices in one face each when k = 1, else the fan's ends).
Mesh fan(int k) {
  Mesh m;
  m.positions.push_back({0, 0, 0.2});
  const double angle = (k == 1 ? 1.0 : 1.6) * M_PI / k;
  for (int j = 0; j <= k; ++j)
    m.positions.push_back({std::cos(angle * j), std::sin(angle * j), 0.1 * std::sin(2.0 * j + 1)});
  for (int j = 0; j < k; ++j) {
    m.face_sizes.push_back(3);
    m.face_vertices.insert(m.face_vertices.end(), {0, j + 1, j + 2});
  }
  return m;
}

// The icosahedron without the faces at vertex `v` (a hole round it), or
// without its first face when v < 0.
Mesh icosahedron_without(int v) {
  Mesh in = bundled("icosahedron"), m;
  m.positions = in.positions;
  for (std::size_t f = 0; f < in.face_count(); ++f) {
    const int* c = &in.face_vertices[3 * f];
    if (v < 0 ? f == 0 : (c[0] == v || c[1] == v || c[2] == v)) continue;
    m.face_sizes.push_back(3);
    m.face_vertices.insert(m.face_vertices.end(), c, c + 3);
  }
  if (v >= 0) {  // vertex v is in no face now: the last vertex takes its number
    const int last = static_cast<int>(m.positions.size()) - 1;
    m.positions[static_cast<std::size_t>(v)] = m.positions.back();
    m.positions.pop_back();
    for (int& x : m.face_vertices)
      if (x == last) x = v;
  }
  return m;
}

struct Primvar {
  double p[3];
  void Clear() { p[0] = p[1] = p[2] = 0; }
  void AddWithWeight(const Primvar& s, double w) {
    for (int k = 0; k < 3; ++k) p[k] += w * s.p[k];
  }
};

// Far's vertices after `level` uniform Loop steps with the boundary option.
std::vector<Point> far_loop_points(const Mesh& mesh, bool corners, int level) {
  namespace osd = bfr_reference::osd;
  bfr_reference::Creasing options;
  options.boundary_corners = corners;
  auto refiner = bfr_reference::make_refiner(static_cast<int>(mesh.vertex_count()), mesh.face_sizes, mesh.face_vertices,
                                             osd::Sdc::SCHEME_LOOP, {}, options);
  refiner->RefineUniform(osd::Far::TopologyRefiner::UniformOptions(level));
  std::vector<Primvar> points(static_cast<std::size_t>(refiner->GetNumVerticesTotal()));
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
    for (std::size_t k = 0; k < 3; ++k) points[v].p[k] = mesh.positions[v][k];
  osd::Far::PrimvarRefinerReal<double> primvars(*refiner);
  Primvar* src = points.data();
  for (int l = 1; l <= level; ++l) {
    Primvar* dst = src + refiner->GetLevel(l - 1).GetNumVertices();
    primvars.Interpolate(l, src, dst);
    src = dst;
  }
  std::vector<Point> out;
  for (int i = 0; i < refiner->GetLevel(level).GetNumVertices(); ++i) out.push_back({src[i].p[0], src[i].p[1], src[i].p[2]});
  return out;
}

// Largest distance from one of `ours` to the nearest of `reference`, and back
// (both sorted by x; candidates within `window` in x), over `size`.
double set_distance(std::vector<Point> ours, std::vector<Point> reference, double size) {
  const double window = 1e-6 * size;
  auto one_way = [&](const std::vector<Point>& from, std::vector<Point> to) {
    std::sort(to.begin(), to.end());
    double worst = 0;
    for (const Point& p : from) {
      double nearest = 1e300;
      for (auto it = std::lower_bound(to.begin(), to.end(), Point{p[0] - window, -1e300, -1e300});
           it != to.end() && (*it)[0] <= p[0] + window; ++it)
        nearest = std::min(nearest, distance(p, *it));
      worst = std::max(worst, nearest);
    }
    return worst / size;
  };
  return std::max(one_way(ours, reference), one_way(reference, ours));
}

}  // namespace

TEST_CASE("Loop steps on open meshes equal OpenSubdiv's Far vertex for vertex, edge-only and edge-and-corner",
          "[runtime][boundaries][loop][opensubdiv]") {
  const auto tables = Tables::load(generated_table("loop", "--valence 3-8 --n 4", "sgt").string());
  std::vector<std::pair<std::string, Mesh>> meshes = {{"grid 5x4", triangulated_grid(5, 4)},
                                                      {"grid 1x1", triangulated_grid(1, 1)},
                                                      {"icosahedron without a face", icosahedron_without(-1)},
                                                      {"icosahedron without the faces at vertex 0", icosahedron_without(0)}};
  for (int k = 1; k <= 8; ++k) meshes.push_back({"fan of " + std::to_string(k), fan(k)});
  for (const auto& [name, mesh] : meshes)
    for (bool corners : {false, true}) {
      Mesh m = mesh;
      m.tags.boundary = corners ? BoundaryInterpolation::EdgeAndCorner : BoundaryInterpolation::EdgeOnly;
      Mesh once = subdivide(*tables, m);
      REQUIRE(once.face_count() == 4 * m.face_count());
      once.tags = m.tags;
      const Mesh twice = subdivide(*tables, once);
      INFO(name << (corners ? ", edge-and-corner" : ", edge-only"));
      CHECK(set_distance(once.positions, far_loop_points(m, corners, 1), extent(m)) < 1e-15);
      CHECK(set_distance(twice.positions, far_loop_points(m, corners, 2), extent(m)) < 1e-15);
    }
}

TEST_CASE("sqrt(3) steps refuse a mesh with a boundary, saying why", "[runtime][boundaries][sqrt3]") {
  const auto tables = Tables::load(generated_table("sqrt3", "--valence 3-8 --n 3", "sgt").string());
  CHECK_THROWS_WITH(subdivide(*tables, icosahedron_without(-1)),
                    Catch::Contains("sqrt(3), which splits no edges") && Catch::Contains("meshes with boundaries are refused"));
}
