// Meshes with boundaries (quad schemes): boundary vertices in two faces and,
// with edge-and-corner interpolation, corners in one. Oracles: OpenSubdiv Bfr
// with the same boundary option (Catmull-Clark), and plain subdivision of a
// tube's tensor-product net by the curve rules along and across it, followed
// by the curve's limit stencil (nonpoly and Catmull-Clark), written here; the
// tessellation's rim and Euler characteristic are counted independently.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <sstream>

#include "bfr_distance.hpp"
#include "bfr_reference.hpp"
#include "cli.hpp"
#include "runtime_api.hpp"
#include "open_meshes.hpp"
#include "runtime_checks.hpp"
#include "stencil_runtime/closest_point.hpp"
#include "stencil_runtime/subdivide.hpp"

using namespace stencil_runtime;
using namespace test_runtime;
using namespace test_meshes;
namespace fs = std::filesystem;

namespace {

Surface boundary_surface(const std::shared_ptr<const Tables>& tables, const Mesh& m, bool corners,
                         const std::vector<int>& holes = {}) {
  MeshFeatures features;
  features.boundary = corners ? BoundaryInterpolation::EdgeAndCorner : BoundaryInterpolation::EdgeOnly;
  return Surface(SurfaceTopology::create(tables, m.vertex_count(), m.face_sizes, m.face_vertices, holes, features), m.positions);
}

std::shared_ptr<const Tables> tables_for(const char* scheme) {
  return Tables::load(generated_table(scheme, "--valence 3-8 --n 1-8", "sgs").string());
}

// Plain subdivision of a curve's control polygon by the rules (vertex a, 1-2a,
// a; edge 1/2, 1/2), periodic or with both ends held (the boundary rule).
std::vector<Point> curve_step(const std::vector<Point>& p, double a, bool periodic) {
  const std::size_t n = p.size();
  std::vector<Point> out;
  auto mix = [](const std::vector<std::pair<const Point*, double>>& terms) {
    Point r{0, 0, 0};
    for (const auto& [q, w] : terms)
      for (std::size_t k = 0; k < 3; ++k) r[k] += w * (*q)[k];
    return r;
  };
  for (std::size_t i = 0; i < n; ++i) {
    const bool end = !periodic && (i == 0 || i + 1 == n);
    if (end) out.push_back(p[i]);
    else out.push_back(mix({{&p[(i + n - 1) % n], a}, {&p[i], 1 - 2 * a}, {&p[(i + 1) % n], a}}));
    if (periodic || i + 1 < n) out.push_back(mix({{&p[i], 0.5}, {&p[(i + 1) % n], 0.5}}));
  }
  return out;
}

// The same curve's limit at vertex i (interior: the stencil (b, 1-2b, b); a held end: itself).
Point curve_limit(const std::vector<Point>& p, std::size_t i, double b, bool periodic) {
  const std::size_t n = p.size();
  if (!periodic && (i == 0 || i + 1 == n)) return p[i];
  Point r{0, 0, 0};
  for (std::size_t k = 0; k < 3; ++k) r[k] = b * p[(i + n - 1) % n][k] + (1 - 2 * b) * p[i][k] + b * p[(i + 1) % n][k];
  return r;
}

// Largest differences to OpenSubdiv Bfr (Catmull-Clark, the same boundary
// option), over the mesh size: of every node of every quad at rates 1..8, and
// of the derivatives at four parameters per quad (Bfr's parameterisation of
// other polygons is its own).
std::pair<double, double> bfr_boundary_difference(const std::shared_ptr<const Tables>& tables, const Mesh& mesh, bool corners) {
  const Surface surface = boundary_surface(tables, mesh, corners);
  bfr_reference::Creasing options;
  options.boundary_corners = corners;
  bfr_reference::BfrLimit reference(mesh.positions, mesh.face_sizes, mesh.face_vertices, bfr_reference::osd::Sdc::SCHEME_CATMARK,
                                    {}, options);
  const double size = extent(mesh);
  double worst = 0, worst_derivative = 0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    if (mesh.face_sizes[f] != 4) continue;
    REQUIRE(reference.has_surface(static_cast<int>(f)));
    for (long n = 1; n <= 8; ++n)
      for (long j = 0; j <= n; ++j)
        for (long i = 0; i <= n; ++i) {
          const double u = static_cast<double>(i) / n, v = static_cast<double>(j) / n;
          worst = std::max(worst, distance(surface.evaluate(f, grid(i, j, n)), reference.evaluate(static_cast<int>(f), u, v)) / size);
        }
    for (const auto& [u, v] : {std::pair{0.3, 0.7}, {0.5, 0.125}, {0.9, 0.05}, {0.02, 0.01}}) {
      const Derivatives ours = surface.derivatives(f, u, v);
      const auto ref = reference.derivatives(static_cast<int>(f), u, v);
      worst_derivative = std::max({worst_derivative, distance(ours.du, ref[1]) / size, distance(ours.dv, ref[2]) / size});
    }
  }
  return {worst, worst_derivative};
}

}  // namespace

TEST_CASE("boundaries: every node of every face at rates 1..8 equals OpenSubdiv Bfr with the same boundary option",
          "[runtime][boundaries][opensubdiv]") {
  const auto tables = tables_for("catmull-clark");
  struct Case {
    const char* name;
    Mesh mesh;
    bool corners;
  };
  for (const Case& c : {Case{"open grid 5x4, edge-and-corner", open_grid(5, 4), true},
                        Case{"open grid 1x1, edge-and-corner", open_grid(1, 1), true},
                        Case{"tube 8x3, edge-only", tube(8, 3), false},
                        Case{"tube 3x1, edge-and-corner", tube(3, 1), true},
                        Case{"box open at the top, edge-only", without_first_face("cube"), false},
                        Case{"open house (triangles), edge-only", house(true), false}}) {
    INFO(c.name);
    const auto [worst, worst_derivative] = bfr_boundary_difference(tables, c.mesh, c.corners);
    CHECK(worst < 1e-10);
    CHECK(worst_derivative < 1e-10);
    WARN(c.name << ": largest difference to Bfr over the mesh size " << worst << " (positions), " << worst_derivative
                << " (derivatives)");
  }
}

TEST_CASE("boundaries: vertices on the boundary in 1..8 faces (boundary sectors): every node of every face at rates 1..8 "
          "equals OpenSubdiv Bfr, and the derivatives",
          "[runtime][boundaries][opensubdiv]") {
  const auto tables = tables_for("catmull-clark");
  struct Case {
    std::string name;
    Mesh mesh;
    bool corners;
  };
  std::vector<Case> cases{{"L of three quads, edge-only", l_shape(), false},
                          {"L of three quads, edge-and-corner", l_shape(), true},
                          {"open grid 3x3, edge-only (corners in one face)", open_grid(3, 3), false},
                          {"box without two adjacent faces, edge-only", without_first_face("cube"), false}};
  for (int k = 1; k <= 8; ++k)
    for (bool corners : {false, true}) cases.push_back({"fan of " + std::to_string(k) + " sectors" + (corners ? ", edge-and-corner" : ", edge-only"), boundary_fan(k, 2), corners});
  {  // the box loses a second face, next to the first: the two vertices of their common edge are in one face each
    Mesh& box = cases[3].mesh;
    box.face_sizes.erase(box.face_sizes.begin());
    box.face_vertices.erase(box.face_vertices.begin(), box.face_vertices.begin() + 4);
  }
  for (const Case& c : cases) {
    INFO(c.name);
    const auto [worst, worst_derivative] = bfr_boundary_difference(tables, c.mesh, c.corners);
    CHECK(worst < 1e-10);
    CHECK(worst_derivative < 1e-10);
    WARN(c.name << ": largest difference to Bfr over the mesh size " << worst << " (positions), " << worst_derivative
                << " (derivatives)");
  }
}

TEST_CASE("boundaries: on a tube, nonpoly and Catmull-Clark equal plain subdivision by the curve rules along and "
          "across, and the boundary is the curve of the boundary polygon",
          "[runtime][boundaries]") {
  struct Scheme {
    const char* name;
    double vertex, limit;  // the curve's vertex weight a and limit weight b
  };
  const int around = 6, rows = 3;
  const Mesh m = tube(around, rows);
  for (const Scheme& s : {Scheme{"nonpoly", 1.0 / 6, 1.0 / 5}, Scheme{"catmull-clark", 1.0 / 8, 1.0 / 6}}) {
    const Surface surface = boundary_surface(tables_for(s.name), m, false);
    for (int levels = 1; levels <= 3; ++levels) {
      // The net P[j][i], refined by tensor steps: along i periodic, across j with both ends held.
      std::vector<std::vector<Point>> net(rows + 1);
      for (int j = 0; j <= rows; ++j)
        for (int i = 0; i < around; ++i) net[static_cast<std::size_t>(j)].push_back(m.positions[static_cast<std::size_t>(j * around + i)]);
      for (int l = 0; l < levels; ++l) {
        for (auto& row : net) row = curve_step(row, s.vertex, true);
        std::vector<std::vector<Point>> next;
        for (std::size_t i = 0; i < net[0].size(); ++i) {
          std::vector<Point> column;
          for (const auto& row : net) column.push_back(row[i]);
          column = curve_step(column, s.vertex, false);
          next.resize(column.size());
          for (std::size_t j = 0; j < column.size(); ++j) next[j].push_back(column[j]);
        }
        net = next;
      }
      // Limit: the tensor of the limit stencils (held ends: themselves across).
      std::vector<std::vector<Point>> along(net.size());
      for (std::size_t j = 0; j < net.size(); ++j)
        for (std::size_t i = 0; i < net[j].size(); ++i) along[j].push_back(curve_limit(net[j], i, s.limit, true));
      const long n = 1L << levels;
      double worst = 0, worst_boundary = 0;
      for (int fj = 0; fj < rows; ++fj)
        for (int fi = 0; fi < around; ++fi)
          for (long b = 0; b <= n; ++b)
            for (long a = 0; a <= n; ++a) {
              const std::size_t I = static_cast<std::size_t>((fi * n + a) % (around * n)), J = static_cast<std::size_t>(fj * n + b);
              std::vector<Point> column;
              for (const auto& row : along) column.push_back(row[I]);
              const Point expected = curve_limit(column, J, s.limit, false);
              const double d = distance(surface.evaluate(static_cast<std::size_t>(fj * around + fi), grid(a, b, n)), expected);
              worst = std::max(worst, d);
              if (J == 0 || J + 1 == column.size()) worst_boundary = std::max(worst_boundary, d);
            }
      INFO(s.name << ", rate " << n);
      CHECK(worst < 1e-12);
      CHECK(worst_boundary < 1e-12);
    }
  }
}

namespace {

// Plain subdivision of an open quad mesh by a quad scheme's rules, written
// here independently of the runtime: face points the centroid, edge points
// (end, wing) inside and the midpoint on the boundary, vertex points the
// regular rule inside (the meshes here have no other interior valence) and
// the boundary curve's rule (a, 1-2a, a) over the two boundary neighbours on
// the boundary, or held with `corners` at a vertex in one face. Children of
// face f are 4f + c, child c at corner c with u along the parent's edge c ->
// c+1, as in the runtime's hierarchy.
struct PlainRules {
  double edge_end, edge_wing, centre, edge, face;  // face points: the centroid
  double curve_a, limit_b;  // the curve's vertex weight and limit weight
};

struct PlainMesh {
  std::vector<Point> points;
  std::vector<std::array<int, 4>> faces;
  // Per vertex: the faces round it, and its boundary neighbours (none inside).
  std::vector<std::vector<std::pair<int, int>>> corners_of;  // (face, corner)
  std::vector<std::vector<int>> boundary_neighbours;
  std::map<std::pair<int, int>, std::vector<std::pair<int, int>>> edges;  // (lo, hi) -> (face, corner of the edge's start)

  explicit PlainMesh(std::vector<Point> p, std::vector<std::array<int, 4>> f) : points(std::move(p)), faces(std::move(f)) {
    corners_of.resize(points.size());
    boundary_neighbours.resize(points.size());
    for (std::size_t fi = 0; fi < faces.size(); ++fi)
      for (int c = 0; c < 4; ++c) {
        const int a = faces[fi][static_cast<std::size_t>(c)], b = faces[fi][static_cast<std::size_t>((c + 1) % 4)];
        corners_of[static_cast<std::size_t>(a)].emplace_back(static_cast<int>(fi), c);
        edges[{std::min(a, b), std::max(a, b)}].emplace_back(static_cast<int>(fi), c);
      }
    for (const auto& [e, users] : edges)
      if (users.size() == 1) {
        boundary_neighbours[static_cast<std::size_t>(e.first)].push_back(e.second);
        boundary_neighbours[static_cast<std::size_t>(e.second)].push_back(e.first);
      }
  }
  static PlainMesh of(const Mesh& m) {
    std::vector<std::array<int, 4>> f;
    for (std::size_t k = 0; k < m.face_count(); ++k)
      f.push_back({m.face_vertices[4 * k], m.face_vertices[4 * k + 1], m.face_vertices[4 * k + 2], m.face_vertices[4 * k + 3]});
    return PlainMesh(m.positions, f);
  }
  int vertex(int f, int c) const { return faces[static_cast<std::size_t>(f)][static_cast<std::size_t>((c + 4) % 4)]; }
};

Point mix(const std::vector<std::pair<Point, double>>& terms) {
  Point r{0, 0, 0};
  for (const auto& [p, w] : terms)
    for (std::size_t k = 0; k < 3; ++k) r[k] += w * p[k];
  return r;
}

PlainMesh plain_step(const PlainMesh& m, const PlainRules& r, bool corners) {
  const std::size_t nv = m.points.size(), nf = m.faces.size();
  std::vector<Point> out(nv);
  auto P = [&](int v) { return m.points[static_cast<std::size_t>(v)]; };
  for (std::size_t v = 0; v < nv; ++v) {
    const auto& bn = m.boundary_neighbours[v];
    if (bn.empty()) {  // inside: valence 4 only here
      REQUIRE(m.corners_of[v].size() == 4);
      std::vector<std::pair<Point, double>> t{{P(static_cast<int>(v)), r.centre}};
      for (const auto& [f, c] : m.corners_of[v]) t.emplace_back(P(m.vertex(f, c + 1)), r.edge), t.emplace_back(P(m.vertex(f, c + 2)), r.face);
      out[v] = mix(t);
    } else {
      REQUIRE(bn.size() == 2);
      out[v] = corners && m.corners_of[v].size() == 1
                   ? P(static_cast<int>(v))
                   : mix({{P(bn[0]), r.curve_a}, {P(static_cast<int>(v)), 1 - 2 * r.curve_a}, {P(bn[1]), r.curve_a}});
    }
  }
  std::vector<int> face_point(nf);
  for (std::size_t f = 0; f < nf; ++f) {
    face_point[f] = static_cast<int>(out.size());
    out.push_back(mix({{P(m.faces[f][0]), 0.25}, {P(m.faces[f][1]), 0.25}, {P(m.faces[f][2]), 0.25}, {P(m.faces[f][3]), 0.25}}));
  }
  std::map<std::pair<int, int>, int> edge_point;
  for (const auto& [e, users] : m.edges) {
    edge_point[e] = static_cast<int>(out.size());
    if (users.size() == 1) {
      out.push_back(mix({{P(e.first), 0.5}, {P(e.second), 0.5}}));
    } else {
      std::vector<std::pair<Point, double>> t{{P(e.first), r.edge_end}, {P(e.second), r.edge_end}};
      for (const auto& [f, c] : users) t.emplace_back(P(m.vertex(f, c + 2)), r.edge_wing), t.emplace_back(P(m.vertex(f, c + 3)), r.edge_wing);
      out.push_back(mix(t));
    }
  }
  auto ep = [&](int a, int b) { return edge_point.at({std::min(a, b), std::max(a, b)}); };
  std::vector<std::array<int, 4>> faces;
  for (std::size_t f = 0; f < nf; ++f)
    for (int c = 0; c < 4; ++c) {
      const int v = m.vertex(static_cast<int>(f), c), next = m.vertex(static_cast<int>(f), c + 1), prev = m.vertex(static_cast<int>(f), c - 1);
      faces.push_back({v, ep(v, next), face_point[f], ep(prev, v)});
    }
  return PlainMesh(out, faces);
}

// The limit position of a vertex of a plain mesh: the tensor of the curve's
// limit stencil inside (regular vertices only), the curve's along the boundary.
Point plain_limit(const PlainMesh& m, int v, const PlainRules& r, bool corners) {
  const auto& bn = m.boundary_neighbours[static_cast<std::size_t>(v)];
  const Point p = m.points[static_cast<std::size_t>(v)];
  const double b = r.limit_b;
  if (!bn.empty()) {
    if (corners && m.corners_of[static_cast<std::size_t>(v)].size() == 1) return p;
    return mix({{m.points[static_cast<std::size_t>(bn[0])], b}, {p, 1 - 2 * b}, {m.points[static_cast<std::size_t>(bn[1])], b}});
  }
  std::vector<std::pair<Point, double>> t{{p, (1 - 2 * b) * (1 - 2 * b)}};
  for (const auto& [f, c] : m.corners_of[static_cast<std::size_t>(v)])
    t.emplace_back(m.points[static_cast<std::size_t>(m.vertex(f, c + 1))], b * (1 - 2 * b)), t.emplace_back(m.points[static_cast<std::size_t>(m.vertex(f, c + 2))], b * b);
  return mix(t);
}

// The vertex of the level-L plain mesh at node (i, j) / 2^L of original face f.
int plain_node(const PlainMesh& fine, int f, long i, long j, int levels) {
  for (int l = levels; l > 0; --l) {
    const long h = 1L << (l - 1);
    int c = 0;
    long x = i, y = j;
    if (i <= h && j <= h) c = 0, x = i, y = j;
    else if (j <= h) c = 1, x = j, y = 2 * h - i;
    else if (i >= h) c = 2, x = 2 * h - i, y = 2 * h - j;
    else c = 3, x = 2 * h - j, y = i;
    f = 4 * f + c, i = x, j = y;
  }
  static constexpr int corner_of[2][2] = {{0, 3}, {1, 2}};  // [i][j]
  return fine.vertex(f, corner_of[i][j]);
}

}  // namespace

TEST_CASE("boundaries: vertices on the boundary in 1..8 faces, nonpoly and Catmull-Clark, equal plain subdivision by the "
          "scheme's rules followed by the limit stencils at every dyadic node",
          "[runtime][boundaries]") {
  struct Scheme {
    const char* name;
    PlainRules rules;
  };
  for (const Scheme& s : {Scheme{"nonpoly", {1.0 / 3, 1.0 / 12, 4.0 / 9, 1.0 / 9, 1.0 / 36, 1.0 / 6, 1.0 / 5}},
                          Scheme{"catmull-clark", {3.0 / 8, 1.0 / 16, 9.0 / 16, 3.0 / 32, 1.0 / 64, 1.0 / 8, 1.0 / 6}}}) {
    const auto tables = tables_for(s.name);
    std::vector<std::pair<std::string, Mesh>> meshes{{"L of three quads", l_shape()}, {"open grid 2x2", open_grid(2, 2)}};
    for (int k : {1, 3, 4, 5, 8}) meshes.emplace_back("fan of " + std::to_string(k), boundary_fan(k, 2));
    for (const auto& [name, mesh] : meshes)
      for (bool corners : {false, true}) {
        INFO(s.name << ", " << name << (corners ? ", edge-and-corner" : ", edge-only"));
        const Surface surface = boundary_surface(tables, mesh, corners);
        PlainMesh fine = PlainMesh::of(mesh);
        const double size = extent(mesh);
        for (int levels = 1; levels <= 3; ++levels) {
          fine = plain_step(fine, s.rules, corners);
          const long n = 1L << levels;
          double worst = 0;
          for (std::size_t f = 0; f < mesh.face_count(); ++f)
            for (long j = 0; j <= n; ++j)
              for (long i = 0; i <= n; ++i) {
                const int v = plain_node(fine, static_cast<int>(f), i, j, levels);
                worst = std::max(worst, distance(surface.evaluate(f, grid(i, j, n)), plain_limit(fine, v, s.rules, corners)) / size);
              }
          INFO("rate " << n);
          CHECK(worst < 1e-13);
        }
      }
  }
}

TEST_CASE("boundaries: the normal at a boundary vertex is the limit of the surface's normals next to it where the "
          "sector has a tangent plane, and refused with the reason where it has none",
          "[runtime][boundaries][normals]") {
  auto angle = [](const Point& a, const Point& b) {  // accurate near 0 too
    const Point c{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    return std::atan2(std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]), a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
  };
  int with_normal = 0;
  for (const char* scheme : {"catmull-clark", "nonpoly"}) {
    const auto tables = tables_for(scheme);
    for (int k : {1, 3, 4, 5, 6, 7, 8}) {
      INFO(scheme << ", vertex in " << k << " faces");
      const Mesh mesh = boundary_fan(k, 2);
      const Surface surface = boundary_surface(tables, mesh, false);
      Point at_vertex{};
      try {
        at_vertex = surface.normal(0, 0.0, 0.0);
      } catch (const EvaluationError& e) {
        CHECK_THAT(e.what(), Catch::Contains("no normal at it") && Catch::Contains("in " + std::to_string(k) + " face"));
        continue;
      }
      ++with_normal;
      // Face 0 of each sector of the fan has the vertex at its corner (0, 0): they all give the same normal.
      for (int s = 1; s < k; ++s) CHECK(angle(surface.normal(static_cast<std::size_t>(4 * s), 0.0, 0.0), at_vertex) < 1e-10);
      // The surface's normals next to the vertex (its derivatives, by the patch descent) approach it, along the
      // diagonal and along the boundary edge, at a rate set by the eigenvalues below the two that span the plane.
      // (Much deeper, near a vertex in one face the two derivatives turn nearly parallel and their cross product
      // is rounding.)
      for (bool diagonal : {true, false}) {
        std::vector<double> off;
        for (int depth : {5, 10, 20}) {
          const double e = std::ldexp(1.0, -depth);
          off.push_back(angle(surface.derivatives(0, e, diagonal ? e : 0.0).normal(), at_vertex));
        }
        CHECK(off[2] < 1e-3);
        CHECK(off[2] < off[1]);
        CHECK(off[1] < off[0]);
        WARN(scheme << ", " << k << " faces, " << (diagonal ? "diagonal" : "boundary edge") << ": the normals at 2^-5, 2^-10, "
                    << "2^-20 from the vertex are " << off[0] << ", " << off[1] << ", " << off[2] << " rad from its normal");
      }
    }
  }
  CHECK(with_normal == 3);  // three faces for both schemes, one face for nonpoly (docs/table-format.md)
}

TEST_CASE("boundaries: tessellations are closed except along the mesh's boundaries and holes, with the right Euler "
          "characteristic", "[runtime][boundaries][tessellation]") {
  std::mt19937 rng(20261125u);
  struct Case {
    const char* name;
    Mesh mesh;
    bool corners;
    std::vector<int> holes;
    std::size_t loops;
  };
  for (const char* scheme : {"nonpoly", "catmull-clark"}) {
    const auto tables = tables_for(scheme);
    for (const Case& c : {Case{"open grid", open_grid(4, 3), true, {}, 1},
                          Case{"tube", tube(7, 2), false, {}, 2},
                          Case{"open box", without_first_face("cube"), false, {}, 1},
                          Case{"open box with a hole in its floor", without_first_face("cube"), false, {0}, 2},
                          Case{"open house", house(true), false, {}, 1},
                          Case{"open grid, edge-only (corners in one face)", open_grid(3, 3), false, {}, 1},
                          Case{"L of three quads", l_shape(), false, {}, 1},
                          Case{"fan of 1 sector", boundary_fan(1, 2), false, {}, 1},
                          Case{"fan of 3 sectors", boundary_fan(3, 2), false, {}, 1},
                          Case{"fan of 5 sectors with a hole", boundary_fan(5, 4), false, {37}, 2},
                          Case{"fan of 8 sectors", boundary_fan(8, 1), true, {}, 1}}) {
      const Surface surface = boundary_surface(tables, c.mesh, c.corners, c.holes);
      for (int trial = 0; trial < 4; ++trial) {
        std::vector<int> rates(c.mesh.face_count());
        for (int& r : rates) r = std::uniform_int_distribution<int>(1, 8)(rng);
        INFO(scheme << ", " << c.name << ", trial " << trial);
        check_rimmed_manifold(tessellate(surface, rates), c.loops, 0);
      }
    }
  }
}

namespace {

// The limit points where the surface ends, from Bfr: on every edge of a face
// that has a surface and none across it (the mesh's boundary, or a hole), the
// nodes t/n along it in the face's (u, v) (a quad's or a triangle's corners).
std::vector<Point> bfr_rim(const Mesh& mesh, const std::vector<int>& holes, int n, bfr_reference::BfrLimit& reference) {
  std::vector<char> hole(mesh.face_count(), 0);
  for (int h : holes) hole[static_cast<std::size_t>(h)] = 1;
  std::map<std::pair<int, int>, int> faces_on;  // undirected edge -> faces with a surface
  std::vector<std::size_t> offset(mesh.face_count() + 1, 0);
  for (std::size_t f = 0; f < mesh.face_count(); ++f) offset[f + 1] = offset[f] + static_cast<std::size_t>(mesh.face_sizes[f]);
  auto vertex = [&](std::size_t f, int k) { return mesh.face_vertices[offset[f] + static_cast<std::size_t>(k % mesh.face_sizes[f])]; };
  for (std::size_t f = 0; f < mesh.face_count(); ++f)
    for (int k = 0; k < mesh.face_sizes[f] && !hole[f]; ++k)
      ++faces_on[std::minmax(vertex(f, k), vertex(f, k + 1))];
  std::vector<Point> out;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    if (hole[f]) continue;
    const int size = mesh.face_sizes[f];
    for (int k = 0; k < size; ++k) {
      if (faces_on[std::minmax(vertex(f, k), vertex(f, k + 1))] != 1) continue;
      for (int t = 0; t < n; ++t) {  // node n is the next edge's node 0
        const double s = static_cast<double>(t) / n;
        double u = 0, v = 0;
        if (size == 4) {
          const double corner[4][2] = {{s, 0}, {1, s}, {1 - s, 1}, {0, 1 - s}};
          u = corner[k][0], v = corner[k][1];
        } else {
          const double corner[3][2] = {{s, 0}, {1 - s, s}, {0, 1 - s}};
          u = corner[k][0], v = corner[k][1];
        }
        out.push_back(reference.evaluate(static_cast<int>(f), u, v));
      }
    }
  }
  return out;
}

// The tessellation's rim (the points on edges of one polygon) against the
// expected points, both ways, to float rounding; the largest distance either way.
double rim_distance(const PolygonSoup& soup, const std::vector<Point>& expected, std::size_t& rim_count) {
  std::set<std::pair<int, int>> directed;
  auto polygon = [&](const int* p, int k) {
    for (int i = 0; i < k; ++i) directed.insert({p[i], p[(i + 1) % k]});
  };
  for (const auto& q : soup.quads) polygon(q.data(), 4);
  for (const auto& t : soup.triangles) polygon(t.data(), 3);
  std::set<int> rim;
  for (const auto& [a, b] : directed)
    if (!directed.count({b, a})) rim.insert(a), rim.insert(b);
  rim_count = rim.size();
  auto nearest = [](const Point& p, const std::vector<Point>& among) {
    double best = HUGE_VAL;
    for (const Point& q : among) best = std::min(best, distance(p, q));
    return best;
  };
  std::vector<Point> ours;
  for (int r : rim) {
    const auto& p = soup.positions[static_cast<std::size_t>(r)];
    ours.push_back({p[0], p[1], p[2]});
  }
  double worst = 0;
  for (const Point& p : ours) worst = std::max(worst, nearest(p, expected));
  for (const Point& p : expected) worst = std::max(worst, nearest(p, ours));
  return worst;
}

}  // namespace

TEST_CASE("boundaries and holes: a tessellation reaches the surface's edge: its rim is the limit points of every edge "
          "the surface ends at, at the faces' grid nodes (OpenSubdiv Bfr), with unit normals",
          "[runtime][boundaries][holes][tessellation]") {
  struct Case {
    const char* name;
    Mesh mesh;
    bool corners;
    std::vector<int> holes;
  };
  const auto catmark = tables_for("catmull-clark");
  const Mesh torus = read_obj((fs::path(STENCIL_SOURCE_DIR) / "meshes" / "tri-torus.obj").string());
  const auto loop = Tables::load(generated_table("loop", "--valence 3-8 --n 1-8", "sgt").string());
  for (const Case& c : {Case{"open grid", open_grid(4, 3), true, {}}, Case{"open grid, edge-only", open_grid(3, 3), false, {}},
                        Case{"tube", tube(7, 2), false, {}}, Case{"open box", without_first_face("cube"), false, {}},
                        Case{"open box with a hole in its floor", without_first_face("cube"), false, {0}},
                        Case{"L of three quads", l_shape(), false, {}}, Case{"fan of 1 sector", boundary_fan(1, 2), false, {}},
                        Case{"fan of 3 sectors", boundary_fan(3, 2), false, {}},
                        Case{"fan of 5 sectors with a hole", boundary_fan(5, 4), false, {37}},
                        Case{"fan of 8 sectors", boundary_fan(8, 1), true, {}},
                        Case{"Loop: triangle torus with two holes touching at a vertex", torus, false, {0, 2}}}) {
    const bool triangles = c.mesh.face_sizes.front() == 3;
    const Surface surface = triangles ? Surface(SurfaceTopology::create(loop, c.mesh.vertex_count(), c.mesh.face_sizes,
                                                                        c.mesh.face_vertices, c.holes),
                                                c.mesh.positions)
                                      : boundary_surface(catmark, c.mesh, c.corners, c.holes);
    bfr_reference::Creasing options;
    options.boundary_corners = c.corners;
    bfr_reference::BfrLimit reference(c.mesh.positions, c.mesh.face_sizes, c.mesh.face_vertices,
                                      triangles ? bfr_reference::osd::Sdc::SCHEME_LOOP : bfr_reference::osd::Sdc::SCHEME_CATMARK,
                                      c.holes, options);
    const double size = extent(c.mesh);
    for (int n : {2, 4, 8}) {
      INFO(c.name << ", rate " << n);
      const PolygonSoup soup = tessellate(surface, std::vector<int>(c.mesh.face_count(), n), {}, true);
      const std::vector<Point> expected = bfr_rim(c.mesh, c.holes, n, reference);
      std::size_t rim_count = 0;
      CHECK(rim_distance(soup, expected, rim_count) <= 1e-6 * size);
      CHECK(rim_count == expected.size());  // one point per node, none doubled or missing
      for (const auto& normal : soup.normals)
        CHECK(std::abs(std::hypot(normal[0], normal[1], normal[2]) - 1) < 1e-5);
    }
  }
}

TEST_CASE("boundaries the tables or the runtime have no patches for are refused, naming the vertex", "[runtime][boundaries]") {
  const auto tables = tables_for("catmull-clark");
  // Tables of valences up to 8 hold the boundary sectors of up to 8 faces: a vertex in 9 asks for more.
  CHECK_THROWS_WITH(boundary_surface(tables, boundary_fan(9, 1), false),
                    Catch::Contains("vertex 0 is on a boundary or crease in 9 faces") &&
                        Catch::Contains("stencilgen --scheme catmull-clark --valence 3,5-9 --n 1-8"));
  MeshFeatures none;
  none.boundary = BoundaryInterpolation::None;
  const Mesh t = tube(5, 2);
  CHECK_THROWS_WITH(SurfaceTopology::create(tables, t.vertex_count(), t.face_sizes, t.face_vertices, {}, none),
                    Catch::Contains("every face has a vertex on the boundary"));
  // Loop: tables of valences up to 8 hold the sectors of up to 8 faces; an open fan of 9 triangles asks for more.
  const auto loop = Tables::load(generated_table("loop", "--valence 3-8 --n 1-4", "sgt").string());
  std::vector<int> sizes(9, 3), vertices;
  for (int j = 0; j < 9; ++j) vertices.insert(vertices.end(), {0, j + 1, j + 2});
  CHECK_THROWS_WITH(SurfaceTopology::create(loop, 11, sizes, vertices),
                    Catch::Contains("vertex 0 is on the boundary in 9 faces") &&
                        Catch::Contains("stencilgen --scheme loop --valence 3-5,7-9 --n 1-4"));
}

TEST_CASE("boundaries from the OBJ tag and the tools' --boundary option", "[runtime][boundaries][tags]") {
  const fs::path dir = scratch_dir("boundary-cli");
  const Mesh grid_mesh = open_grid(3, 2);
  const fs::path plain = dir / "grid.obj", tagged = dir / "grid-tagged.obj";
  {
    std::ofstream a(plain), b(tagged);
    for (const auto& p : grid_mesh.positions) a << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    std::size_t k = 0;
    for (int size : grid_mesh.face_sizes) {
      a << 'f';
      for (int c = 0; c < size; ++c) a << ' ' << grid_mesh.face_vertices[k++] + 1;
      a << '\n';
    }
    a.flush();
    std::ifstream in(plain);
    b << in.rdbuf() << "t interpolateboundary 1/0/0 1\n";
  }
  const std::string tables = generated_table("catmull-clark", "--valence 3-8 --n 1-8", "sgs").string();
  // The corner (0, 0) is interpolated exactly with edge-and-corner, from the tag or the option.
  const CliResult from_tag = run_stencileval("--tables " + tables + " --mesh " + tagged.string() + " --face 0 --uv 0,0");
  REQUIRE(from_tag.status == 0);
  const CliResult from_option =
      run_stencileval("--tables " + tables + " --mesh " + plain.string() + " --boundary edge-and-corner --face 0 --uv 0,0");
  REQUIRE(from_option.status == 0);
  CHECK(from_tag.output == from_option.output);
  // Without it (edge only, OpenSubdiv's default) the corner follows the boundary curve: its limit is
  // 1/6, 2/3, 1/6 of its boundary neighbours (vertices 1 and 4) and itself.
  const CliResult edge_only = run_stencileval("--tables " + tables + " --mesh " + plain.string() + " --face 0 --uv 0,0");
  REQUIRE(edge_only.status == 0);
  auto last_point = [](const std::string& out) {
    std::istringstream lines(out);
    std::string line, last;
    while (std::getline(lines, line))
      if (!line.empty()) last = line;
    Point p{};
    std::istringstream(last) >> p[0] >> p[1] >> p[2];
    return p;
  };
  const auto& P = grid_mesh.positions;
  Point curve{};
  for (std::size_t k = 0; k < 3; ++k) curve[k] = P[1][k] / 6 + 2 * P[0][k] / 3 + P[4][k] / 6;
  CHECK(distance(last_point(edge_only.output), curve) < 1e-6);
  CHECK(distance(last_point(from_tag.output), P[0]) < 1e-6);
  // The option overrides the tag.
  const CliResult overridden =
      run_stencileval("--tables " + tables + " --mesh " + tagged.string() + " --boundary edge-only --face 0 --uv 0,0");
  REQUIRE(overridden.status == 0);
  CHECK(overridden.output == edge_only.output);
  const CliResult tess = run_stenciltess("--tables " + tables + " --mesh " + tagged.string() + " --rate 4 --out " +
                                         (dir / "t.obj").string());
  CHECK(tess.status == 0);
  CHECK(fs::exists(dir / "t.obj"));
  const CliResult bad = run_stenciltess("--tables " + tables + " --mesh " + plain.string() + " --boundary sideways --rate 4 --out " +
                                        (dir / "u.obj").string());
  CHECK(bad.status == 1);
  CHECK(!fs::exists(dir / "u.obj"));
}

TEST_CASE("boundaries: closest points equal a Bfr brute force, also where the nearest point is on the boundary curve "
          "or at a boundary vertex in other than two faces",
          "[runtime][boundaries][distance][opensubdiv]") {
  std::mt19937 rng(11);
  const auto tables = tables_for("catmull-clark");
  for (const Mesh& mesh : {tube(8, 3), without_first_face("cube"), l_shape(), open_grid(3, 3), boundary_fan(5, 2)}) {
    const Surface surface = boundary_surface(tables, mesh, false);
    const ClosestPointQuery query(surface);
    const bfr_reference::BfrOracle oracle(mesh);
    const double size = extent(mesh);
    std::uniform_real_distribution<double> coordinate(-2.0, 2.5);
    for (int k = 0; k < 40; ++k) {
      const Point q{coordinate(rng), coordinate(rng), coordinate(rng)};
      INFO(mesh.face_count() << "-face mesh, query " << k << ": " << q[0] << " " << q[1] << " " << q[2]);
      const ClosestPoint ours = query.find(q);
      REQUIRE(ours.found);
      CHECK(std::abs(ours.distance - oracle.distance_to(q)) < 1e-8 * size);
      CHECK(distance(surface.evaluate(ours.face, ours.u, ours.v, 1e-12).point, ours.point) < 1e-9 * size);
    }
  }
}

TEST_CASE("boundaries: subdivide() on an open mesh keeps its limit surface", "[runtime][boundaries]") {
  for (const char* scheme : {"catmull-clark", "nonpoly"}) {
    const auto tables = tables_for(scheme);
    for (bool corners : {false, true}) {
      Mesh mesh = corners ? open_grid(4, 3) : without_first_face("cube");
      mesh.tags.boundary = corners ? BoundaryInterpolation::EdgeAndCorner : BoundaryInterpolation::EdgeOnly;
      const Mesh refined = subdivide(*tables, mesh);
      REQUIRE(refined.face_count() == 4 * mesh.face_count());
      const Surface before = boundary_surface(tables, mesh, corners), after = boundary_surface(tables, refined, corners);
      double worst = 0;
      // Child 0 of face f is face 4f, the quadrant at f's corner 0 with the same axes.
      for (std::size_t f = 0; f < mesh.face_count(); ++f)
        for (long j = 0; j <= 4; ++j)
          for (long i = 0; i <= 4; ++i)
            worst = std::max(worst, distance(after.evaluate(4 * f, grid(i, j, 4)), before.evaluate(f, grid(i, j, 8))));
      INFO(scheme << (corners ? ", open grid with corners" : ", open box"));
      CHECK(worst < 1e-13 * extent(mesh));
    }
  }
}

TEST_CASE("boundaries, `none`: faces at boundary vertices have no surface, the others equal Bfr's with VTX_BOUNDARY_NONE",
          "[runtime][boundaries][opensubdiv]") {
  const auto tables = tables_for("catmull-clark");
  Mesh l_shape = open_grid(4, 4);  // an L: boundary vertices in 1, 2 and 3 faces, all allowed with `none`
  for (int k = 0; k < 2; ++k) {  // the last two faces of the top row
    l_shape.face_sizes.pop_back();
    l_shape.face_vertices.resize(l_shape.face_vertices.size() - 4);
  }
  l_shape.positions.resize(l_shape.positions.size() - 2);  // their two top-right vertices are in no face now
  for (const Mesh& mesh : {open_grid(5, 4), tube(6, 4), l_shape}) {
    MeshFeatures features;
    features.boundary = BoundaryInterpolation::None;
    const Surface surface(SurfaceTopology::create(tables, mesh.vertex_count(), mesh.face_sizes, mesh.face_vertices, {}, features),
                          mesh.positions);
    using Osd = OpenSubdiv::Far::TopologyDescriptor;
    Osd desc;
    desc.numVertices = static_cast<int>(mesh.vertex_count());
    desc.numFaces = static_cast<int>(mesh.face_count());
    desc.numVertsPerFace = mesh.face_sizes.data();
    desc.vertIndicesPerFace = mesh.face_vertices.data();
    OpenSubdiv::Sdc::Options sdc;
    sdc.SetVtxBoundaryInterpolation(OpenSubdiv::Sdc::Options::VTX_BOUNDARY_NONE);
    using Factory = OpenSubdiv::Far::TopologyRefinerFactory<Osd>;
    std::unique_ptr<OpenSubdiv::Far::TopologyRefiner> refiner(
        Factory::Create(desc, Factory::Options(OpenSubdiv::Sdc::SCHEME_CATMARK, sdc)));
    REQUIRE(refiner);
    OpenSubdiv::Bfr::RefinerSurfaceFactory<> factory(*refiner);
    std::vector<double> flat;
    for (const Point& p : mesh.positions) flat.insert(flat.end(), p.begin(), p.end());
    const double size = extent(mesh);
    double worst = 0;
    std::size_t with_surface = 0;
    for (std::size_t f = 0; f < mesh.face_count(); ++f) {
      INFO(mesh.face_count() << "-face mesh, face " << f);
      const bool has = factory.FaceHasLimitSurface(static_cast<int>(f));
      REQUIRE(surface.topology().is_hole(f) == !has);
      if (!has) {
        CHECK_THROWS_WITH(surface.evaluate(f, grid(1, 1, 2)), Catch::Contains("under boundary interpolation `none` such faces have no surface"));
        continue;
      }
      ++with_surface;
      OpenSubdiv::Bfr::Surface<double> bfr;
      REQUIRE(factory.InitVertexSurface(static_cast<int>(f), &bfr));
      std::vector<double> patch(static_cast<std::size_t>(bfr.GetNumPatchPoints()) * 3);
      bfr.PreparePatchPoints(flat.data(), 3, patch.data(), 3);
      for (long j = 0; j <= 6; ++j)
        for (long i = 0; i <= 6; ++i) {
          const double uv[2] = {i / 6.0, j / 6.0};
          Point ref{};
          bfr.Evaluate(uv, patch.data(), 3, ref.data());
          worst = std::max(worst, distance(surface.evaluate(f, grid(i, j, 6)), ref) / size);
        }
    }
    CHECK(with_surface > 0);
    CHECK(worst < 1e-10);
    std::vector<int> rates(mesh.face_count(), 3);
    const PolygonSoup soup = tessellate(surface, rates);
    CHECK(!soup.positions.empty());
  }
}

