#include "quad/quad_scheme_loader.hpp"

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

// The regular case must be the tensor product of a symmetric binary primal
// curve mask of width 5: even rule (s2, s0, s2), odd rule (s1, s1).
void check_tensor_product(const QuadScheme& q, const SchemeContext& ctx) {
  const CurveScheme& c = q.curve;
  std::array<Rational, 5> s;
  try {
    s = one_ring_mask(c, "quad schemes need a primal mask supported on [-2, 2] (one-ring rules)");
  } catch (const Error& e) {
    ctx.fail("regular_curve", e.what());
  }
  auto expect = [&](const char* rule, const Rational& have, const Rational& want) {
    if (have != want)
      ctx.fail("rules." + std::string(rule),
               "at valence 4 the rule must be the tensor product of '" + c.name + "': expected " + to_string(want) +
                   ", got " + to_string(have));
  };
  expect("face.corner", q.face_corner, s[1] * s[1]);
  expect("edge.end", q.edge_end, s[1] * s[2]);
  expect("edge.wing", q.edge_wing, s[1] * s[0]);
  const VertexRule r = q.vertex_rule(4);
  expect("vertex.centre", r.centre, s[2] * s[2]);
  expect("vertex.edge", r.edge, s[2] * s[0]);
  expect("vertex.face", r.face, s[0] * s[0]);
}

// Polygon rules, checked to reproduce the quad rules on quads: there the edge
// point is (end + face/2)(ends) + (face/4)(wings), and the vertex point is
// (c + m/2 + f/4) old + ((m + f)/(2v)) per edge neighbour + (f/(4v)) per diagonal.
void load_polygon_rules(QuadScheme& q, const json& p, const SchemeContext& ctx) {
  auto& r = q.polygon;
  r.present = true;
  const json& edge = ctx.require(p, "edge", "polygon_rules");
  const json& vertex = ctx.require(p, "vertex", "polygon_rules");
  r.edge_end = ctx.rational(ctx.require(edge, "end", "polygon_rules.edge"), "polygon_rules.edge.end", q.parameters);
  r.edge_face = ctx.rational(ctx.require(edge, "face_point", "polygon_rules.edge"), "polygon_rules.edge.face_point", q.parameters);
  auto formula = [&](const char* key) {
    return ctx.formula(ctx.require(vertex, key, "polygon_rules.vertex"), std::string("polygon_rules.vertex.") + key);
  };
  r.vertex_centre = formula("centre");
  r.vertex_midpoint = formula("edge_midpoint");
  r.vertex_face = formula("face_point");
  if (r.edge_end + r.edge_face / 2 != q.edge_end || r.edge_face / 4 != q.edge_wing)
    ctx.fail("polygon_rules.edge", "on quads it gives end " + to_string(r.edge_end + r.edge_face / 2) + " and wing " +
                                       to_string(r.edge_face / 4) + ", but rules.edge has " + to_string(q.edge_end) +
                                       " and " + to_string(q.edge_wing));
  for (int v = q.min_valence; v <= q.max_valence; ++v) {
    const auto pr = q.polygon_vertex_rule(v);
    const VertexRule want = q.vertex_rule(v);
    const Rational centre = pr.centre + pr.midpoint / 2 + pr.face / 4, e = (pr.midpoint + pr.face) / (2 * v),
                   f = pr.face / (4 * v);
    if (centre != want.centre || e != want.edge || f != want.face)
      ctx.fail("polygon_rules.vertex", "on quads at valence " + std::to_string(v) + " it gives " + to_string(centre) +
                                           ", " + to_string(e) + ", " + to_string(f) + ", but rules.vertex has " +
                                           to_string(want.centre) + ", " + to_string(want.edge) + ", " +
                                           to_string(want.face));
  }
}

}  // namespace

QuadScheme load_quad_scheme(const std::string& spec, const std::vector<std::string>& overrides, const fs::path& dir) {
  const fs::path file = resolve_scheme_file(spec, dir);
  QuadScheme scheme = quad_scheme_from_json(read_file(file, limits::kMaxSchemeFileBytes, "scheme"), file.string(), overrides,
                                             file.has_parent_path() ? file.parent_path() : dir);
  check_scheme_file_name(spec, scheme.name, file);
  return scheme;
}

QuadScheme quad_scheme_from_json(const std::string& text, const std::string& origin,
                                 const std::vector<std::string>& overrides, const fs::path& curve_dir) {
  const SchemeContext ctx(origin);
  const json doc = parse_scheme_document(text, ctx);
  const std::string type = doc.at("type").get<std::string>();
  if (type != "quad") ctx.fail("type", "'" + excerpt(type) + "' is not a quad surface scheme (expected \"quad\")");

  QuadScheme q;
  q.source = origin;
  q.name = doc.at("name").get<std::string>();
  q.description = doc.value("description", "");
  q.parameters = resolve_parameters(doc, overrides, q.name, ctx);

  const std::string& curve = ctx.string(ctx.require(doc, "regular_curve", ""), "regular_curve");
  if (!is_scheme_name(curve))
    ctx.fail("regular_curve", "'" + excerpt(curve) + "' is not the name of a curve scheme (" + kSchemeNameRule + ")");
  try {
    q.curve = load_curve_scheme(curve, {}, curve_dir);
  } catch (const Error& e) {
    ctx.fail("regular_curve", e.what());
  }

  const json& rules = ctx.require(doc, "rules", "");
  const json& face = ctx.require(rules, "face", "rules");
  const json& edge = ctx.require(rules, "edge", "rules");
  const json& vertex = ctx.require(rules, "vertex", "rules");
  q.face_corner = ctx.rational(ctx.require(face, "corner", "rules.face"), "rules.face.corner", q.parameters);
  q.edge_end = ctx.rational(ctx.require(edge, "end", "rules.edge"), "rules.edge.end", q.parameters);
  q.edge_wing = ctx.rational(ctx.require(edge, "wing", "rules.edge"), "rules.edge.wing", q.parameters);
  if (4 * q.face_corner != 1) ctx.fail("rules.face.corner", "4 * corner must be 1, got " + to_string(q.face_corner));
  if (2 * q.edge_end + 4 * q.edge_wing != 1)
    ctx.fail("rules.edge", "2 * end + 4 * wing must be 1, got " + to_string(2 * q.edge_end + 4 * q.edge_wing));
  auto formula = [&](const char* key) {
    return ctx.formula(ctx.require(vertex, key, "rules.vertex"), std::string("rules.vertex.") + key);
  };
  q.vertex_centre = formula("centre");
  q.vertex_edge = formula("edge");
  q.vertex_face = formula("face");
  if (doc.contains("valences")) {
    const json& v = doc["valences"];
    q.min_valence = static_cast<int>(
        ctx.integer(ctx.require(v, "min", "valences"), "valences.min", limits::kMinValence, limits::kMaxValence));
    q.max_valence = static_cast<int>(
        ctx.integer(ctx.require(v, "max", "valences"), "valences.max", q.min_valence, limits::kMaxValence));
  }
  // Every covered valence must give a rule summing to 1 (cheap, and catches typos early).
  for (int v = q.min_valence; v <= q.max_valence; ++v) q.vertex_rule(v);
  check_tensor_product(q, ctx);
  if (doc.contains("polygon_rules")) load_polygon_rules(q, doc["polygon_rules"], ctx);

  json canonical = doc;  // the regular curve's content is part of the identity
  canonical["regular_curve_hash"] = hex64(q.curve.hash);
  q.hash = scheme_content_hash(canonical, q.parameters);
  return q;
}

}  // namespace sg
