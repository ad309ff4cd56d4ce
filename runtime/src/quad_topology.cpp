#include "stencil_runtime/quad_topology.hpp"

#include <algorithm>
#include <string>

#include "stencil_runtime/polygon_links.hpp"

namespace stencil_runtime {

QuadTopology::QuadTopology(const Mesh& mesh) {
  const std::size_t nf = mesh.face_count();
  vertex_of_.reserve(4 * nf);
  std::size_t offset = 0;
  for (std::size_t f = 0; f < nf; ++f) {
    const int size = mesh.face_sizes[f];
    if (size != 4)
      throw MeshError("face " + std::to_string(f) + " has " + std::to_string(size) +
                      " vertices; quad schemes need a mesh of quads");
    for (int c = 0; c < 4; ++c) {
      const int v = mesh.face_vertices[offset + static_cast<std::size_t>(c)];
      if (v < 0 || static_cast<std::size_t>(v) >= mesh.vertex_count())
        throw MeshError("face " + std::to_string(f) + " refers to vertex " + std::to_string(v) + ", which does not exist");
      vertex_of_.push_back(v);
    }
    offset += 4;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        if (vertex_of_[4 * f + a] == vertex_of_[4 * f + b])
          throw MeshError("face " + std::to_string(f) + " uses vertex " + std::to_string(vertex_of_[4 * f + a]) + " twice");
  }
  const PolygonLinks links = link_polygons(mesh);  // pairs the half-edges, counts valences
  twin_.assign(links.twin.begin(), links.twin.end());
  valence_ = links.valence;
  // Each vertex must have a single fan of faces: walking around it from one
  // outgoing half-edge must visit all of them.
  std::vector<int> seen(mesh.vertex_count(), 0);
  for (std::uint32_t h = 0; h < 4 * nf; ++h) {
    const int v = vertex_of_[h];
    if (seen[static_cast<std::size_t>(v)]) continue;
    int count = 0;
    std::uint32_t e = h;
    do {
      ++count;
      // Previous corner's half-edge in this face ends at v; its twin leaves v in the next face.
      e = twin_[(e & ~3u) | ((e + 3) & 3u)];
    } while (e != h && count <= valence_[static_cast<std::size_t>(v)]);
    if (count != valence_[static_cast<std::size_t>(v)])
      throw MeshError("vertex " + std::to_string(v) + " is non-manifold (its faces form more than one fan)");
    seen[static_cast<std::size_t>(v)] = 1;
  }
}

int QuadTopology::corner_of_vertex(std::size_t f, int v) const {
  for (int c = 0; c < 4; ++c)
    if (vertex_of_[4 * f + static_cast<std::size_t>(c)] == v) return c;
  return -1;
}

}  // namespace stencil_runtime
