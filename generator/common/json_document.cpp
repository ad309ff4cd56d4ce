#include "common/json_document.hpp"

#include <algorithm>
#include <cctype>
#include <limits>
#include <string_view>
#include <unordered_set>
#include <vector>

#include "base/error.hpp"
#include "base/limits.hpp"

namespace sg {
namespace {

// nlohmann's what() without its "[json.exception.parse_error.101] " tag.
std::string without_tag(const char* what) {
  const std::string_view text(what);
  const auto end = text.find("] ");
  return std::string(text.starts_with("[json.exception.") && end != std::string_view::npos ? text.substr(end + 2) : text);
}

// The open arrays and objects while a document is parsed, to name where a key
// repeats: the JSON library keeps one of the two values without a word, so a
// scheme file or table that says a thing twice would mean whichever it kept.
struct OpenContainer {
  bool array = false;
  std::size_t elements = 0;             // arrays: elements begun so far
  std::string key;                      // objects: the key whose value is being read
  std::unordered_set<std::string> keys;  // objects: the keys seen so far
};

std::string open_path(const std::vector<OpenContainer>& open) {
  std::string path;
  for (const OpenContainer& c : open)
    path = c.array ? field_path(path, c.elements - 1) : field_path(path, c.key);
  return path;
}

}  // namespace

template <class Json>
Json parse_json_document(const std::string& text, const std::string& origin) {
  using Event = typename Json::parse_event_t;
  std::vector<OpenContainer> open;
  // `depth` is the number of open arrays and objects around the value that starts.
  const typename Json::parser_callback_t check = [&origin, &open](int depth, Event event, Json& parsed) {
    const bool starts = event == Event::object_start || event == Event::array_start;
    if (starts && depth >= limits::kMaxJsonDepth)
      throw Error(origin + ": arrays and objects nested deeper than " + std::to_string(limits::kMaxJsonDepth) +
                  " levels (the limit for JSON documents)");
    if ((starts || event == Event::value) && !open.empty() && open.back().array) ++open.back().elements;
    if (starts) {
      open.emplace_back();
      open.back().array = event == Event::array_start;
    } else if (event == Event::object_end || event == Event::array_end) {
      open.pop_back();
    } else if (event == Event::key) {
      OpenContainer& object = open.back();
      object.key = parsed.template get<std::string>();
      if (!object.keys.insert(object.key).second)
        throw Error(origin + ": " + open_path(open) + ": the key appears twice in its object (which value is meant is ambiguous)");
    }
    return true;
  };
  try {
    return Json::parse(text, check);
  } catch (const typename Json::exception& e) {
    throw Error(origin + ": not valid JSON: " + without_tag(e.what()));
  }
}

template nlohmann::json parse_json_document<nlohmann::json>(const std::string&, const std::string&);
template nlohmann::ordered_json parse_json_document<nlohmann::ordered_json>(const std::string&, const std::string&);

std::optional<std::string> json_difference(const nlohmann::ordered_json& expected, const nlohmann::ordered_json& actual,
                                           const std::string& path) {
  if (expected.type() != actual.type()) return path.empty() ? std::string("the document") : path;
  if (expected.is_object()) {
    for (const auto& [key, value] : expected.items()) {
      if (!actual.contains(key)) return field_path(path, key) + " (missing)";
      if (auto d = json_difference(value, actual[key], field_path(path, key))) return d;
    }
    for (const auto& [key, value] : actual.items())
      if (!expected.contains(key)) return field_path(path, key) + " (not a field of it)";
    return std::nullopt;
  }
  if (expected.is_array()) {
    if (expected.size() != actual.size())
      return (path.empty() ? std::string("the document") : path) + " (" + std::to_string(actual.size()) + " entries, not " +
             std::to_string(expected.size()) + ")";
    for (std::size_t k = 0; k < expected.size(); ++k)
      if (auto d = json_difference(expected[k], actual[k], field_path(path, k))) return d;
    return std::nullopt;
  }
  if (expected != actual) return path.empty() ? std::string("the document") : path;
  return std::nullopt;
}

std::string field_path(const std::string& parent, const std::string& key) {
  const bool plain = !key.empty() && (std::isalpha(static_cast<unsigned char>(key[0])) || key[0] == '_') &&
                     std::all_of(key.begin(), key.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
  if (!plain) return parent + "[\"" + excerpt(key) + "\"]";  // e.g. values["1/3"]
  return parent.empty() ? key : parent + "." + key;
}
std::string field_path(const std::string& parent, std::size_t index) {
  return parent + "[" + std::to_string(index) + "]";
}

template <class Json>
std::string json_excerpt(const Json& j) {
  return excerpt(j.dump());
}

template <class Json>
void DocumentReader<Json>::fail(const std::string& field, const std::string& what) const {
  throw Error(origin_ + ": " + (field.empty() ? "" : field + ": ") + what);
}

template <class Json>
const Json& DocumentReader<Json>::require(const Json& obj, const std::string& key, const std::string& field) const {
  if (!obj.is_object()) fail(field, "expected an object, got " + json_excerpt(obj));
  const auto it = obj.find(key);
  if (it == obj.end()) fail(field, "missing required field '" + excerpt(key) + "'");
  return *it;
}

template <class Json>
const Json& DocumentReader<Json>::object(const Json& j, const std::string& field) const {
  if (!j.is_object()) fail(field, "expected an object, got " + json_excerpt(j));
  return j;
}

template <class Json>
const Json& DocumentReader<Json>::array(const Json& j, const std::string& field) const {
  if (!j.is_array()) fail(field, "expected an array, got " + json_excerpt(j));
  return j;
}

template <class Json>
const std::string& DocumentReader<Json>::string(const Json& j, const std::string& field) const {
  if (!j.is_string()) fail(field, "expected a string, got " + json_excerpt(j));
  return j.template get_ref<const std::string&>();
}

template <class Json>
long DocumentReader<Json>::integer(const Json& j, const std::string& field, long lo, long hi) const {
  if (!j.is_number_integer()) fail(field, "expected an integer, got " + json_excerpt(j));
  // Non-negative integers are stored unsigned: compare before any conversion.
  const std::uint64_t u = j.template get<std::uint64_t>();
  const std::int64_t s = j.template get<std::int64_t>();
  const bool in_range = j.is_number_unsigned()
                            ? u <= static_cast<std::uint64_t>(std::numeric_limits<long>::max()) &&
                                  static_cast<long>(u) >= lo && static_cast<long>(u) <= hi
                            : s >= lo && s <= hi;
  if (!in_range) fail(field, json_excerpt(j) + " is outside the range " + std::to_string(lo) + ".." + std::to_string(hi));
  return j.is_number_unsigned() ? static_cast<long>(u) : static_cast<long>(s);
}

template <class Json>
Rational DocumentReader<Json>::rational_literal(const Json& j, const std::string& field) const {
  const std::string& text = string(j, field);
  try {
    return parse_rational(text);
  } catch (const Error& e) {
    fail(field, e.what());
  }
}

template <class Json>
Integer DocumentReader<Json>::integer_literal(const Json& j, const std::string& field) const {
  const std::string& text = string(j, field);
  const std::size_t digits = !text.empty() && (text[0] == '-' || text[0] == '+') ? 1 : 0;
  if (text.size() == digits ||
      !std::all_of(text.begin() + static_cast<long>(digits), text.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
    fail(field, "'" + excerpt(text) + "' is not an integer");
  return Integer(text[0] == '+' ? text.substr(1) : text);
}

template class DocumentReader<nlohmann::json>;
template class DocumentReader<nlohmann::ordered_json>;
template std::string json_excerpt(const nlohmann::json&);
template std::string json_excerpt(const nlohmann::ordered_json&);

}  // namespace sg
