#pragma once
// Compact topology of a manifold mesh whose faces all have K corners (K = 4:
// quads, K = 3: triangles), closed or, where the caller allows it, with
// boundaries: for each face corner (a half-edge from corner c to corner c+1),
// the opposite half-edge in the neighbouring face (kNoTwin on a boundary), and
// each vertex's valence (its number of faces). Half-edge h = K * face + corner.
#include <cstdint>
#include <vector>

#include "connectivity.hpp"
#include "polygon_links.hpp"
#include "stencil_runtime/error.hpp"

namespace stencil_runtime {

template <int K>
class UniformTopology {
 public:
  static constexpr std::uint32_t kNoTwin = UINT32_MAX;
  // Throws MeshError naming the face, edge or vertex when the mesh is not a
  // manifold made of K-gons, closed unless `boundaries` (see link_polygons).
  explicit UniformTopology(const Connectivity& mesh, bool boundaries = false);
  // The same from the mesh's half-edges, already linked.
  UniformTopology(const Connectivity& mesh, const PolygonLinks& links);

  bool has_boundary() const { return has_boundary_; }
  bool on_boundary(int vertex) const { return has_boundary_ && boundary_[static_cast<std::size_t>(vertex)] != 0; }

  std::size_t faces() const { return vertex_of_.size() / K; }
  std::size_t vertices() const { return valence_.size(); }
  // Vertex at corner c of face f (corners taken mod K, c >= -K).
  int vertex(std::size_t f, int c) const { return vertex_of_[K * f + static_cast<std::size_t>((c + K) % K)]; }
  int valence(int vertex) const { return valence_[static_cast<std::size_t>(vertex)]; }
  // The half-edge opposite h (same edge, other face, reversed); kNoTwin on a boundary.
  std::uint32_t twin(std::uint32_t h) const { return twin_[h]; }
  static std::uint32_t face_of(std::uint32_t h) { return h / K; }
  static int corner_of(std::uint32_t h) { return static_cast<int>(h % K); }
  static std::uint32_t half_edge(std::size_t f, int c) {
    return static_cast<std::uint32_t>(K * f + static_cast<std::size_t>((c + K) % K));
  }
  // The vertex half-edge h points to (its face's next corner).
  int head(std::uint32_t h) const { return vertex(face_of(h), corner_of(h) + 1); }
  // Whether a corner of face f is on the boundary.
  bool touches_boundary(std::size_t f) const {
    for (int c = 0; c < K && has_boundary_; ++c)
      if (on_boundary(vertex(f, c))) return true;
    return false;
  }
  // Whether a corner of face f is a vertex marked in `marked` (one flag per vertex; empty: none is).
  bool touches_marked(std::size_t f, const std::vector<char>& marked) const {
    for (int c = 0; c < K && !marked.empty(); ++c)
      if (marked[static_cast<std::size_t>(vertex(f, c))]) return true;
    return false;
  }
  // The next half-edge leaving the same vertex, counter-clockwise (faces are
  // counter-clockwise seen from outside); kNoTwin past a boundary vertex's last face.
  std::uint32_t turn_ccw(std::uint32_t h) const { return twin_[half_edge(face_of(h), corner_of(h) + K - 1)]; }
  // Corner of face f holding vertex v, or -1.
  int corner_of_vertex(std::size_t f, int v) const;

 private:
  std::vector<int> vertex_of_;
  std::vector<std::uint32_t> twin_;
  std::vector<int> valence_;
  std::vector<char> boundary_;
  bool has_boundary_ = false;
};

using QuadTopology = UniformTopology<4>;
using TriangleTopology = UniformTopology<3>;

extern template class UniformTopology<3>;
extern template class UniformTopology<4>;

}  // namespace stencil_runtime
