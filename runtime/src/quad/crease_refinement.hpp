#pragma once
// Semi-sharp creases and corners on a quad scheme's mesh: one subdivision
// step of the scheme's smooth rules (quad_refinement.hpp) with the rows of the
// points at sharp features replaced by OpenSubdiv's creasing masks (Sdc's
// crease, corner and transition masks), the crease rule being the scheme's own
// curve. The sharpness decays each step; once it is gone the mesh is smooth
// and its patches are evaluated exactly from the tables (docs/runtime.md).
#include "mesh/connectivity.hpp"
#include "mesh/sharpness.hpp"
#include "quad_refinement.hpp"
#include "tables/quad_tables.hpp"

namespace stencil_runtime {

// The subdivision rule along a crease: the regular curve's vertex mask
// (neighbour, centre, neighbour); new edge points are edge midpoints.
struct CurveCreaseRule {
  double centre = 0, neighbour = 0;
};

// The scheme's regular curve, read off its regular rules (their tensor
// product): face corner 1/4 (midpoints), edge end and wing twice the curve's
// centre and neighbour weights. Throws MeshError when the tables' rules are no
// such product (then the scheme has no crease rule the runtime could use).
CurveCreaseRule curve_crease_rule(const QuadTables& tables, const std::string& scheme);

// Applies the creasing of `sharpness` (of `parent`'s vertices and edges) to
// `step`, one smooth step of `parent` whose child face c of parent face f has
// corners (vertex c, edge point c -> c+1, face point, edge point c-1 -> c), and
// returns the sharpness of the child level.
LevelSharpness sharpen_step(const Connectivity& parent, const LevelSharpness& sharpness, const CurveCreaseRule& rule,
                            QuadStep& step);

}  // namespace stencil_runtime
