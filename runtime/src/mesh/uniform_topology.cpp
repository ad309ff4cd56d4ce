#include "uniform_topology.hpp"

#include <string>

#include "polygon_links.hpp"
#include "stencil_runtime/limits.hpp"

namespace stencil_runtime {

namespace {

// The mesh, once its faces are all K-gons (checked before linking, for the clearer message).
template <int K>
const Connectivity& k_gons(const Connectivity& mesh) {
  const std::size_t nf = mesh.face_count();
  if (nf > limits::kMaxMeshElements / K)
    throw MeshError("the mesh has " + std::to_string(nf) + " faces; the runtime supports up to " +
                    std::to_string(limits::kMaxMeshElements / K));
  for (std::size_t f = 0; f < nf; ++f)
    if (mesh.face_sizes[f] != K)
      throw MeshError("face " + std::to_string(f) + " has " + std::to_string(mesh.face_sizes[f]) + " vertices; " +
                      (K == 4 ? "quad schemes need a mesh of quads here" : "triangle schemes need a mesh of triangles"));
  return mesh;
}

}  // namespace

template <int K>
UniformTopology<K>::UniformTopology(const Connectivity& mesh, bool boundaries)
    : UniformTopology(mesh, link_polygons(k_gons<K>(mesh), boundaries)) {}

template <int K>
UniformTopology<K>::UniformTopology(const Connectivity& mesh, const PolygonLinks& links) {
  k_gons<K>(mesh);
  vertex_of_ = mesh.face_vertices;
  twin_.resize(links.twin.size());
  for (std::size_t h = 0; h < twin_.size(); ++h)
    twin_[h] = links.twin[h] == PolygonLinks::kNoTwin ? kNoTwin : static_cast<std::uint32_t>(links.twin[h]);
  valence_ = links.valence;
  has_boundary_ = links.has_boundary;
  if (has_boundary_) boundary_ = links.boundary;
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
