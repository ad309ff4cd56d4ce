#pragma once
// Shared plumbing of the scheme loaders: finding a scheme file, parsing it, and
// reporting errors as "FILE: FIELD: message".
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "algebra/expression.hpp"
#include "base/error.hpp"

namespace sg {

class SchemeContext {
 public:
  explicit SchemeContext(std::string file) : file_(std::move(file)) {}
  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    throw Error(file_ + ": " + (field.empty() ? "" : field + ": ") + what);
  }
  const nlohmann::json& require(const nlohmann::json& obj, const std::string& key, const std::string& field) const {
    if (!obj.is_object() || !obj.contains(key)) fail(field, "missing required field '" + key + "'");
    return obj.at(key);
  }
  long integer(const nlohmann::json& j, const std::string& field) const {
    if (!j.is_number_integer()) fail(field, "expected an integer, got " + j.dump());
    return j.get<long>();
  }
  // A rational literal or formula string, evaluated exactly with `b`.
  Rational rational(const nlohmann::json& j, const std::string& field, const Bindings& b) const {
    if (j.is_number_integer()) return Rational(j.get<long>());
    if (!j.is_string())
      fail(field, "expected an exact rational string such as \"-1/16\" (floating point is not exact), got " + j.dump());
    try {
      return evaluate_expression(j.get<std::string>(), b);
    } catch (const Error& e) {
      fail(field, e.what());
    }
  }
  const std::string& file() const { return file_; }

 private:
  std::string file_;
};

// Parses the file and checks "format" and "version".
nlohmann::json read_scheme_document(const std::filesystem::path& file, const SchemeContext& ctx);

// Identity of a scheme: FNV-1a of its canonical content (the document without
// its description, with the resolved parameters), so overrides give a new identity.
std::uint64_t scheme_content_hash(nlohmann::json canonical, const Bindings& parameters);

// Declared parameter defaults, then NAME=VALUE overrides (errors name the parameter).
Bindings resolve_parameters(const nlohmann::json& doc, const std::vector<std::string>& overrides,
                            const std::string& scheme_name, const SchemeContext& ctx);

}  // namespace sg
