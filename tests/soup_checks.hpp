#pragma once
// Independent topology checks for tessellations: directed-edge counts of a
// polygon soup and the Euler characteristic of a control mesh.
#include <map>
#include <set>
#include <utility>

#include "stencil_runtime/mesh.hpp"

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
