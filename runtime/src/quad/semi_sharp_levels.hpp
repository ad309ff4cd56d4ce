#pragma once
// The refinement round semi-sharp features (family/semi_sharp_levels.hpp) by
// the quad scheme's own steps.
#include "family/boundary_rules.hpp"
#include "family/semi_sharp_levels.hpp"
#include "tables/quad_tables.hpp"

namespace stencil_runtime {

// From a quad mesh, closed or with boundaries (`boundary`: their rules, needed
// on a closed mesh too, for the regions' borders), and its sharpness.
// `crease` and `edge_and_corner` as for sharpen_step.
SemiSharpRefinement refine_round_semi_sharp(const Connectivity& mesh, const LevelSharpness& sharpness,
                                            const QuadTables& tables, const CurveCreaseRule& crease,
                                            const BoundaryRules& boundary, bool edge_and_corner);

}  // namespace stencil_runtime
