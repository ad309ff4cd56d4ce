#include "surface_repair.hpp"

#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

#include <iterator>
#include <string>
#include <vector>

#include "stencil_reconstruction/initial_mesh.hpp"

namespace stencil_reconstruction {

namespace PMP = CGAL::Polygon_mesh_processing;

RepairCounts close_surface(TriangleMesh& mesh) {
  RepairCounts counts;
  if (mesh.number_of_faces() == 0) throw ReconstructionError("the reconstruction produced no faces");
  counts.components_dropped = PMP::keep_largest_connected_components(mesh, 1);
  // One border halfedge per hole, then each hole triangulated.
  std::vector<TriangleMesh::Halfedge_index> borders;
  PMP::extract_boundary_cycles(mesh, std::back_inserter(borders));
  for (const auto h : borders) {
    if (!mesh.is_border(h)) continue;  // an earlier filling closed it
    std::vector<TriangleMesh::Face_index> faces;
    std::vector<TriangleMesh::Vertex_index> vertices;
    PMP::triangulate_and_refine_hole(mesh, h, std::back_inserter(faces), std::back_inserter(vertices));
    ++counts.holes_filled;
  }
  mesh.collect_garbage();
  for (const auto v : mesh.vertices())
    if (mesh.is_isolated(v)) mesh.remove_vertex(v);
  mesh.collect_garbage();
  if (!CGAL::is_closed(mesh))
    throw ReconstructionError("the reconstructed surface has holes that could not be filled");
  if (!PMP::is_outward_oriented(mesh)) PMP::reverse_face_orientations(mesh);
  return counts;
}

}  // namespace stencil_reconstruction
