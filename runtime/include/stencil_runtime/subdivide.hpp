#pragma once
// One whole-mesh step of a scheme's own subdivision, with the rules its tables
// store: a quad scheme's polygon step when the mesh has other polygons (every
// face becomes quads), else its quad step (1 to 4); a triangle scheme's Loop
// step (1 to 4) or double sqrt(3) step (1 to 9). The limit surface does not change.
// A quad or Loop mesh may have boundaries: OpenSubdiv's boundary rules, with
// the mesh's `interpolateboundary` tag (edge-only unless it says
// edge-and-corner); sqrt(3) refuses them (it has no rule along a boundary).
#include "mesh.hpp"
#include "tables.hpp"

namespace stencil_runtime {

// Throws MeshError naming the face, edge or vertex for a mesh the scheme cannot
// refine, or a coordinate that is not finite or beyond limits::kMaxCoordinate.
Mesh subdivide(const Tables& tables, const Mesh& mesh);

}  // namespace stencil_runtime
