#include <CGAL/Advancing_front_surface_reconstruction.h>

#include <array>

#include "advancing_front.hpp"

namespace stencil_reconstruction {

TriangleMesh advancing_front(const std::vector<CgalPoint>& points) {
  std::vector<std::array<std::size_t, 3>> facets;
  CGAL::advancing_front_surface_reconstruction(points.begin(), points.end(), std::back_inserter(facets));
  TriangleMesh mesh;
  std::vector<TriangleMesh::Vertex_index> vertices;
  vertices.reserve(points.size());
  for (const CgalPoint& p : points) vertices.push_back(mesh.add_vertex(p));
  for (const auto& f : facets)
    mesh.add_face(vertices[f[0]], vertices[f[1]], vertices[f[2]]);  // a face that would break the manifold is skipped
  return mesh;
}

}  // namespace stencil_reconstruction
