// SurfaceTopology::create from a Mesh: its OBJ tags become the features the
// runtime honours (holes, creases and corners, infinitely sharp ones, the
// crease method, smooth triangles); a tag it cannot honour yet is an error
// naming its line or its vertex instead of a silently different surface.
#include <algorithm>
#include <string>

#include "stencil_runtime/surface_topology.hpp"
#include "tables/quad_tables.hpp"

namespace stencil_runtime {

namespace {

std::string where(const Mesh& mesh, long line) { return mesh.source.empty() ? "tag" : mesh.source + ":" + std::to_string(line); }

}  // namespace

std::shared_ptr<const SurfaceTopology> SurfaceTopology::create(std::shared_ptr<const Tables> tables, const Mesh& mesh) {
  if (!tables) throw EvaluationError("SurfaceTopology::create needs tables");
  const MeshTags& tags = mesh.tags;
  MeshFeatures features;
  features.chaikin = tags.chaikin_creases;
  features.boundary = tags.boundary;
  // Infinitely sharp features are boundaries of the cut mesh (family/sharp_cut.hpp), a sharp vertex on none of them
  // a cone point; the families refuse, naming the vertex, what they cannot evaluate yet.
  for (const auto& c : tags.creases) features.edges.push_back({c.a, c.b, c.sharpness});
  for (const auto& c : tags.corners) features.vertices.push_back({c.vertex, c.sharpness});
  // Smooth triangles change Catmull-Clark's first step only (Loop ignores the tag, as OpenSubdiv).
  const bool triangles = std::find(mesh.face_sizes.begin(), mesh.face_sizes.end(), 3) != mesh.face_sizes.end();
  if (tags.smooth_triangles && triangles && tables->family() == SchemeFamily::Quad) {
    try {
      tables->quad().check_smooth_triangles();
    } catch (const MeshError& e) {
      throw MeshError(where(mesh, tags.smooth_triangles_line) + ": " + e.what());
    }
    features.smooth_triangles = true;
  }
  std::vector<int> holes;
  for (const auto& h : tags.holes) holes.push_back(h.face);
  try {
    return create(std::move(tables), mesh.vertex_count(), mesh.face_sizes, mesh.face_vertices, holes, features);
  } catch (const MeshError& e) {  // named by its file, where it has one
    if (mesh.source.empty()) throw;
    throw MeshError(mesh.source + ": " + e.what());
  }
}

}  // namespace stencil_runtime
