#pragma once
// Reading JSON documents that users give stencilgen (scheme files, tables given
// to verify): parsing under a nesting limit, and reading fields with errors
// that say "ORIGIN: FIELD: message", where FIELD is the JSON path
// (functions[2].values["1/3"]), never the JSON library's own wording.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "algebra/rational.hpp"

namespace sg {

// Parses `text` (Json: nlohmann::json or nlohmann::ordered_json). Throws
// sg::Error "ORIGIN: not valid JSON: ..." (with the line and column) or, for
// nesting deeper than limits::kMaxJsonDepth, "ORIGIN: ... nested deeper than
// ..."; the depth is checked while parsing, so nothing that walks a document
// recursively (copies, dumps) ever sees a deeper one. A key that appears twice
// in one object is refused too, naming its path ("ORIGIN: rules.edge: the key
// appears twice ...").
template <class Json>
Json parse_json_document(const std::string& text, const std::string& origin);

// A field's path below `parent`: "parent.key", "parent[\"1/3\"]" for a key
// that is not a plain name, or "parent[index]".
std::string field_path(const std::string& parent, const std::string& key);
std::string field_path(const std::string& parent, std::size_t index);
// Where two documents first differ, as a field path ("" for the whole
// document), or nothing when they are equal as values (key order and spacing
// aside from arrays' order): for verify's messages.
std::optional<std::string> json_difference(const nlohmann::ordered_json& expected, const nlohmann::ordered_json& actual,
                                           const std::string& path = "");

// Fields of one document, each read with its type and range checked; every
// failure throws sg::Error "ORIGIN: FIELD: what".
template <class Json>
class DocumentReader {
 public:
  explicit DocumentReader(std::string origin) : origin_(std::move(origin)) {}
  const std::string& origin() const { return origin_; }

  [[noreturn]] void fail(const std::string& field, const std::string& what) const;
  // obj[key], where `field` is obj's own path ("" for the document).
  const Json& require(const Json& obj, const std::string& key, const std::string& field) const;
  const Json& object(const Json& j, const std::string& field) const;
  const Json& array(const Json& j, const std::string& field) const;
  const std::string& string(const Json& j, const std::string& field) const;
  // An integer in [lo, hi] (a JSON number; 2.0 or "2" are refused).
  long integer(const Json& j, const std::string& field, long lo, long hi) const;
  // An exact rational written as a string, "p" or "p/q" (as tables store them).
  Rational rational_literal(const Json& j, const std::string& field) const;
  // An integer written as a string of decimal digits with an optional sign.
  Integer integer_literal(const Json& j, const std::string& field) const;

 private:
  std::string origin_;
};

// A JSON value as quoted in messages: whole when short, else its start.
template <class Json>
std::string json_excerpt(const Json& j);

}  // namespace sg
