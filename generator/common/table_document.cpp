#include "common/table_document.hpp"

#include "base/error.hpp"
#include "common/scheme_registry.hpp"

namespace sg {

TableDocument parse_table_document(const std::string& text, const std::string& origin) {
  TableDocument t;
  t.origin = origin;
  t.doc = parse_json_document<nlohmann::ordered_json>(text, origin);
  const DocumentReader<nlohmann::ordered_json> reader(origin);
  reader.object(t.doc, "");
  t.format = reader.string(reader.require(t.doc, "format", ""), "format");
  t.scheme = reader.string(reader.require(t.doc, "scheme", ""), "scheme");
  if (!is_scheme_name(t.scheme))
    reader.fail("scheme", "'" + excerpt(t.scheme) + "' is not a scheme name (" + kSchemeNameRule + ")");
  for (const auto& [name, value] : reader.object(reader.require(t.doc, "parameters", ""), "parameters").items())
    t.parameters.push_back(name + "=" + to_string(reader.rational_literal(value, field_path("parameters", name))));
  return t;
}

}  // namespace sg
