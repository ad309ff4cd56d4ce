#pragma once
// Checked reading of a JSON table file: size and nesting depth limited, every
// field looked up with a LoadError naming the file and the field when it is
// missing or of the wrong kind, and exact numbers parsed strictly.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "stencil_runtime/error.hpp"

namespace stencil_runtime::detail {

// Nesting depth of a table file: tables nest four levels; this leaves room.
inline constexpr int kMaxJsonDepth = 16;

class JsonFile {
 public:
  // Reads and parses `path` (a regular file of at most limits::kMaxTableFileBytes,
  // nested at most kMaxJsonDepth levels, no object repeating a key).
  explicit JsonFile(std::string path);
  const nlohmann::json& root() const { return doc_; }
  const std::string& path() const { return path_; }

  // doc[key] (`field` names it in errors, e.g. "nodes[3].numerators").
  const nlohmann::json& member(const nlohmann::json& object, const char* key, const std::string& field) const;
  std::string string(const nlohmann::json& value, const std::string& field) const;
  std::int64_t integer(const nlohmann::json& value, const std::string& field) const;
  const nlohmann::json& array(const nlohmann::json& value, const std::string& field) const;
  [[noreturn]] void fail(const std::string& field, const std::string& what) const;

 private:
  std::string path_;
  nlohmann::json doc_;
};

// Strict decimal parse of a whole string into a 64-bit integer (optional sign);
// false on anything else or on overflow.
bool parse_int64(std::string_view text, std::int64_t& out);

// An exact rational "p/q" or "p" (any number of digits) rounded to a double:
// finite, q nonzero; `fail` otherwise.
double parse_exact_rational(std::string_view text, const JsonFile& file, const std::string& field);
// numerator / denominator, both integers of any length.
double parse_ratio(std::string_view numerator, std::string_view denominator, const JsonFile& file, const std::string& field);

}  // namespace stencil_runtime::detail
