#pragma once
// A triangle scheme's own subdivision steps, applied to topology alone: each
// gives the refined connectivity and the sparse matrices that compute its
// vertices (refinement.hpp), with the rules stored in the tables. The limit
// surface does not change.
#include <array>
#include <string>
#include <vector>

#include "family/boundary_rules.hpp"
#include "family/crease_step.hpp"
#include "family/refinement.hpp"
#include "mesh/connectivity.hpp"
#include "mesh/uniform_topology.hpp"
#include "tables/triangle_tables.hpp"

namespace stencil_runtime {

struct TriangleStep {
  Connectivity mesh;
  std::vector<RefinementStep> steps;  // one for Loop, two for a double sqrt(3) step
};

// The scheme's crease curve (the rule along creases and boundaries), or a
// MeshError saying why there is none and that `refused` ("creases and
// corners", "meshes with boundaries") are refused: sqrt(3) splits no edges, and
// tables before format 5 carry no crease rule.
CurveCreaseRule triangle_crease_rule(const TriangleTables& tables, const std::string& scheme, const std::string& refused);

// One Loop step. New vertices: the vertex points (same numbers), then one edge
// point per edge (in the order of its first half-edge). Children of face f are
// faces 4f + c: child c < 3 has corners (vertex point of corner c, edge point
// of edge c -> c+1, edge point of edge c-1 -> c), so it covers f's corner c,
// its u axis along f's edge c -> c+1; child 3 is the middle (edge points of
// edges 0, 1, 2). Throws MeshError when a vertex's valence has no rule. A
// topology with boundaries needs `boundary` (OpenSubdiv's rules with the
// scheme's crease curve; else MeshError): then an edge's point is its midpoint
// on the boundary and Loop's rule inside, whatever its ends.
TriangleStep loop_step(const TriangleTopology& topology, const TriangleTables& rules, const BoundaryRules* boundary = nullptr);

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

// Two sqrt(3) steps, which split each face in nine: children of face f are
// faces 9f + c, c the ternary cell (ternary_cells), each with its corners in
// the cell's order.
TriangleStep sqrt3_double_step(const TriangleTopology& topology, const TriangleTables& rules);

}  // namespace stencil_runtime
