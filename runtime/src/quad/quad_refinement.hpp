#pragma once
// A quad scheme's own subdivision steps, applied to topology alone: each step
// gives the refined connectivity and the sparse matrix that computes its
// vertices from the vertices before (refinement.hpp), with the rules stored
// in the tables. The limit surface does not change.
#include "family/boundary_rules.hpp"
#include "family/refinement.hpp"
#include "mesh/connectivity.hpp"
#include "mesh/polygon_links.hpp"
#include "mesh/uniform_topology.hpp"
#include "tables/quad_tables.hpp"

namespace stencil_runtime {

struct QuadStep {
  Connectivity mesh;  // every face a quad
  RefinementStep step;
};

// One step of the scheme's quad rules. New vertices: the vertex points (same
// numbers as the old vertices), then one face point per face, then one edge
// point per edge (in the order of its first half-edge). Children of face f are
// faces 4f + c (c = corner), child c having corners (vertex point of corner c,
// edge point of edge c -> c+1, face point, edge point of edge c-1 -> c), so that
// child c covers the quadrant of f at corner c in f's own parameterisation,
// scaled by 1/2 and rotated by c quarter turns. Throws MeshError when a
// vertex's valence has no rule in the tables. A topology with boundaries
// needs `boundary` (else MeshError).
QuadStep subdivide_quads(const QuadTopology& topology, const QuadTables& rules, const BoundaryRules* boundary = nullptr);

// One step of the scheme's polygon rules on a manifold mesh with faces of any
// size (>= 3), closed or with `boundary` rules; every face of the result is a quad. Children of face f
// (k corners) are faces offset(f) + c, c = 0..k-1, laid out as in
// subdivide_quads. Throws MeshError naming the vertex whose valence has no rule.
// `smooth_triangles`: OpenSubdiv's Catmull-Clark option TRI_SUB_SMOOTH, for an
// edge next to one or two triangles: each face point weighs f = the mean of
// 0.47 per triangle and 1/4 per other face, each end (1 - 2f) / 2.
QuadStep subdivide_polygons(const Connectivity& mesh, const PolygonLinks& links, const QuadTables& rules,
                            bool smooth_triangles = false, const BoundaryRules* boundary = nullptr);

}  // namespace stencil_runtime
