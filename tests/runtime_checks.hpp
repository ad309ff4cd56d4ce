#pragma once
// Independent measures for the runtime tests: the size of a mesh, distances,
// directed-edge counts of a tessellation (soup or written mesh) and the Euler
// characteristic of a control mesh.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <numeric>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "stencil_runtime/mesh.hpp"

// Length of the diagonal of the mesh's bounding box.
inline double extent(const stencil_runtime::Mesh& m) {
  std::array<double, 3> lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (const auto& p : m.positions)
    for (int c = 0; c < 3; ++c) lo[c] = std::min(lo[c], p[c]), hi[c] = std::max(hi[c], p[c]);
  return std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) + (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

// How many faces each vertex is a corner of (its valence, on a closed manifold).
inline std::vector<int> vertex_valences(const stencil_runtime::Mesh& m) {
  std::vector<int> v(m.vertex_count(), 0);
  for (int x : m.face_vertices) ++v[static_cast<std::size_t>(x)];
  return v;
}

inline double distance(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

// How often each directed edge (a -> b) occurs in the soup's polygons. A closed,
// consistently oriented 2-manifold has every count 1 and every reverse present.
inline std::map<std::pair<int, int>, int> directed_edges(const stencil_runtime::PolygonSoup& soup) {
  std::map<std::pair<int, int>, int> directed;
  auto add = [&](const int* poly, int k) {
    for (int c = 0; c < k; ++c) ++directed[{poly[c], poly[(c + 1) % k]}];
  };
  for (const auto& q : soup.quads) add(q.data(), 4);
  for (const auto& t : soup.triangles) add(t.data(), 3);
  return directed;
}

// The same for a mesh read back from a written tessellation.
inline std::map<std::pair<int, int>, int> directed_edges(const stencil_runtime::Mesh& mesh) {
  std::map<std::pair<int, int>, int> directed;
  std::size_t off = 0;
  for (int k : mesh.face_sizes) {
    for (int c = 0; c < k; ++c)
      ++directed[{mesh.face_vertices[off + static_cast<std::size_t>(c)], mesh.face_vertices[off + static_cast<std::size_t>((c + 1) % k)]}];
    off += static_cast<std::size_t>(k);
  }
  return directed;
}

inline long euler_characteristic(const stencil_runtime::Mesh& mesh) {
  std::set<std::pair<int, int>> edges;
  std::size_t off = 0;
  for (int k : mesh.face_sizes) {
    for (int c = 0; c < k; ++c) {
      const int a = mesh.face_vertices[off + static_cast<std::size_t>(c)];
      const int b = mesh.face_vertices[off + static_cast<std::size_t>((c + 1) % k)];
      edges.insert({std::min(a, b), std::max(a, b)});
    }
    off += static_cast<std::size_t>(k);
  }
  return static_cast<long>(mesh.vertex_count()) - static_cast<long>(edges.size()) + static_cast<long>(mesh.face_count());
}

// The first defect of a tessellation as a closed, consistently oriented
// 2-manifold with Euler characteristic `chi` whose points are all used and
// distinct ("" when there is none), by an independent directed-edge count.
inline std::string tessellation_defect(const stencil_runtime::PolygonSoup& soup, long chi) {
  const auto directed = directed_edges(soup);
  std::set<int> used;
  for (const auto& [e, count] : directed) {
    const std::string edge = std::to_string(e.first) + "->" + std::to_string(e.second);
    if (count != 1) return "edge " + edge + " occurs " + std::to_string(count) + " times";
    if (!directed.count({e.second, e.first})) return "edge " + edge + " has no reverse";
    if (e.first == e.second) return "degenerate edge " + edge;
    used.insert(e.first);
  }
  if (used.size() != soup.positions.size()) return "unused points";
  const long found = static_cast<long>(soup.positions.size()) - static_cast<long>(directed.size() / 2) +
                     static_cast<long>(soup.quads.size() + soup.triangles.size());
  if (found != chi) return "Euler characteristic " + std::to_string(found) + ", expected " + std::to_string(chi);
  // Every limit point computed once: no two output vertices coincide.
  const std::set<std::array<float, 3>> distinct(soup.positions.begin(), soup.positions.end());
  if (distinct.size() != soup.positions.size()) return "repeated points";
  return "";
}

// Where tessellation point k lies on a quad mesh prepared by one isolation step
// with every prepared face at rate n: the centre (i, j) of child c of original
// face F, as F's parameter (u/(4n), v/(4n)). Children follow the runtime's
// quadrant order (child c's u axis along the parent's edge c -> c+1).
struct TessellationParameter {
  std::size_t face;
  long u, v, denominator;
};
inline TessellationParameter tessellation_parameter(std::size_t k, long n) {
  const std::size_t face = k / static_cast<std::size_t>(n * n), cell = k % static_cast<std::size_t>(n * n);
  const long i = static_cast<long>(cell % static_cast<std::size_t>(n)), j = static_cast<long>(cell / static_cast<std::size_t>(n));
  const int c = static_cast<int>(face % 4);
  // Child grid (2i+1, 2j+1) / 2n -> parent-aligned quadrant coordinates -> original face on the grid 1/(4n).
  const long a = 2 * i + 1, b = 2 * j + 1, m = 2 * n;
  long x = 0, y = 0;
  switch (c) {
    case 0: x = a, y = b; break;
    case 1: x = m - b, y = a; break;
    case 2: x = m - a, y = m - b; break;
    default: x = b, y = m - a; break;
  }
  return {face / 4, x + ((c == 1 || c == 2) ? m : 0), y + ((c >= 2) ? m : 0), 2 * m};
}

// A closed triangular prism: two triangles and three quads, every vertex of
// valence 3 (the polygon step, then isolation).
inline stencil_runtime::Mesh prism() {
  stencil_runtime::Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0.3, 0.9, 0}, {0, 0, 1.2}, {1, 0, 1.1}, {0.4, 1, 1.3}};
  m.face_sizes = {3, 3, 4, 4, 4};
  m.face_vertices = {0, 2, 1, 3, 4, 5, 0, 1, 4, 3, 1, 2, 5, 4, 2, 0, 3, 5};
  return m;
}

// Every point used; every undirected edge used once (rim) or twice in opposite
// directions; the rim edges form `loops` closed loops; V - E + F = 2 - loops
// for a genus-0 mesh (`genus` otherwise).
inline void check_rimmed_manifold(const stencil_runtime::PolygonSoup& soup, std::size_t loops, int genus) {
  std::map<std::pair<int, int>, int> directed;
  std::vector<char> used(soup.positions.size(), 0);
  std::size_t faces = 0;
  auto polygon = [&](const int* p, int k) {
    ++faces;
    for (int i = 0; i < k; ++i) {
      REQUIRE(p[i] >= 0);
      REQUIRE(static_cast<std::size_t>(p[i]) < soup.positions.size());
      used[static_cast<std::size_t>(p[i])] = 1;
      ++directed[{p[i], p[(i + 1) % k]}];
    }
  };
  for (const auto& q : soup.quads) polygon(q.data(), 4);
  for (const auto& t : soup.triangles) polygon(t.data(), 3);
  CHECK(std::all_of(used.begin(), used.end(), [](char c) { return c != 0; }));
  std::size_t edges = 0;
  std::vector<int> parent(soup.positions.size());
  std::iota(parent.begin(), parent.end(), 0);
  std::function<int(int)> find = [&](int x) { return parent[static_cast<std::size_t>(x)] == x ? x : parent[static_cast<std::size_t>(x)] = find(parent[static_cast<std::size_t>(x)]); };
  std::set<int> rim_points;
  for (const auto& [e, count] : directed) {
    INFO("directed edge " << e.first << " -> " << e.second);
    REQUIRE(count == 1);  // consistently oriented: no directed edge twice
    const bool twin = directed.count({e.second, e.first}) != 0;
    if (e.first < e.second || !twin) ++edges;
    if (!twin) {  // a rim edge
      parent[static_cast<std::size_t>(find(e.first))] = find(e.second);
      rim_points.insert(e.first);
      rim_points.insert(e.second);
    }
  }
  {  // every rim point has one rim edge in and one out
    std::map<int, int> in, out;
    for (const auto& [e, count] : directed)
      if (!directed.count({e.second, e.first})) ++out[e.first], ++in[e.second];
    for (int p : rim_points) {
      INFO("rim point " << p);
      CHECK(in[p] == 1);
      CHECK(out[p] == 1);
    }
  }
  std::set<int> roots;
  for (int p : rim_points) roots.insert(find(p));
  CHECK(roots.size() == loops);
  const long chi = static_cast<long>(soup.positions.size()) - static_cast<long>(edges) + static_cast<long>(faces);
  CHECK(chi == 2 - 2 * genus - static_cast<long>(loops));
}

