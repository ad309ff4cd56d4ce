#include "quad_creases.hpp"

#include <cmath>

namespace stencil_runtime {

CurveCreaseRule quad_crease_rule(const QuadTables& t, const std::string& scheme) {
  const CurveCreaseRule rule{2 * t.edge_end(), 2 * t.edge_wing()};
  const double tol = 1e-14;
  bool product = std::abs(t.face_corner() - 0.25) <= tol && std::abs(rule.centre + 2 * rule.neighbour - 1) <= tol;
  if (const auto* v = t.vertex_rule(4))
    product = product && std::abs(v->centre - rule.centre * rule.centre) <= tol &&
              std::abs(v->edge - rule.centre * rule.neighbour) <= tol &&
              std::abs(v->face - rule.neighbour * rule.neighbour) <= tol;
  if (!product)
    throw MeshError("the scheme " + scheme +
                    "'s regular rules are not the tensor product of a curve with midpoint edge rule, so the runtime has "
                    "no crease rule for it: creases and corners are refused");
  return rule;
}

std::vector<int> quad_step_edge_points(const Connectivity& parent, const Connectivity& child) {
  std::vector<int> out(parent.face_vertices.size());
  for (std::size_t k = 0; k < out.size(); ++k) out[k] = child.face_vertices[4 * k + 1];
  return out;
}

}  // namespace stencil_runtime
