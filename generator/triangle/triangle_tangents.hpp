#pragma once
// The tangent plane of a triangle patch (Loop, sqrt(3)) at its extraordinary
// vertex: two tangent stencils along the patch's u and v edges, from the left
// eigenvectors of the patch's subdivision onto its own child at the vertex
// (algebra/tangent_stencils.hpp says how and why). The patch's (u, v) frame
// (u along e0, v along e1, 60 degrees on) is positively oriented, so
// t_u.P x t_v.P points as du x dv does next to the vertex.
#include <optional>
#include <string>
#include <vector>

#include "algebra/tangent_stencils.hpp"
#include "triangle/triangle_children.hpp"
#include "triangle/triangle_table.hpp"

namespace sg {

// `children`: region 0's children over `layout` (its union layout);
// `tables`: the valence's tables at some rate (region 0's node stencils at the
// patch's corners (1, 0) and (0, 1) give the edges' far ends).
std::optional<TangentStencils> triangle_ev_tangents(const std::vector<TriangleChild>& children,
                                                    const std::vector<SectorPoint>& layout, const TriangleTable& table,
                                                    std::string& why);

}  // namespace sg
