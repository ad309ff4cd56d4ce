#include "json_reader.hpp"

#include <charconv>
#include <cmath>
#include <unordered_set>
#include <vector>

#include "binary_reader.hpp"

namespace stencil_runtime::detail {

using nlohmann::json;

namespace {

// The open arrays and objects while a table file is parsed, to name where a key
// repeats (the JSON library would keep one of the two values without a word).
struct OpenContainer {
  bool array = false;
  std::size_t elements = 0;             // arrays: elements begun so far
  std::string key;                      // objects: the key whose value is being read
  std::unordered_set<std::string> keys;  // objects: the keys seen so far
};

std::string open_path(const std::vector<OpenContainer>& open) {
  std::string path;
  for (const OpenContainer& c : open) {
    if (c.array) {
      path += "[" + std::to_string(c.elements - 1) + "]";
    } else {
      if (!path.empty()) path += ".";
      path += c.key;
    }
  }
  return path;
}

}  // namespace

JsonFile::JsonFile(std::string path) : path_(std::move(path)) {
  const std::string text = read_table_file(path_);
  // The callback sees every nesting step before the parser recurses into it.
  int too_deep = 0;
  std::vector<OpenContainer> open;
  const json::parser_callback_t check = [&](int depth, json::parse_event_t event, json& parsed) {
    using Event = json::parse_event_t;
    const bool starts = event == Event::object_start || event == Event::array_start;
    if (starts && depth >= kMaxJsonDepth) too_deep = 1;
    if (too_deep) return false;
    if ((starts || event == Event::value) && !open.empty() && open.back().array) ++open.back().elements;
    if (starts) {
      open.emplace_back();
      open.back().array = event == Event::array_start;
    } else if (event == Event::object_end || event == Event::array_end) {
      open.pop_back();
    } else if (event == Event::key) {
      OpenContainer& object = open.back();
      object.key = parsed.get<std::string>();
      if (!object.keys.insert(object.key).second)
        throw LoadError(path_ + ": " + open_path(open) + ": the key appears twice in its object (which value is meant is ambiguous)");
    }
    return true;
  };
  try {
    doc_ = json::parse(text, check);
  } catch (const json::exception& e) {
    throw LoadError(path_ + ": not valid JSON: " + e.what());
  }
  if (too_deep) throw LoadError(path_ + ": nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
  if (!doc_.is_object()) throw LoadError(path_ + ": not a JSON object");
}

void JsonFile::fail(const std::string& field, const std::string& what) const {
  throw LoadError(path_ + ": " + field + ": " + what);
}

const json& JsonFile::member(const json& object, const char* key, const std::string& field) const {
  if (!object.is_object()) fail(field, "expected an object");
  const auto it = object.find(key);
  if (it == object.end()) fail(field.empty() ? key : field + "." + key, "missing");
  return *it;
}

std::string JsonFile::string(const json& value, const std::string& field) const {
  if (!value.is_string()) fail(field, "expected a string");
  return value.get<std::string>();
}

std::int64_t JsonFile::integer(const json& value, const std::string& field) const {
  if (!value.is_number_integer()) fail(field, "expected an integer");
  if (value.is_number_unsigned() && value.get<std::uint64_t>() > static_cast<std::uint64_t>(INT64_MAX))
    fail(field, "integer out of range");
  return value.get<std::int64_t>();
}

const json& JsonFile::array(const json& value, const std::string& field) const {
  if (!value.is_array()) fail(field, "expected an array");
  return value;
}

bool parse_int64(std::string_view text, std::int64_t& out) {
  if (!text.empty() && text[0] == '+') text.remove_prefix(1);
  if (text.empty()) return false;
  const auto [end, err] = std::from_chars(text.data(), text.data() + text.size(), out);
  return err == std::errc() && end == text.data() + text.size();
}

namespace {

// An integer of any length as mantissa * 10^exponent (19 significant digits).
struct Decimal {
  long double mantissa = 0;
  long exponent = 0;
};

bool parse_integer(std::string_view s, Decimal& d) {
  std::size_t i = 0;
  const bool negative = !s.empty() && s[0] == '-';
  if (negative || (!s.empty() && s[0] == '+')) ++i;
  if (i == s.size() || s.size() > 100000) return false;
  std::size_t used = 0;
  for (std::size_t k = i; k < s.size(); ++k) {
    if (s[k] < '0' || s[k] > '9') return false;
    if (used < 19) {
      d.mantissa = d.mantissa * 10 + (s[k] - '0');
      if (d.mantissa != 0) ++used;
    } else {
      ++d.exponent;
    }
  }
  if (negative) d.mantissa = -d.mantissa;
  return true;
}

}  // namespace

double parse_ratio(std::string_view numerator, std::string_view denominator, const JsonFile& file, const std::string& field) {
  Decimal n, d;
  if (!parse_integer(numerator, n) || !parse_integer(denominator, d))
    file.fail(field, quoted_excerpt(std::string(numerator) + "/" + std::string(denominator)) + " is not an exact rational");
  if (d.mantissa == 0) file.fail(field, "zero denominator");
  const double x = static_cast<double>(n.mantissa / d.mantissa * std::pow(10.0L, static_cast<long double>(n.exponent - d.exponent)));
  if (!std::isfinite(x)) file.fail(field, "value out of range");
  return x;
}

double parse_exact_rational(std::string_view text, const JsonFile& file, const std::string& field) {
  const auto slash = text.find('/');
  if (slash == std::string_view::npos) return parse_ratio(text, "1", file, field);
  return parse_ratio(text.substr(0, slash), text.substr(slash + 1), file, field);
}

}  // namespace stencil_runtime::detail
