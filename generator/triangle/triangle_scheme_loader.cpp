#include "triangle/triangle_scheme_loader.hpp"

#include "base/limits.hpp"
#include "common/hash.hpp"
#include "common/read_file.hpp"
#include "common/scheme_file.hpp"
#include "curve/curve_scheme_loader.hpp"
#include "curve/one_ring_mask.hpp"

namespace sg {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// The crease rule from a curve scheme: binary, uniform, a symmetric primal mask
// on [-2, 2] whose odd rule is the midpoint (the edge point of a crease edge).
void load_crease_curve(TriangleScheme& s, const json& doc, const SchemeContext& ctx, const fs::path& curve_dir) {
  const std::string field = "crease_curve";
  if (s.refinement != TriangleRefinement::Loop)
    ctx.fail(field, "only schemes with Loop's refinement take a crease curve (sqrt(3) splits no edges)");
  s.crease_curve = ctx.string(doc[field], field);
  if (!is_scheme_name(s.crease_curve))
    ctx.fail(field, "'" + excerpt(s.crease_curve) + "' is not the name of a curve scheme (" + kSchemeNameRule + ")");
  CurveScheme c;
  try {
    c = load_curve_scheme(s.crease_curve, {}, curve_dir);
  } catch (const Error& e) {
    ctx.fail(field, e.what());
  }
  std::array<Rational, 5> m;
  try {
    m = one_ring_mask(c, "a crease rule must be supported on [-2, 2] (one ring along the crease)");
  } catch (const Error& e) {
    ctx.fail(field, e.what());
  }
  if (m[1] != Rational(1, 2))
    ctx.fail(field, "'" + c.name + "' must insert edge midpoints (odd rule 1/2, 1/2), got " + to_string(m[1]));
  s.has_crease = true;
  s.crease_centre = m[2];
  s.crease_neighbour = m[0];
  s.crease_hash = c.hash;
}

}  // namespace

TriangleScheme load_triangle_scheme(const std::string& spec, const std::vector<std::string>& overrides,
                                    const fs::path& dir) {
  const fs::path file = resolve_scheme_file(spec, dir);
  TriangleScheme scheme = triangle_scheme_from_json(read_file(file, limits::kMaxSchemeFileBytes, "scheme"), file.string(),
                                                     overrides, file.has_parent_path() ? file.parent_path() : dir);
  check_scheme_file_name(spec, scheme.name, file);
  return scheme;
}

TriangleScheme triangle_scheme_from_json(const std::string& text, const std::string& origin,
                                         const std::vector<std::string>& overrides, const fs::path& curve_dir) {
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
  if (doc.contains("crease_curve")) load_crease_curve(s, doc, ctx, curve_dir);
  json canonical = doc;  // the crease curve's content is part of the identity
  if (s.has_crease) canonical["crease_curve_hash"] = hex64(s.crease_hash);
  s.hash = scheme_content_hash(canonical, s.parameters);
  return s;
}

}  // namespace sg
