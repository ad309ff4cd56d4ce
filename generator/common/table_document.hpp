#pragma once
// A table file given to `stencilgen verify`: parsed once, under the input
// limits, with the fields every family's table records in the same way.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/json_document.hpp"

namespace sg {

struct TableDocument {
  std::string origin;                   // names the file in errors
  nlohmann::ordered_json doc;
  std::string format;                   // "stencilgen-curve-table", "stencilgen-surface-table", ...
  std::string scheme;                   // the scheme's name (a scheme name, never a path)
  std::vector<std::string> parameters;  // NAME=VALUE, the parameters the table records
};

// Throws sg::Error "ORIGIN: FIELD: ..." when the text is not a JSON object
// with a string "format", a scheme name in "scheme" and exact rationals in
// "parameters" (limits::kMaxJsonDepth holds while parsing).
TableDocument parse_table_document(const std::string& text, const std::string& origin);

}  // namespace sg
