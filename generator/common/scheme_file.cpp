#include "common/scheme_file.hpp"

#include "common/hash.hpp"
#include "common/parameters_json.hpp"
#include "common/read_file.hpp"

namespace sg {
namespace fs = std::filesystem;
using nlohmann::json;

json read_scheme_document(const fs::path& file, const SchemeContext& ctx) {
  json doc;
  try {
    doc = json::parse(read_file(file));
  } catch (const json::parse_error& e) {
    ctx.fail("", std::string("not valid JSON: ") + e.what());
  }
  if (!doc.is_object()) ctx.fail("", "expected a JSON object");
  if (ctx.require(doc, "format", "") != "stencilgen-scheme") ctx.fail("format", "expected \"stencilgen-scheme\"");
  if (ctx.integer(ctx.require(doc, "version", ""), "version") != 1) ctx.fail("version", "only version 1 is supported");
  const json& name = ctx.require(doc, "name", "");
  if (!name.is_string() || name.get<std::string>().empty()) ctx.fail("name", "expected a non-empty string");
  if (!ctx.require(doc, "type", "").is_string()) ctx.fail("type", "expected a string");
  return doc;
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
    if (!doc["parameters"].is_object()) ctx.fail("parameters", "expected an object");
    for (const auto& [key, value] : doc["parameters"].items())
      params[key] = ctx.rational(value, "parameters." + key, {});
  }
  for (const std::string& o : overrides) {
    const auto eq = o.find('=');
    if (eq == std::string::npos) throw Error("parameter override '" + o + "' is not NAME=VALUE");
    const std::string key = o.substr(0, eq);
    if (!params.count(key)) {
      std::string known;
      for (const auto& [k, v] : params) known += (known.empty() ? "" : ", ") + k;
      throw Error("scheme '" + scheme_name + "' has no parameter '" + key + "'" +
                  (known.empty() ? " (it has none)" : " (it has: " + known + ")"));
    }
    try {
      params[key] = evaluate_expression(o.substr(eq + 1), {});
    } catch (const Error& e) {
      throw Error("parameter override '" + o + "': " + e.what());
    }
  }
  return params;
}

}  // namespace sg
