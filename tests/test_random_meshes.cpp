// Random meshes with random boundaries, holes, creases, corners and boundary
// options, Catmull-Clark and Loop, against OpenSubdiv's Bfr with the same
// tags: every node of every face at a few rates, positions and derivatives.
// The meshes are made here from grids, tubes, tori and the bundled meshes by
// dropping faces at random (which makes boundary vertices of every count of
// faces, corners, vertices in no face and vertices where two boundaries touch,
// which OpenSubdiv makes corners) and by flipping a face now and then (its
// edges then non-manifold, which OpenSubdiv makes infinitely sharp), so they reach
// configurations no hand-made test names. A mesh the runtime refuses must be
// refused with a message that names what it lacks; such refusals are counted
// and shown, and a refusal of anything but a documented limitation fails.
//
// nonpoly, which nothing else evaluates, is checked for continuity across
// every edge instead. The default suite runs a few dozen meshes per scheme; `runtime_tests
// "[soak]"` runs STENCIL_SOAK_MESHES of them (default 400) with its own seed
// (STENCIL_SOAK_SEED).

#include <algorithm>
#include <cmath>
#include <catch2/catch.hpp>
#include <cstdlib>
#include <map>
#include <random>
#include <set>
#include <sstream>

#include "bfr_reference.hpp"
#include "cli.hpp"
#include "closest_point_checks.hpp"
#include "loop_meshes.hpp"
#include "open_meshes.hpp"
#include "runtime_api.hpp"
#include "runtime_checks.hpp"
#include "sharp_features.hpp"
#include "stencil_runtime/closest_point.hpp"
#include "stencil_runtime/tessellation.hpp"

using namespace stencil_runtime;
using namespace test_runtime;

namespace {

using test_meshes::bundled;

// A torus of `around` x `rows` quads.
Mesh quad_torus(int around, int rows) {
  Mesh m;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < around; ++i) {
      const double a = 2 * M_PI * i / around, b = 2 * M_PI * j / rows, r = 2 + 0.7 * std::cos(b) + 0.05 * (i % 3);
      m.positions.push_back({r * std::cos(a), r * std::sin(a), 0.7 * std::sin(b) + 0.03 * (j % 2)});
    }
  auto at = [&](int i, int j) { return (j % rows) * around + (i % around); };
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < around; ++i) {
      m.face_sizes.push_back(4);
      m.face_vertices.insert(m.face_vertices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return m;
}

// An open grid of quads each split into two triangles along a random diagonal
// (inner vertices of valence 4 to 8).
Mesh triangle_grid(int columns, int rows, std::mt19937& rng) {
  Mesh m = test_meshes::open_grid(columns, rows);
  std::vector<int> vertices;
  for (std::size_t f = 0; f < m.face_count(); ++f) {
    const int* q = &m.face_vertices[4 * f];
    if (rng() % 2) vertices.insert(vertices.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
    else vertices.insert(vertices.end(), {q[0], q[1], q[3], q[1], q[2], q[3]});
  }
  m.face_vertices = vertices;
  m.face_sizes.assign(vertices.size() / 3, 3);
  return m;
}

// The mesh with each face dropped with probability `p` (the vertices stay, some in no face).
Mesh drop_faces(const Mesh& m, double p, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  Mesh out;
  out.positions = m.positions;
  std::size_t first = 0;
  for (int k : m.face_sizes) {
    if (u(rng) >= p) {
      out.face_sizes.push_back(k);
      out.face_vertices.insert(out.face_vertices.end(), m.face_vertices.begin() + static_cast<long>(first),
                               m.face_vertices.begin() + static_cast<long>(first + static_cast<std::size_t>(k)));
    }
    first += static_cast<std::size_t>(k);
  }
  return out;
}

std::vector<std::pair<int, int>> edges_of(const Mesh& m) {
  std::set<std::pair<int, int>> out;
  std::size_t corner = 0;
  for (int k : m.face_sizes) {
    for (int c = 0; c < k; ++c) {
      const int a = m.face_vertices[corner + static_cast<std::size_t>(c)];
      const int b = m.face_vertices[corner + static_cast<std::size_t>((c + 1) % k)];
      out.insert({std::min(a, b), std::max(a, b)});
    }
    corner += static_cast<std::size_t>(k);
  }
  return {out.begin(), out.end()};
}

struct Case {
  Mesh mesh;
  SharpFeatures features;
  std::vector<int> holes;
  std::string what;
};

// A random mesh of the family and random tags on it.
// The mesh with face f's orientation reversed (its edges then used twice in one direction).
Mesh flipped(Mesh m, std::size_t f) {
  std::size_t first = 0;
  for (std::size_t g = 0; g < f; ++g) first += static_cast<std::size_t>(m.face_sizes[g]);
  std::reverse(m.face_vertices.begin() + static_cast<std::ptrdiff_t>(first),
               m.face_vertices.begin() + static_cast<std::ptrdiff_t>(first) + m.face_sizes[f]);
  return m;
}

Case random_case(bool loop, std::mt19937& rng) {
  Case c;
  std::ostringstream what;
  const int base = static_cast<int>(rng() % (loop ? 5 : 7));
  const int a = 3 + static_cast<int>(rng() % 4), b = 3 + static_cast<int>(rng() % 4);
  if (!loop) {
    switch (base) {
      case 0: c.mesh = test_meshes::open_grid(a, b), what << "grid " << a << "x" << b; break;
      case 1: c.mesh = test_meshes::tube(a + 1, b), what << "tube " << a + 1 << "x" << b; break;
      case 2: c.mesh = quad_torus(a + 1, b), what << "torus " << a + 1 << "x" << b; break;
      case 3: c.mesh = test_meshes::boundary_fan(1 + static_cast<int>(rng() % 8), 2), what << "boundary fan"; break;
      case 5: c.mesh = triangle_grid(a, b, rng), what << "triangle grid " << a << "x" << b << " (the polygon step)"; break;
      case 6: c.mesh = test_meshes::house(rng() % 2 == 0), what << "house (quads and triangles)"; break;
      default: {
        const char* names[] = {"cube", "quad-sphere", "torus-3-5", "bumpy-sphere", "chess-piece"};
        const char* name = names[rng() % 5];
        c.mesh = bundled(name), what << name;
      }
    }
  } else {
    switch (base) {
      case 0: c.mesh = triangle_grid(a, b, rng), what << "triangle grid " << a << "x" << b; break;
      case 1: c.mesh = loop_meshes::triangle_tube(a + 1, b), what << "triangle tube " << a + 1 << "x" << b; break;
      case 2:
        c.mesh = loop_meshes::with_flip(loop_meshes::triangle_torus(a + 1, b), a + 1, static_cast<int>(rng() % static_cast<unsigned>(b)));
        what << "triangle torus with a flip " << a + 1 << "x" << b;
        break;
      default: {
        const char* names[] = {"icosahedron", "tri-mix", "tri-torus"};
        const char* name = names[rng() % 3];
        c.mesh = bundled(name), what << name;
      }
    }
  }
  std::uniform_real_distribution<double> u(0, 1);
  const double drop = u(rng) < 0.3 ? 0.0 : 0.35 * u(rng);
  c.mesh = drop_faces(c.mesh, drop, rng);
  if (c.mesh.face_count() == 0) c.mesh = loop ? loop_meshes::triangle_tube(4, 2) : test_meshes::tube(4, 2);
  what << ", " << c.mesh.face_count() << " faces kept";
  if (u(rng) < 0.2) {  // a face flipped against its neighbours: its shared edges non-manifold
    const std::size_t f = rng() % c.mesh.face_count();
    c.mesh = flipped(c.mesh, f);
    what << ", face " << f << " flipped";
  }

  const float sharpness[] = {0.5f, 1.0f, 2.5f, 10.0f};
  const double crease_share = u(rng) < 0.3 ? 0.0 : 0.25 * u(rng);
  for (const auto& [x, y] : edges_of(c.mesh))
    if (u(rng) < crease_share) c.features.crease(x, y, sharpness[rng() % 4]);
  const int corners = static_cast<int>(rng() % 3);
  for (int k = 0; k < corners; ++k)
    c.features.corner(static_cast<int>(rng() % c.mesh.vertex_count()), sharpness[rng() % 4]);
  const int holes = c.mesh.face_count() > 4 ? static_cast<int>(rng() % 3) : 0;
  for (int k = 0; k < holes; ++k) c.holes.push_back(static_cast<int>(rng() % c.mesh.face_count()));
  std::sort(c.holes.begin(), c.holes.end());
  c.holes.erase(std::unique(c.holes.begin(), c.holes.end()), c.holes.end());
  const BoundaryInterpolation options[] = {BoundaryInterpolation::EdgeOnly, BoundaryInterpolation::EdgeAndCorner,
                                           BoundaryInterpolation::None};
  const BoundaryInterpolation option = options[rng() % 3];
  c.features.boundary(option);
  const bool triangles = std::find(c.mesh.face_sizes.begin(), c.mesh.face_sizes.end(), 3) != c.mesh.face_sizes.end();
  if (!loop && triangles && rng() % 2) c.features.smooth_triangles(), what << ", smooth triangles";
  what << ", " << c.features.ours.edges.size() << " sharp edges, " << corners << " sharp vertices, " << c.holes.size()
       << " holes, boundary "
       << (option == BoundaryInterpolation::EdgeOnly ? "edge-only" : option == BoundaryInterpolation::EdgeAndCorner ? "edge-and-corner" : "none");
  what << "\n  tags:";
  for (const auto& e : c.features.ours.edges) what << " crease " << e.a << "-" << e.b << " " << e.sharpness << ";";
  for (const auto& v : c.features.ours.vertices) what << " corner " << v.vertex << " " << v.sharpness << ";";
  for (int h : c.holes) what << " hole " << h << ";";
  c.what = what.str();
  return c;
}

// The vertices where Bfr's limit point is not the surface's: infinitely sharp
// darts (one infinitely sharp edge at an inner vertex of no infinite vertex
// sharpness), where OpenSubdiv's limit mask is its smooth one (shown in
// test_creases.cpp and test_triangle_sector.cpp against Far's own refinement).
std::set<int> bfr_dart_vertices(const Case& c) {
  std::map<std::pair<int, int>, int> faces_at_edge;
  std::size_t first = 0;
  std::set<int> holes(c.holes.begin(), c.holes.end());
  for (std::size_t f = 0; f < c.mesh.face_count(); ++f) {
    const int k = c.mesh.face_sizes[f];
    for (int i = 0; i < k; ++i) {
      const int x = c.mesh.face_vertices[first + static_cast<std::size_t>(i)];
      const int y = c.mesh.face_vertices[first + static_cast<std::size_t>((i + 1) % k)];
      ++faces_at_edge[{std::min(x, y), std::max(x, y)}];
    }
    first += static_cast<std::size_t>(k);
  }
  std::map<int, int> sharp_edges;
  std::set<int> on_boundary, sharp_vertex;
  for (const auto& [e, n] : faces_at_edge)
    if (n != 2) on_boundary.insert(e.first), on_boundary.insert(e.second);
  for (const auto& e : c.features.ours.edges)
    if (e.sharpness >= 10) ++sharp_edges[e.a], ++sharp_edges[e.b];
  for (const auto& v : c.features.ours.vertices)
    if (v.sharpness >= 10) sharp_vertex.insert(v.vertex);
  std::set<int> out;
  for (const auto& [v, n] : sharp_edges)
    if (n == 1 && !on_boundary.count(v) && !sharp_vertex.count(v)) out.insert(v);
  return out;
}

// Limitations the docs state (docs/runtime.md): refusals that name them are not failures.
bool documented_refusal(const std::string& message) {
  for (const char* known : {"valence", "faces at", "not covered", "regenerate", "no surface", "infinitely sharp under boundary interpolation `none`", "smooth triangle rule"})
    if (message.find(known) != std::string::npos) return true;
  return false;
}

struct Tally {
  int compared = 0, refused = 0;
  double worst_position = 0, worst_derivative = 0;
  std::map<std::string, int> reasons;
};

// A refusal counted by its kind (its first words, numbers blanked); "" when
// it names a documented limitation, else what it said.
std::string refused(const Error& e, Tally& tally) {
  ++tally.refused;
  const std::string reason = e.what();
  std::string kind = reason.substr(0, 60);
  for (char& ch : kind)
    if (ch >= '0' && ch <= '9') ch = '#';
  ++tally.reasons[kind];
  return documented_refusal(reason) ? "" : "refused: " + reason;
}

// The case's topology, or null with `why` (refused()) when the runtime refuses it.
std::shared_ptr<const SurfaceTopology> case_topology(const std::shared_ptr<const Tables>& tables, const Case& c, Tally& tally,
                                                     std::string& why) {
  try {
    return SurfaceTopology::create(tables, c.mesh.vertex_count(), c.mesh.face_sizes, c.mesh.face_vertices, c.holes, c.features.ours);
  } catch (const Error& e) {
    why = refused(e, tally);
    return nullptr;
  }
}

// A tessellation at random rates: every point finite and used, no directed
// edge twice (consistently oriented, nothing overlapping), and the edges with
// no reverse (the rims along boundaries and holes) closed loops. Closest
// points to random queries: on the surface at the parameters returned, and no
// farther than the surface's nodes at rate 4. "" when all holds.
std::string tessellation_and_distances(const Surface& surface, const Case& c, double size) {
  std::mt19937 rng(static_cast<unsigned>(c.mesh.face_count() * 7919 + c.mesh.vertex_count()));
  const auto& rates = surface.topology().tables().rates();
  std::vector<int> chosen(c.mesh.face_count());
  for (int& r : chosen) r = rates[rng() % rates.size()];
  const PolygonSoup soup = tessellate(surface, chosen);
  std::map<std::pair<int, int>, int> directed;
  std::vector<int> balance(soup.positions.size(), 0);
  std::vector<char> used(soup.positions.size(), 0);
  auto polygon = [&](const int* v, int k) {
    for (int i = 0; i < k; ++i) {
      used[static_cast<std::size_t>(v[i])] = 1;
      ++directed[{v[i], v[(i + 1) % k]}];
    }
  };
  for (const auto& q : soup.quads) polygon(q.data(), 4);
  for (const auto& t : soup.triangles) polygon(t.data(), 3);
  for (const auto& [e, n] : directed) {
    if (n != 1) return "tessellation: edge " + std::to_string(e.first) + "->" + std::to_string(e.second) + " occurs " + std::to_string(n) + " times";
    if (!directed.count({e.second, e.first})) ++balance[static_cast<std::size_t>(e.first)], --balance[static_cast<std::size_t>(e.second)];
  }
  for (std::size_t p = 0; p < soup.positions.size(); ++p) {
    if (!used[p]) return "tessellation: point " + std::to_string(p) + " unused";
    if (balance[p] != 0) return "tessellation: the rim is not closed at point " + std::to_string(p);
    for (float x : soup.positions[p])
      if (!std::isfinite(x)) return "tessellation: point " + std::to_string(p) + " is not finite";
  }
  std::vector<Point> nodes = surface_nodes(surface, c.mesh, 4);
  // A mesh of N-gons only (Catmull-Clark's polygon step): the tessellation's
  // points stand in for the nodes, rounded to float.
  const double slack = nodes.empty() ? 1e-6 * size : 1e-9 * size;
  if (nodes.empty())
    for (const auto& p : soup.positions) nodes.push_back({p[0], p[1], p[2]});
  if (nodes.empty()) return "";
  ClosestPointOptions options;
  options.tolerance = 1e-10 * size;
  options.threads = 1;
  const ClosestPointQuery query(surface, options);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  for (int k = 0; k < 6; ++k) {
    const Point& near = nodes[rng() % nodes.size()];
    const Point q{near[0] + u(rng) * size, near[1] + u(rng) * size, near[2] + u(rng) * size};
    if (const std::string defect = closest_point_defect(surface, q, query.find(q), nodes, size, slack); !defect.empty()) return defect;
  }
  return "";
}

// Compares one case against Bfr; returns a description of the first mismatch, or "".
std::string compare(const std::shared_ptr<const Tables>& tables, bool loop, const Case& c, Tally& tally) {
  std::string why;
  const auto topology = case_topology(tables, c, tally, why);
  if (!topology) return why;
  const Surface surface(topology, c.mesh.positions);
  std::unique_ptr<bfr_reference::BfrLimit> reference;
  try {
    reference = std::make_unique<bfr_reference::BfrLimit>(
        c.mesh.positions, c.mesh.face_sizes, c.mesh.face_vertices,
        loop ? bfr_reference::osd::Sdc::SCHEME_LOOP : bfr_reference::osd::Sdc::SCHEME_CATMARK, c.holes, c.features.osd);
  } catch (const std::exception&) {
    return "";  // OpenSubdiv refused it too: nothing to compare
  }
  ++tally.compared;
  const double size = extent(c.mesh);
  const std::set<int> darts = bfr_dart_vertices(c);
  std::size_t first = 0;
  const int sides = loop ? 3 : 4;
  for (std::size_t face = 0; face < c.mesh.face_count(); first += static_cast<std::size_t>(c.mesh.face_sizes[face]), ++face) {
    if (c.mesh.face_sizes[face] != sides) continue;
    const bool ours_has = !topology->is_hole(face);
    if (ours_has != reference->has_surface(static_cast<int>(face)))
      return "face " + std::to_string(face) + ": surface " + (ours_has ? "here but not in Bfr" : "in Bfr but not here");
    if (!ours_has) continue;
    auto corner_vertex = [&](long i, long j, long n) -> int {
      if (loop) {
        if (i == 0 && j == 0) return c.mesh.face_vertices[first];
        if (i == n && j == 0) return c.mesh.face_vertices[first + 1];
        if (i == 0 && j == n) return c.mesh.face_vertices[first + 2];
        return -1;
      }
      if ((i != 0 && i != n) || (j != 0 && j != n)) return -1;
      const int k = i == 0 ? (j == 0 ? 0 : 3) : (j == 0 ? 1 : 2);
      return c.mesh.face_vertices[first + static_cast<std::size_t>(k)];
    };
    for (long n : {1L, 2L, 3L, 5L})
      for (long j = 0; j <= n; ++j)
        for (long i = 0; i + (loop ? j : 0) <= n; ++i) {
          const int vertex = corner_vertex(i, j, n);
          if (vertex >= 0 && darts.count(vertex)) continue;
          const double u = static_cast<double>(i) / static_cast<double>(n), v = static_cast<double>(j) / static_cast<double>(n);
          const Point ours = surface.evaluate(face, grid(i, j, n));
          const auto ref = reference->derivatives(static_cast<int>(face), u, v);
          const double d = distance(ours, ref[0]) / size;
          tally.worst_position = std::max(tally.worst_position, d);
          std::ostringstream where;
          where << "face " << face << " at (" << i << "/" << n << ", " << j << "/" << n << ")";
          if (!(d < 1e-10)) return where.str() + ": position " + std::to_string(d) + " of the size from Bfr's";
          if (vertex >= 0) continue;  // a vertex's parametric derivatives: Bfr's are not defined at an EV
          const Derivatives dd = surface.derivatives(face, grid(i, j, n));
          const double e = std::max(distance(dd.du, ref[1]), distance(dd.dv, ref[2])) / size;
          tally.worst_derivative = std::max(tally.worst_derivative, e);
          if (!(e < 1e-8)) return where.str() + ": derivative " + std::to_string(e) + " of the size from Bfr's";
        }
  }
  return tessellation_and_distances(surface, c, size);
}

// nonpoly has no reference to compare with: the surface is the same from both
// faces at every node of every edge two quads share (rates 1..5), and its
// tessellations and closest points hold as above. "" when all holds.
std::string nonpoly_checks(const std::shared_ptr<const Tables>& tables, const Case& c, Tally& tally) {
  std::string why;
  const auto topology = case_topology(tables, c, tally, why);
  if (!topology) return why;
  ++tally.compared;
  const Surface surface(topology, c.mesh.positions);
  const double size = extent(c.mesh);
  // Quad corner c's edge c -> c+1 at fraction t from corner c.
  auto on_edge = [](int corner, long t, long n) -> std::pair<long, long> {
    switch (corner) {
      case 0: return {t, 0};
      case 1: return {n, t};
      case 2: return {n - t, n};
      default: return {0, n - t};
    }
  };
  std::map<std::pair<int, int>, std::pair<std::size_t, int>> half_edges;  // (a, b) -> face, corner
  std::size_t first = 0;
  for (std::size_t f = 0; f < c.mesh.face_count(); first += static_cast<std::size_t>(c.mesh.face_sizes[f]), ++f) {
    if (c.mesh.face_sizes[f] != 4 || topology->is_hole(f)) continue;
    for (int k = 0; k < 4; ++k)
      half_edges[{c.mesh.face_vertices[first + static_cast<std::size_t>(k)], c.mesh.face_vertices[first + static_cast<std::size_t>((k + 1) % 4)]}] = {f, k};
  }
  for (const auto& [edge, here] : half_edges) {
    const auto there = half_edges.find({edge.second, edge.first});
    if (there == half_edges.end() || edge.first > edge.second) continue;
    for (long n = 1; n <= 5; ++n)
      for (long t = 0; t <= n; ++t) {
        const auto [i, j] = on_edge(here.second, t, n);
        const auto [k, l] = on_edge(there->second.second, n - t, n);
        const double d = distance(surface.evaluate(here.first, grid(i, j, n)), surface.evaluate(there->second.first, grid(k, l, n))) / size;
        tally.worst_position = std::max(tally.worst_position, d);
        if (!(d < 1e-12))
          return "faces " + std::to_string(here.first) + " and " + std::to_string(there->second.first) + " differ by " + std::to_string(d) +
                 " of the size on their edge " + std::to_string(edge.first) + "-" + std::to_string(edge.second);
      }
  }
  return tessellation_and_distances(surface, c, size);
}

int environment(const char* name, int fallback) {
  const char* s = std::getenv(name);
  return s ? std::atoi(s) : fallback;
}

void run(bool loop, int meshes, unsigned seed) {
  const auto tables = Tables::load(loop ? generated_table("loop", "--valence 3-8 --n 1-5", "sgt").string()
                                        : generated_table("catmull-clark", "--valence 3-8 --n 5", "sgs").string());
  std::mt19937 rng(seed);
  Tally tally;
  for (int k = 0; k < meshes; ++k) {
    const Case c = random_case(loop, rng);
    INFO("case " << k << " (seed " << seed << "): " << c.what);
    const std::string mismatch = compare(tables, loop, c, tally);
    CHECK(mismatch == "");
  }
  std::ostringstream summary;
  summary << (loop ? "Loop" : "Catmull-Clark") << ": " << meshes << " random meshes, " << tally.compared << " compared with Bfr, "
          << tally.refused << " refused; worst position " << tally.worst_position << ", derivative " << tally.worst_derivative
          << " of the size";
  for (const auto& [reason, n] : tally.reasons) summary << "\n  " << n << " x " << reason;
  WARN(summary.str());
  CHECK(tally.compared > meshes / 2);
}

}  // namespace

TEST_CASE("random meshes, boundaries, holes and sharp features equal Bfr (Catmull-Clark)",
          "[runtime][random][opensubdiv]") {
  run(false, 30, 20261128u);
}

TEST_CASE("random meshes, boundaries, holes and sharp features equal Bfr (Loop)",
          "[runtime][random][opensubdiv][loop]") {
  run(true, 30, 20261128u);
}

void run_nonpoly(int meshes, unsigned seed) {
  const auto tables = Tables::load(generated_table("nonpoly", "--valence 3-8 --n 5", "sgs").string());
  std::mt19937 rng(seed);
  Tally tally;
  for (int k = 0; k < meshes; ++k) {
    const Case c = random_case(false, rng);
    INFO("case " << k << " (seed " << seed << "): " << c.what);
    CHECK(nonpoly_checks(tables, c, tally) == "");
  }
  std::ostringstream summary;
  summary << "nonpoly: " << meshes << " random meshes, " << tally.compared << " checked, " << tally.refused
          << " refused; worst difference across an edge " << tally.worst_position << " of the size";
  for (const auto& [reason, n] : tally.reasons) summary << "\n  " << n << " x " << reason;
  WARN(summary.str());
  CHECK(tally.compared > meshes / 2);
}

TEST_CASE("random meshes, boundaries, holes and sharp features: nonpoly is continuous, tessellates and finds closest points",
          "[runtime][random]") {
  run_nonpoly(20, 20261128u);
}

TEST_CASE("a sharp edge between two darts, or a dart and a corner, equals Bfr",
          "[runtime][random][opensubdiv][creases]") {
  // Found by the random meshes: with no vertex on two sharp edges the cut
  // leaves both ends inside the mesh, where they were taken for regular
  // vertices (Catmull-Clark) or refused (Loop, a corner).
  for (bool loop : {false, true}) {
    const auto tables = Tables::load(loop ? generated_table("loop", "--valence 3-8 --n 1-5", "sgt").string()
                                          : generated_table("catmull-clark", "--valence 3-8 --n 5", "sgs").string());
    std::mt19937 rng(3);
    for (int corner = 0; corner < 2; ++corner)
      for (bool closed : {false, true}) {
        Case c;
        c.mesh = loop ? (closed ? loop_meshes::triangle_torus(6, 5) : triangle_grid(4, 5, rng))
                      : (closed ? quad_torus(6, 5) : test_meshes::open_grid(4, 5));
        const int a = closed ? 13 : 11, b = closed ? 19 : 16;  // inside, one row apart
        c.features.crease(a, b, 10);
        if (corner) c.features.corner(a, 10);
        INFO((loop ? "Loop" : "Catmull-Clark") << (closed ? " torus" : " grid") << (corner ? ", a corner and a dart" : ", two darts"));
        Tally t;
        CHECK(compare(tables, loop, c, t) == "");
        CHECK(t.compared == 1);
      }
  }
}

TEST_CASE("vertices in no face and non-manifold vertices (fans meeting at a point) equal Bfr", "[runtime][random][opensubdiv]") {
  // OpenSubdiv ignores the first and makes the second an infinitely sharp
  // corner of every fan; the runtime subdivides a copy per fan (mesh/manifold_input.hpp).
  for (bool loop : {false, true}) {
    const auto tables = Tables::load(loop ? generated_table("loop", "--valence 3-8 --n 1-5", "sgt").string()
                                          : generated_table("catmull-clark", "--valence 3-8 --n 5", "sgs").string());
    std::mt19937 rng(5);
    Mesh sheet = loop ? triangle_grid(4, 4, rng) : test_meshes::open_grid(4, 4);
    const int centre = 12;  // (2, 2)
    // Two opposite quadrants of the sheet round its centre: a bowtie, the centre in two fans.
    Mesh bowtie;
    bowtie.positions = sheet.positions;
    std::size_t first = 0;
    for (std::size_t f = 0; f < sheet.face_count(); first += static_cast<std::size_t>(sheet.face_sizes[f]), ++f) {
      double x = 0, y = 0;
      for (int c = 0; c < sheet.face_sizes[f]; ++c) {
        const auto& p = sheet.positions[static_cast<std::size_t>(sheet.face_vertices[first + static_cast<std::size_t>(c)])];
        x += p[0] / sheet.face_sizes[f], y += p[1] / sheet.face_sizes[f];
      }
      const double cx = sheet.positions[centre][0], cy = sheet.positions[centre][1];
      if ((x - cx) * (y - cy) < 0) continue;  // the other two quadrants
      bowtie.face_sizes.push_back(sheet.face_sizes[f]);
      for (int c = 0; c < sheet.face_sizes[f]; ++c) bowtie.face_vertices.push_back(sheet.face_vertices[first + static_cast<std::size_t>(c)]);
    }
    // The bowtie again with two vertices in no face in front (every index moved by 2).
    Mesh spare = bowtie;
    spare.positions.insert(spare.positions.begin(), {{9, 9, 9}, {-9, 4, 1}});
    for (int& v : spare.face_vertices) v += 2;
    for (const BoundaryInterpolation option : {BoundaryInterpolation::EdgeOnly, BoundaryInterpolation::EdgeAndCorner})
      for (const Mesh* m : {&bowtie, &spare}) {
        Case c;
        c.mesh = *m;
        c.features.boundary(option);
        if (m == &spare) c.features.crease(centre + 2, centre + 3, 2.5);  // a tag on one fan's edge, moved with it
        INFO((loop ? "Loop" : "Catmull-Clark") << (m == &bowtie ? " bowtie" : " bowtie with two spare vertices"));
        Tally t;
        CHECK(compare(tables, loop, c, t) == "");
        CHECK(t.compared == 1);
        // The vertex shared by the fans is their corner: the surface passes through it.
        const Surface surface(SurfaceTopology::create(tables, c.mesh.vertex_count(), c.mesh.face_sizes, c.mesh.face_vertices, {},
                                                      c.features.ours),
                              c.mesh.positions);
        const int shared = m == &spare ? centre + 2 : centre;
        int seen = 0;
        for (std::size_t f = 0, first = 0; f < c.mesh.face_count(); first += static_cast<std::size_t>(c.mesh.face_sizes[f]), ++f)
          for (int k = 0; k < c.mesh.face_sizes[f]; ++k)
            if (c.mesh.face_vertices[first + static_cast<std::size_t>(k)] == shared) {
              const long i = loop ? (k == 1) : (k == 1 || k == 2), j = loop ? (k == 2) : (k == 2 || k == 3);
              CHECK(distance(surface.evaluate(f, grid(i, j, 1)), c.mesh.positions[static_cast<std::size_t>(shared)]) < 1e-14);
              ++seen;
            }
        CHECK(seen >= 2);
      }
  }
  // Messages name the vertices as the caller numbers them, not the copies.
  const auto few = Tables::load(generated_table("catmull-clark", "--valence 4 --n 2", "sgs").string());
  Mesh cube = test_meshes::bundled("cube");
  cube.positions.insert(cube.positions.begin(), {0, 0, 9});
  for (int& v : cube.face_vertices) v += 1;
  try {
    SurfaceTopology::create(few, cube.vertex_count(), cube.face_sizes, cube.face_vertices);
    FAIL("valence 3 is not in the tables");
  } catch (const MeshError& e) {
    const std::string message = e.what();
    INFO(message);
    CHECK(message.find("vertex 1 ") != std::string::npos);  // the cube's first vertex, 0 inside
    CHECK(message.find("vertex 0 ") == std::string::npos);
  }
}

// Three sheets of `columns` x 3 quads meeting along one chain of `columns`
// edges (every chain edge in three faces, the chain's inner vertices on a
// non-manifold crease); `triangles`: each quad split in two.
Mesh fins(int columns, bool triangles) {
  Mesh m;
  for (int i = 0; i <= columns; ++i) m.positions.push_back({double(i), 0.1 * (i % 2), 0});
  const double directions[3][3] = {{0, 1, 0.1}, {0.1, -0.6, 0.8}, {-0.2, -0.7, -0.7}};
  for (int sheet = 0; sheet < 3; ++sheet) {
    const int first = static_cast<int>(m.positions.size());
    for (int j = 1; j <= 3; ++j)
      for (int i = 0; i <= columns; ++i) {
        const double* d = directions[sheet];
        m.positions.push_back({i + 0.1 * j * d[0], j * d[1] + 0.05 * (i % 3), j * d[2] + 0.03 * ((i + j) % 2)});
      }
    auto at = [&](int i, int j) { return j == 0 ? i : first + (j - 1) * (columns + 1) + i; };
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < columns; ++i) {
        const int q[4] = {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};
        if (triangles) {
          m.face_sizes.insert(m.face_sizes.end(), {3, 3});
          m.face_vertices.insert(m.face_vertices.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
        } else {
          m.face_sizes.push_back(4);
          m.face_vertices.insert(m.face_vertices.end(), q, q + 4);
        }
      }
  }
  return m;
}

TEST_CASE("non-manifold edges (fins, a book, a flipped face) equal Bfr", "[runtime][random][opensubdiv]") {
  // OpenSubdiv makes such edges infinitely sharp and their vertices corners,
  // except on a non-manifold crease (mesh/manifold_input.hpp).
  for (bool loop : {false, true}) {
    const auto tables = Tables::load(loop ? generated_table("loop", "--valence 3-8 --n 1-5", "sgt").string()
                                          : generated_table("catmull-clark", "--valence 3-8 --n 5", "sgs").string());
    std::mt19937 rng(9);
    const Mesh book = fins(1, loop);
    const Mesh grid = loop ? triangle_grid(5, 5, rng) : test_meshes::open_grid(5, 5);
    const Mesh torus = loop ? loop_meshes::triangle_torus(6, 5) : quad_torus(6, 5);
    const std::vector<std::pair<std::string, Mesh>> meshes = {
        {"fins", fins(4, loop)}, {"book", book}, {"grid with a flipped face", flipped(grid, loop ? 24 : 12)},
        {"torus with a flipped face", flipped(torus, 7)}};
    for (const auto& [name, mesh] : meshes)
      for (const BoundaryInterpolation option :
           {BoundaryInterpolation::EdgeOnly, BoundaryInterpolation::EdgeAndCorner, BoundaryInterpolation::None}) {
        if (name == "book" && option == BoundaryInterpolation::None) continue;  // every face at the boundary: no surface
        Case c;
        c.mesh = mesh;
        c.features.boundary(option);
        if (name == "fins") c.features.crease(8, 9, 2.5);  // a semi-sharp edge on one sheet, next to the chain
        INFO((loop ? "Loop " : "Catmull-Clark ") << name << ", boundary option " << static_cast<int>(option));
        Tally t;
        CHECK(compare(tables, loop, c, t) == "");
        std::string refusals;
        for (const auto& [why, count] : t.reasons) refusals += why + "; ";
        INFO("refused: " << refusals);
        CHECK(t.compared == 1);
      }
  }
  // A fin of one quad on two edges of a grid: the grid's middle vertex is on
  // a non-manifold crease, and the fin's piece there is one face. Edge-only:
  // every piece follows the crease, as in OpenSubdiv. Edge-and-corner would
  // make that piece's copy a corner, and a further sharp edge at the vertex
  // would change OpenSubdiv's one rule there for every piece: refused, named.
  {
    const auto tables = Tables::load(generated_table("catmull-clark", "--valence 3-8 --n 5", "sgs").string());
    Mesh fin = test_meshes::open_grid(4, 4);
    fin.positions.push_back({2.0, 2.2, 0.8});
    fin.face_sizes.push_back(4);
    fin.face_vertices.insert(fin.face_vertices.end(), {11, 12, 13, 25});
    Case c;
    c.mesh = fin;
    Tally t;
    CHECK(compare(tables, false, c, t) == "");
    CHECK(t.compared == 1);
    for (int variant = 0; variant < 2; ++variant) {
      MeshFeatures features;
      if (variant == 0) features.boundary = BoundaryInterpolation::EdgeAndCorner;
      else features.edges.push_back({12, 17, 2.0f});
      INFO("variant " << variant);
      CHECK_THROWS_WITH(SurfaceTopology::create(tables, fin.vertex_count(), fin.face_sizes, fin.face_vertices, {}, features),
                        Catch::Contains("vertex 12 is on a non-manifold crease") &&
                            Catch::Contains(variant == 0 ? "a piece of one face" : "a further sharp edge (12, 17)"));
    }
  }
  // The chain's inner vertices follow the crease curve through the chain's
  // points (not corners): the limit there is (1/6, 2/3, 1/6) of the chain.
  const auto tables = Tables::load(generated_table("catmull-clark", "--valence 3-8 --n 5", "sgs").string());
  const Mesh m = fins(4, false);
  const Surface surface(SurfaceTopology::create(tables, m.vertex_count(), m.face_sizes, m.face_vertices), m.positions);
  for (int sheet = 0; sheet < 3; ++sheet) {
    const std::size_t face = static_cast<std::size_t>(sheet) * 12 + 1;  // chain edge (1, 2), corner 0 at vertex 1
    Point expected{};
    for (int k = 0; k < 3; ++k) expected[static_cast<std::size_t>(k)] = (m.positions[0][k] + 4 * m.positions[1][k] + m.positions[2][k]) / 6;
    CHECK(distance(surface.evaluate(face, grid(0, 0, 1)), expected) < 1e-14);
  }
}

TEST_CASE("soak: many random meshes against Bfr, both schemes", "[.soak]") {
  const int meshes = environment("STENCIL_SOAK_MESHES", 400);
  const unsigned seed = static_cast<unsigned>(environment("STENCIL_SOAK_SEED", 1));
  run(false, meshes, seed);
  run(true, meshes, seed);
  run_nonpoly(meshes, seed);
}


