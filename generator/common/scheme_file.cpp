#include "common/scheme_file.hpp"

#include <cctype>
#include <map>
#include <set>

#include "base/error.hpp"
#include "base/limits.hpp"
#include "common/hash.hpp"
#include "common/parameters_json.hpp"
#include "common/read_file.hpp"
#include "common/scheme_registry.hpp"

namespace sg {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// A name a formula can use: a letter or '_', then letters, digits and '_'.
bool is_parameter_name(const std::string& name) {
  if (name.empty() || static_cast<long>(name.size()) > limits::kMaxNameLength) return false;
  if (!std::isalpha(static_cast<unsigned char>(name[0])) && name[0] != '_') return false;
  for (char c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  return true;
}

}  // namespace

Rational SchemeContext::rational(const json& j, const std::string& field, const Bindings& b) const {
  if (j.is_number_integer()) return Rational(Integer(j.dump()));  // exact for any 64-bit value, signed or not
  if (!j.is_string())
    fail(field, "expected an exact rational string such as \"-1/16\" (floating point is not exact), got " +
                    json_excerpt(j));
  try {
    return evaluate_expression(j.get_ref<const std::string&>(), b);
  } catch (const Error& e) {
    fail(field, e.what());
  }
}

std::string SchemeContext::formula(const json& j, const std::string& field) const {
  if (j.is_number_integer()) return j.dump();
  if (!j.is_string()) fail(field, "expected a formula string in v, got " + json_excerpt(j));
  return j.get<std::string>();
}

json parse_scheme_document(const std::string& text, const SchemeContext& ctx) {
  const json doc = parse_json_document<json>(text, ctx.origin());
  ctx.object(doc, "");
  if (ctx.require(doc, "format", "") != "stencilgen-scheme") ctx.fail("format", "expected \"stencilgen-scheme\"");
  ctx.integer(ctx.require(doc, "version", ""), "version", 1, 1);
  const std::string& name = ctx.string(ctx.require(doc, "name", ""), "name");
  if (!is_scheme_name(name)) ctx.fail("name", "'" + excerpt(name) + "' is not a scheme name: " + kSchemeNameRule);
  const std::string& type = ctx.string(ctx.require(doc, "type", ""), "type");
  if (doc.contains("description")) ctx.string(doc["description"], "description");
  // A field no loader reads is refused, not ignored: a misspelt optional one
  // ("polygon_rule") would otherwise give another scheme without a word.
  static const std::map<std::string, std::set<std::string>> own = {
      {"curve-uniform", {"arity", "mask"}},
      {"curve-columns", {"arity", "mask", "left_mask", "right_mask", "special_columns"}},
      {"curve-knots", {"degree", "knot_spacing"}},
      {"quad", {"regular_curve", "rules", "valences", "polygon_rules"}},
      {"triangle", {"refinement", "rules", "valences", "crease_curve"}}};
  if (const auto it = own.find(type); it != own.end())
    for (const auto& [key, value] : doc.items())
      if (!it->second.count(key) && key != "format" && key != "version" && key != "name" && key != "type" &&
          key != "description" && key != "parameters")
        ctx.fail(key, "is not a field of a " + type + " scheme (docs/scheme-format.md)");
  return doc;
}

json read_scheme_document(const fs::path& file, const SchemeContext& ctx) {
  return parse_scheme_document(read_file(file, limits::kMaxSchemeFileBytes, "scheme"), ctx);
}

std::uint64_t scheme_content_hash(json canonical, const Bindings& parameters) {
  canonical.erase("description");
  canonical["parameters"] = parameters_json<json>(parameters);
  return fnv1a64(canonical.dump());
}

Bindings resolve_parameters(const json& doc, const std::vector<std::string>& overrides, const std::string& scheme_name,
                            const SchemeContext& ctx) {
  Bindings params;
  if (doc.contains("parameters")) {
    for (const auto& [key, value] : ctx.object(doc["parameters"], "parameters").items()) {
      const std::string field = field_path("parameters", key);
      if (!is_parameter_name(key))
        ctx.fail(field, "'" + excerpt(key) + "' is not a parameter name (a letter or '_', then letters, digits and '_'; at most " +
                            std::to_string(limits::kMaxNameLength) + " characters)");
      // Names the formulas give a meaning of their own: a parameter so named would be shadowed, or shadow it.
      const std::string type = doc.contains("type") && doc["type"].is_string() ? doc["type"].get<std::string>() : "";
      if (key == "cos2pi" || (key == "v" && (type == "quad" || type == "triangle")))
        ctx.fail(field, "'" + key + "' is a name of the formulas (" +
                            (key == "v" ? std::string("the valence in rule formulas") : std::string("the function cos2pi")) +
                            "); give the parameter another name");
      params[key] = ctx.rational(value, field, {});
    }
  }
  std::set<std::string> overridden;
  for (const std::string& o : overrides) {
    const auto eq = o.find('=');
    if (eq == std::string::npos) throw Error("parameter override '" + excerpt(o) + "' is not NAME=VALUE");
    const std::string key = o.substr(0, eq);
    if (!overridden.insert(key).second)
      throw Error("parameter '" + excerpt(key) + "' is overridden twice (--param " + excerpt(key) + "=... given more than once)");
    if (!params.count(key)) {
      std::string known;
      for (const auto& [k, v] : params) known += (known.empty() ? "" : ", ") + k;
      throw Error("scheme '" + scheme_name + "' has no parameter '" + excerpt(key) + "'" +
                  (known.empty() ? " (it has none)" : " (it has: " + known + ")"));
    }
    try {
      params[key] = evaluate_expression(o.substr(eq + 1), {});
    } catch (const Error& e) {
      throw Error("parameter override " + key + ": " + e.what());
    }
  }
  return params;
}

}  // namespace sg
