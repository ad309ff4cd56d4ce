#pragma once
// What the quad family gives the crease steps (family/crease_step.hpp): its
// crease rule and where its steps put their edge points.
#include <string>
#include <vector>

#include "family/crease_step.hpp"
#include "mesh/connectivity.hpp"
#include "tables/quad_tables.hpp"

namespace stencil_runtime {

// The scheme's regular curve, read off its regular rules (the generator checks
// that they are its tensor product): face corner 1/4 (midpoints), edge end and
// wing twice the curve's centre and neighbour weights. Throws MeshError when
// the tables' rules are no such product.
CurveCreaseRule quad_crease_rule(const QuadTables& tables, const std::string& scheme);

// The edge point of each corner's edge in a quad step of `parent` whose
// result is `child` (child face k, the k-th corner's quadrant, has that edge
// point second: subdivide_quads and subdivide_polygons).
std::vector<int> quad_step_edge_points(const Connectivity& parent, const Connectivity& child);

}  // namespace stencil_runtime
