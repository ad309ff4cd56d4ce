#include "triangle/triangle_scheme_loader.hpp"

#include "base/limits.hpp"
#include "common/read_file.hpp"
#include "common/scheme_file.hpp"

namespace sg {
namespace fs = std::filesystem;
using nlohmann::json;

TriangleScheme load_triangle_scheme(const std::string& spec, const std::vector<std::string>& overrides,
                                    const fs::path& dir) {
  const fs::path file = resolve_scheme_file(spec, dir);
  return triangle_scheme_from_json(read_file(file, limits::kMaxSchemeFileBytes, "scheme"), file.string(), overrides);
}

TriangleScheme triangle_scheme_from_json(const std::string& text, const std::string& origin,
                                         const std::vector<std::string>& overrides) {
  const SchemeContext ctx(origin);
  const json doc = parse_scheme_document(text, ctx);
  const std::string type = doc.at("type").get<std::string>();
  if (type != "triangle")
    ctx.fail("type", "'" + excerpt(type) + "' is not a triangle surface scheme (expected \"triangle\")");

  TriangleScheme s;
  s.source = origin;
  s.name = doc.at("name").get<std::string>();
  s.description = doc.value("description", "");
  s.parameters = resolve_parameters(doc, overrides, s.name, ctx);
  const json& refinement = ctx.require(doc, "refinement", "");
  if (refinement == "loop") s.refinement = TriangleRefinement::Loop;
  else if (refinement == "sqrt3") s.refinement = TriangleRefinement::Sqrt3;
  else ctx.fail("refinement", "expected \"loop\" or \"sqrt3\", got " + json_excerpt(refinement));

  const json& rules = ctx.require(doc, "rules", "");
  if (s.refinement == TriangleRefinement::Loop) {
    const json& edge = ctx.require(rules, "edge", "rules");
    s.edge_end = ctx.rational(ctx.require(edge, "end", "rules.edge"), "rules.edge.end", s.parameters);
    s.edge_opposite = ctx.rational(ctx.require(edge, "opposite", "rules.edge"), "rules.edge.opposite", s.parameters);
    if (2 * s.edge_end + 2 * s.edge_opposite != 1)
      ctx.fail("rules.edge", "2 * end + 2 * opposite must be 1, got " + to_string(2 * s.edge_end + 2 * s.edge_opposite));
  } else if (rules.contains("edge")) {
    ctx.fail("rules.edge", "sqrt(3) has no edge rule (its new vertices are face centroids)");
  }
  const json& vertex = ctx.require(rules, "vertex", "rules");
  s.vertex_neighbour = ctx.formula(ctx.require(vertex, "neighbour", "rules.vertex"), "rules.vertex.neighbour");

  if (doc.contains("valences")) {
    const json& v = doc["valences"];
    s.min_valence = static_cast<int>(
        ctx.integer(ctx.require(v, "min", "valences"), "valences.min", limits::kMinValence, limits::kMaxValence));
    s.max_valence = static_cast<int>(
        ctx.integer(ctx.require(v, "max", "valences"), "valences.max", s.min_valence, limits::kMaxValence));
  }
  if (s.min_valence > 6 || s.max_valence < 6) ctx.fail("valences", "the range must include the regular valence 6");
  // The regular scaling function is solved exactly: valence 6 must be rational.
  if (!s.exact_neighbour_weight(6))
    ctx.fail("rules.vertex.neighbour", "must be rational at the regular valence v = 6");
  // Every covered valence must evaluate, with a centre weight 1 - v w in [0, 1).
  for (int v = s.min_valence; v <= s.max_valence; ++v) {
    const Real x = s.real_neighbour_weight(v);
    if (!(x > 0) || !(v * x <= 1))
      ctx.fail("rules.vertex.neighbour", "at v = " + std::to_string(v) + " it is " + to_string(x, 12) +
                                             "; need 0 < w <= 1/v so that every weight is non-negative");
  }
  s.hash = scheme_content_hash(doc, s.parameters);
  return s;
}

}  // namespace sg
