#include "stencil_runtime/uniform_topology.hpp"

#include <string>

#include "stencil_runtime/polygon_links.hpp"

namespace stencil_runtime {

template <int K>
UniformTopology<K>::UniformTopology(const Mesh& mesh) {
  const std::size_t nf = mesh.face_count();
  vertex_of_.reserve(K * nf);
  std::size_t offset = 0;
  for (std::size_t f = 0; f < nf; ++f) {
    const int size = mesh.face_sizes[f];
    if (size != K)
      throw MeshError("face " + std::to_string(f) + " has " + std::to_string(size) + " vertices; " +
                      (K == 4 ? "quad schemes need a mesh of quads" : "triangle schemes need a mesh of triangles"));
    for (int c = 0; c < K; ++c) {
      const int v = mesh.face_vertices[offset + static_cast<std::size_t>(c)];
      if (v < 0 || static_cast<std::size_t>(v) >= mesh.vertex_count())
        throw MeshError("face " + std::to_string(f) + " refers to vertex " + std::to_string(v) + ", which does not exist");
      vertex_of_.push_back(v);
    }
    offset += K;
    for (int a = 0; a < K; ++a)
      for (int b = a + 1; b < K; ++b)
        if (vertex_of_[K * f + a] == vertex_of_[K * f + b])
          throw MeshError("face " + std::to_string(f) + " uses vertex " + std::to_string(vertex_of_[K * f + a]) + " twice");
  }
  const PolygonLinks links = link_polygons(mesh);  // pairs the half-edges, counts valences
  twin_.assign(links.twin.begin(), links.twin.end());
  valence_ = links.valence;
  // Each vertex must have a single fan of faces: turning around it from one
  // outgoing half-edge must visit all of them.
  std::vector<int> seen(mesh.vertex_count(), 0);
  for (std::uint32_t h = 0; h < K * nf; ++h) {
    const int v = vertex_of_[h];
    if (seen[static_cast<std::size_t>(v)]) continue;
    int count = 0;
    std::uint32_t e = h;
    do {
      ++count;
      e = turn_ccw(e);
    } while (e != h && count <= valence_[static_cast<std::size_t>(v)]);
    if (count != valence_[static_cast<std::size_t>(v)])
      throw MeshError("vertex " + std::to_string(v) + " is non-manifold (its faces form more than one fan)");
    seen[static_cast<std::size_t>(v)] = 1;
  }
}

template <int K>
int UniformTopology<K>::corner_of_vertex(std::size_t f, int v) const {
  for (int c = 0; c < K; ++c)
    if (vertex_of_[K * f + static_cast<std::size_t>(c)] == v) return c;
  return -1;
}

template class UniformTopology<3>;
template class UniformTopology<4>;

}  // namespace stencil_runtime
