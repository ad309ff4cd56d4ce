#pragma once
// Brings a closed triangle mesh into the form the triangle tables evaluate:
// every face with at most one extraordinary vertex, and every face's layout
// reachable by chart walks over regular vertices. Where that fails the whole
// mesh is refined by the scheme's own step (rules from the table file), which
// leaves the limit surface unchanged.
#include <array>
#include <string>

#include "prepared_mesh.hpp"
#include "triangle_patch.hpp"
#include "triangle_table.hpp"
#include "triangle_topology.hpp"

namespace stencil_runtime {

// One Loop step. Children of face f are faces 4f + c: child c < 3 has corners
// (vertex point of corner c, edge point of edge c -> c+1, edge point of edge
// c-1 -> c), so it covers f's corner c, its u axis along f's edge c -> c+1;
// child 3 is the middle (edge points of edges 0, 1, 2). Throws MeshError when a
// vertex's valence has no rule in the table.
Mesh loop_subdivide_once(const Mesh& mesh, const TriangleTopology& topology, const TriangleTables& rules);

// The nine cells of a triangle's ternary split, in child order: "up" cells
// (a, b) with corners (a,b), (a+1,b), (a,b+1), then "down" cells with corners
// (a+1,b), (a+1,b+1), (a,b+1) (lattice units of a third: a along corner 0 -> 1,
// b along 0 -> 2).
struct TernaryCell {
  int a, b;
  bool down;
  std::array<std::array<int, 2>, 3> corners() const {
    if (down) return {{{a + 1, b}, {a + 1, b + 1}, {a, b + 1}}};
    return {{{a, b}, {a + 1, b}, {a, b + 1}}};
  }
};
const std::array<TernaryCell, 9>& ternary_cells();

// Two sqrt(3) steps (rules from the table file), which split each face in
// nine: children of face f are faces 9f + c, c the ternary cell (ternary_cells),
// each with its corners in the cell's order.
Mesh sqrt3_subdivide_twice(const Mesh& mesh, const TriangleTopology& topology, const TriangleTables& rules);

// A prepared triangle mesh with its topology and every face's patch, as the
// isolation check found them.
struct PreparedTriangleMesh {
  PreparedMesh prepared;
  TriangleTopology topology;  // of prepared.mesh
  std::vector<TrianglePatch> patches;
};

// Checks that the mesh is a closed manifold of triangles and its valences are
// in the tables (an error names the vertex and the stencilgen call that would
// add its valence), then refines until every face's patch can be gathered
// (find_triangle_patch), by Loop steps or by double sqrt(3) steps, at most 3.
// Loop needs 1 step for the bundled meshes, sqrt(3) 1 or 2 double steps:
// its band reaches 4 rings from an extraordinary vertex.
PreparedTriangleMesh prepare_triangle_mesh(const Mesh& mesh, const TriangleTables& tables, const std::string& scheme_name);

// Where parameter (i/n, j/n) of an original face (u along corner 0 -> 1, v
// along 0 -> 2, i + j <= n) lands: the prepared face and its grid indices on
// the same n.
FaceParameter locate_triangle(const PreparedMesh& prepared, std::size_t original_face, long i, long j, long n);

}  // namespace stencil_runtime
