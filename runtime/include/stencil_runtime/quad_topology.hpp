#pragma once
// Compact topology of a closed manifold quad mesh: for each face corner (a
// half-edge from corner c to corner c+1), the opposite half-edge in the
// neighbouring face, and each vertex's valence and one outgoing half-edge.
// Half-edge h = 4 * face + corner.
#include <cstdint>
#include <vector>

#include "mesh.hpp"

namespace stencil_runtime {

class QuadTopology {
 public:
  // Throws MeshError naming the face, edge or vertex when the mesh is not a
  // closed manifold made of quads.
  explicit QuadTopology(const Mesh& mesh);

  std::size_t faces() const { return vertex_of_.size() / 4; }
  std::size_t vertices() const { return valence_.size(); }
  // Vertex at corner c of face f (corners taken mod 4).
  int vertex(std::size_t f, int c) const { return vertex_of_[4 * f + static_cast<std::size_t>(c & 3)]; }
  int valence(int vertex) const { return valence_[static_cast<std::size_t>(vertex)]; }
  // The half-edge opposite h (same edge, other face, reversed).
  std::uint32_t twin(std::uint32_t h) const { return twin_[h]; }
  static std::uint32_t face_of(std::uint32_t h) { return h >> 2; }
  static int corner_of(std::uint32_t h) { return static_cast<int>(h & 3u); }
  static std::uint32_t half_edge(std::size_t f, int c) { return static_cast<std::uint32_t>(4 * f + static_cast<std::size_t>(c & 3)); }
  // Corner of face f holding vertex v, or -1.
  int corner_of_vertex(std::size_t f, int v) const;

 private:
  std::vector<int> vertex_of_;
  std::vector<std::uint32_t> twin_;
  std::vector<int> valence_;
};

}  // namespace stencil_runtime
