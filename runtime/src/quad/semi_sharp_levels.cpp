#include "semi_sharp_levels.hpp"

#include "quad_creases.hpp"
#include "quad_refinement.hpp"

namespace stencil_runtime {

SemiSharpRefinement refine_round_semi_sharp(const Connectivity& mesh, const LevelSharpness& sharpness,
                                            const QuadTables& tables, const CurveCreaseRule& crease,
                                            const BoundaryRules& boundary, bool edge_and_corner) {
  const RegionStepper step = [&](const Connectivity& region) {
    const QuadTopology topo(region, true);
    QuadStep s = subdivide_quads(topo, tables, &boundary);
    RegionStep out;
    out.edge_points = quad_step_edge_points(region, s.mesh);
    out.step = std::move(s.step);
    out.mesh = std::move(s.mesh);
    return out;
  };
  return refine_round_semi_sharp(mesh, sharpness, step, crease, edge_and_corner);
}

}  // namespace stencil_runtime
