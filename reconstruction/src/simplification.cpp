#include "simplification.hpp"

#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

namespace stencil_reconstruction {

namespace SMS = CGAL::Surface_mesh_simplification;

void simplify_to_vertices(TriangleMesh& mesh, std::size_t vertices) {
  // A closed triangle surface has E = 3 (V - chi) edges, chi = V - E + F its
  // Euler characteristic, which collapses keep.
  const long chi = static_cast<long>(mesh.number_of_vertices()) - static_cast<long>(mesh.number_of_edges()) +
                   static_cast<long>(mesh.number_of_faces());
  const long edges = 3 * (static_cast<long>(vertices) - chi);
  if (edges <= 0 || static_cast<std::size_t>(edges) >= mesh.number_of_edges()) return;
  // The predicate stops once fewer edges than its count are left: one more
  // than E, so that collapses (3 edges each) stop at E itself, not at E - 3.
  SMS::Count_stop_predicate<TriangleMesh> stop(static_cast<std::size_t>(edges) + 1);
  SMS::edge_collapse(mesh, stop);
  mesh.collect_garbage();
}

}  // namespace stencil_reconstruction
