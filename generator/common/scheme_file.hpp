#pragma once
// Shared plumbing of the scheme loaders: reading a scheme document (from a
// file or from memory) under the input limits, checking its header, its
// identity hash and its parameters, with errors "FILE: FIELD: message".
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "algebra/expression.hpp"
#include "common/json_document.hpp"

namespace sg {

// The fields of one scheme document, plus its exact formulas.
class SchemeContext : public DocumentReader<nlohmann::json> {
 public:
  using DocumentReader::DocumentReader;
  // An integer or a rational literal or formula string, evaluated exactly with `b`.
  Rational rational(const nlohmann::json& j, const std::string& field, const Bindings& b) const;
  // A formula string (or an integer) kept as text, to be evaluated later (e.g. at each valence).
  std::string formula(const nlohmann::json& j, const std::string& field) const;
};

// Parses a scheme document (limits::kMaxJsonDepth) and checks its header:
// "format", "version", "name" (a scheme name: it becomes a folder and file
// name), "type", and "description" when present.
nlohmann::json parse_scheme_document(const std::string& text, const SchemeContext& ctx);

// The same for a file (at most limits::kMaxSchemeFileBytes).
nlohmann::json read_scheme_document(const std::filesystem::path& file, const SchemeContext& ctx);

// Identity of a scheme: FNV-1a of its canonical content (the document without
// its description, with the resolved parameters), so overrides give a new identity.
std::uint64_t scheme_content_hash(nlohmann::json canonical, const Bindings& parameters);

// Declared parameter defaults (names as in formulas), then NAME=VALUE
// overrides (errors name the parameter).
Bindings resolve_parameters(const nlohmann::json& doc, const std::vector<std::string>& overrides,
                            const std::string& scheme_name, const SchemeContext& ctx);

}  // namespace sg
