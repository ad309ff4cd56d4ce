#pragma once
// Brings a closed quad mesh into the form the tables evaluate: every face with
// at most one extraordinary vertex. Where some face has two or more, the whole
// mesh is refined by the scheme's own subdivision step (rules from the table
// file), which leaves the limit surface unchanged; each step makes the
// extraordinary vertices one ring further apart. Original face F then covers
// 4^s faces of the prepared mesh (s = steps), in a fixed quadrant order.
#include <array>
#include <vector>

#include "mesh.hpp"
#include "prepared_mesh.hpp"
#include "quad_topology.hpp"
#include "surface_table.hpp"

namespace stencil_runtime {

// One subdivision step. Children of face f are faces 4f + c (c = corner), child
// c having corners (vertex point of corner c, edge point of edge c->c+1, face
// point, edge point of edge c-1->c), so that child c covers the quadrant of f at
// corner c in f's own parameterisation, scaled by 1/2 and rotated by c quarter
// turns. Throws MeshError when a vertex's valence has no rule in the table.
Mesh subdivide_once(const Mesh& mesh, const QuadTopology& topology, const SurfaceTables& rules);

// One step of the scheme's polygon rules on a closed manifold mesh with faces
// of any size (>= 3); every face of the result is a quad. Children of face f
// (k corners) are faces offset(f) + c, c = 0..k-1, laid out as in
// subdivide_once. Throws MeshError naming the face, edge or vertex.
Mesh subdivide_polygons(const Mesh& mesh, const SurfaceTables& rules);


// Checks the valences against the table (an error names the vertex and the
// stencilgen call that would add its valence). A mesh with non-quad faces gets
// one step of the scheme's polygon rules first (refused, naming the face, when
// the scheme has none). Then it is refined until every face has at most one
// extraordinary vertex (at most 3 steps in all).
PreparedMesh prepare_mesh(const Mesh& mesh, const SurfaceTables& tables, const std::string& scheme_name);

// Where a parameter of an original face lands after `steps` refinements:
// the prepared face and the parameter in it. Parameters are grid indices
// (i/n, j/n); the result is on the grid of the same n, 0 <= i', j' <= n.
FaceParameter locate(const PreparedMesh& prepared, std::size_t original_face, long i, long j, long n);

}  // namespace stencil_runtime
