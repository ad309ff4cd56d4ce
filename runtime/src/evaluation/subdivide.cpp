#include "stencil_runtime/subdivide.hpp"

#include <algorithm>

#include "mesh/coordinates.hpp"
#include "quad/quad_creases.hpp"
#include "quad/quad_refinement.hpp"
#include "triangle/triangle_steps.hpp"

namespace stencil_runtime {

Mesh subdivide(const Tables& tables, const Mesh& mesh) {
  if (const std::string fault = coordinate_fault(mesh.positions.data(), mesh.positions.size()); !fault.empty())
    throw MeshError("cannot subdivide the mesh: " + fault);
  const Connectivity c{mesh.vertex_count(), mesh.face_sizes, mesh.face_vertices};
  Connectivity next;
  std::vector<RefinementStep> steps;
  if (tables.family() == SchemeFamily::Quad) {
    const bool quads = std::all_of(mesh.face_sizes.begin(), mesh.face_sizes.end(), [](int k) { return k == 4; });
    const PolygonLinks links = link_polygons(c, true);
    BoundaryRules boundary;  // OpenSubdiv's, with the mesh's interpolation tag
    if (links.has_boundary) {
      const CurveCreaseRule crease = quad_crease_rule(tables.quad(), tables.scheme());
      boundary = {crease.centre, crease.neighbour, mesh.tags.boundary == BoundaryInterpolation::EdgeAndCorner};
    }
    const BoundaryRules* rules = links.has_boundary ? &boundary : nullptr;
    QuadStep step = quads ? subdivide_quads(QuadTopology(c, links), tables.quad(), rules)
                          : subdivide_polygons(c, links, tables.quad(), false, rules);
    next = std::move(step.mesh);
    steps.push_back(std::move(step.step));
  } else {
    const TriangleTables& t = tables.triangle();
    const PolygonLinks links = link_polygons(c, true);
    BoundaryRules boundary;  // OpenSubdiv's, with the mesh's interpolation tag and the scheme's crease curve
    if (links.has_boundary) {
      const CurveCreaseRule crease = triangle_crease_rule(t, tables.scheme(), "meshes with boundaries");
      boundary = {crease.centre, crease.neighbour, mesh.tags.boundary == BoundaryInterpolation::EdgeAndCorner};
    }
    const TriangleTopology topology(c, links);
    TriangleStep step = t.refinement() == TriangleRefinement::Loop
                            ? loop_step(topology, t, links.has_boundary ? &boundary : nullptr)
                            : sqrt3_double_step(topology, t);
    next = std::move(step.mesh);
    steps = std::move(step.steps);
  }
  Mesh out;
  out.positions = mesh.positions;
  out.face_sizes = std::move(next.face_sizes);
  out.face_vertices = std::move(next.face_vertices);
  for (const RefinementStep& s : steps) {
    std::vector<Point> refined(s.rows());
    s.apply(out.positions.data(), refined.data());
    out.positions = std::move(refined);
  }
  return out;
}

}  // namespace stencil_runtime
