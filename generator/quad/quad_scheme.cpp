#include "quad/quad_scheme.hpp"

#include "base/error.hpp"

namespace sg {

VertexRule QuadScheme::vertex_rule(int valence) const {
  if (valence < min_valence || valence > max_valence)
    throw Error(source + ": valence " + std::to_string(valence) + " is outside the range " +
                std::to_string(min_valence) + ".." + std::to_string(max_valence) + " the scheme covers");
  Bindings b = parameters;
  b["v"] = valence;
  VertexRule r;
  auto eval = [&](const std::string& formula, const char* field) {
    try {
      return evaluate_expression(formula, b);
    } catch (const Error& e) {
      throw Error(source + ": rules.vertex." + field + " at v = " + std::to_string(valence) + ": " + e.what());
    }
  };
  r.centre = eval(vertex_centre, "centre");
  r.edge = eval(vertex_edge, "edge");
  r.face = eval(vertex_face, "face");
  const Rational sum = r.centre + valence * (r.edge + r.face);
  if (sum != 1)
    throw Error(source + ": rules.vertex: the weights sum to " + to_string(sum) + " at v = " + std::to_string(valence) +
                ", not 1 (centre + v*edge + v*face must be 1)");
  return r;
}

QuadScheme::PolygonVertexRule QuadScheme::polygon_vertex_rule(int valence) const {
  if (!polygon.present) throw Error(source + ": the scheme has no polygon_rules");
  Bindings b = parameters;
  b["v"] = valence;
  auto eval = [&](const std::string& formula, const char* field) {
    try {
      return evaluate_expression(formula, b);
    } catch (const Error& e) {
      throw Error(source + ": polygon_rules.vertex." + field + " at v = " + std::to_string(valence) + ": " + e.what());
    }
  };
  return {eval(polygon.vertex_centre, "centre"), eval(polygon.vertex_midpoint, "edge_midpoint"),
          eval(polygon.vertex_face, "face_point")};
}

}  // namespace sg
