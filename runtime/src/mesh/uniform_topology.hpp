#pragma once
// Compact topology of a closed manifold mesh whose faces all have K corners
// (K = 4: quads, K = 3: triangles): for each face corner (a half-edge from
// corner c to corner c+1), the opposite half-edge in the neighbouring face, and
// each vertex's valence. Half-edge h = K * face + corner.
#include <cstdint>
#include <vector>

#include "connectivity.hpp"
#include "polygon_links.hpp"
#include "stencil_runtime/error.hpp"

namespace stencil_runtime {

template <int K>
class UniformTopology {
 public:
  // Throws MeshError naming the face, edge or vertex when the mesh is not a
  // closed manifold made of K-gons (see link_polygons).
  explicit UniformTopology(const Connectivity& mesh);
  // The same from the mesh's half-edges, already linked.
  UniformTopology(const Connectivity& mesh, const PolygonLinks& links);

  std::size_t faces() const { return vertex_of_.size() / K; }
  std::size_t vertices() const { return valence_.size(); }
  // Vertex at corner c of face f (corners taken mod K, c >= -K).
  int vertex(std::size_t f, int c) const { return vertex_of_[K * f + static_cast<std::size_t>((c + K) % K)]; }
  int valence(int vertex) const { return valence_[static_cast<std::size_t>(vertex)]; }
  // The half-edge opposite h (same edge, other face, reversed).
  std::uint32_t twin(std::uint32_t h) const { return twin_[h]; }
  static std::uint32_t face_of(std::uint32_t h) { return h / K; }
  static int corner_of(std::uint32_t h) { return static_cast<int>(h % K); }
  static std::uint32_t half_edge(std::size_t f, int c) {
    return static_cast<std::uint32_t>(K * f + static_cast<std::size_t>((c + K) % K));
  }
  // The next half-edge leaving the same vertex, counter-clockwise (faces are
  // counter-clockwise seen from outside).
  std::uint32_t turn_ccw(std::uint32_t h) const { return twin_[half_edge(face_of(h), corner_of(h) + K - 1)]; }
  // Corner of face f holding vertex v, or -1.
  int corner_of_vertex(std::size_t f, int v) const;

 private:
  std::vector<int> vertex_of_;
  std::vector<std::uint32_t> twin_;
  std::vector<int> valence_;
};

using QuadTopology = UniformTopology<4>;
using TriangleTopology = UniformTopology<3>;

extern template class UniformTopology<3>;
extern template class UniformTopology<4>;

}  // namespace stencil_runtime
