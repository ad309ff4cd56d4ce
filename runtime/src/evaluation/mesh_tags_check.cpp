// SurfaceTopology::create from a Mesh: its OBJ tags are checked first, so that
// a tag the runtime cannot honour is an error instead of a silently smooth
// surface (issue 17 adds creases, corners and holes).
#include <algorithm>
#include <sstream>
#include <string>

#include "stencil_runtime/surface_topology.hpp"

namespace stencil_runtime {

namespace {

std::string number(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

[[noreturn]] void refuse(const Mesh& mesh, long line, const std::string& what) {
  const std::string where = mesh.source.empty() ? "tag" : mesh.source + ":" + std::to_string(line);
  throw MeshError(where + ": " + what +
                  " is not supported yet: the runtime evaluates smooth closed meshes only; remove the tag to evaluate "
                  "the smooth surface");
}

}  // namespace

std::shared_ptr<const SurfaceTopology> SurfaceTopology::create(std::shared_ptr<const Tables> tables, const Mesh& mesh) {
  if (!tables) throw EvaluationError("SurfaceTopology::create needs tables");
  const MeshTags& tags = mesh.tags;
  for (const auto& c : tags.creases)
    if (c.sharpness > 0)
      refuse(mesh, c.line, "a crease of sharpness " + number(c.sharpness) + " on the edge " + std::to_string(c.a) + "-" +
                               std::to_string(c.b));
  for (const auto& c : tags.corners)
    if (c.sharpness > 0)
      refuse(mesh, c.line, "a corner of sharpness " + number(c.sharpness) + " at vertex " + std::to_string(c.vertex));
  if (tags.smooth_triangles && tables->family() == SchemeFamily::Quad &&
      std::find(mesh.face_sizes.begin(), mesh.face_sizes.end(), 3) != mesh.face_sizes.end())
    refuse(mesh, tags.smooth_triangles_line, "OpenSubdiv's smooth triangle rule (`smoothtriangles`)");
  std::vector<int> holes;
  for (const auto& h : tags.holes) holes.push_back(h.face);
  return create(std::move(tables), mesh.vertex_count(), mesh.face_sizes, mesh.face_vertices, holes);
}

}  // namespace stencil_runtime
