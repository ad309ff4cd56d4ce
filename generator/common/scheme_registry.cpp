#include "common/scheme_registry.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "base/limits.hpp"
#include "common/scheme_file.hpp"

namespace sg {
namespace fs = std::filesystem;
using nlohmann::json;

fs::path default_schemes_dir() {
  if (const char* env = std::getenv("STENCILGEN_SCHEMES_DIR"); env && *env) return env;
  return STENCILGEN_SCHEMES_DIR;
}

const char* const kSchemeNameRule =
    "letters, digits, '-' and '_', starting with a letter or digit, at most 64 characters";
static_assert(limits::kMaxNameLength == 64, "kSchemeNameRule states the limit");

bool is_scheme_name(const std::string& name) {
  if (name.empty() || static_cast<long>(name.size()) > limits::kMaxNameLength) return false;
  if (!std::isalnum(static_cast<unsigned char>(name[0]))) return false;
  for (char c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') return false;
  return true;
}

std::vector<std::string> available_schemes(const fs::path& dir, SchemeFamily family) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    if (entry.path().extension() != ".json") continue;
    if (family != SchemeFamily::Any) {
      std::string type;
      try {
        const SchemeContext ctx(entry.path().string());
        type = read_scheme_document(entry.path(), ctx).at("type").get<std::string>();
      } catch (const Error&) {
        continue;  // unreadable or invalid files belong to no family; loading them reports why
      }
      const SchemeFamily of = type == "quad" ? SchemeFamily::Quad : type == "triangle" ? SchemeFamily::Triangle : SchemeFamily::Curve;
      if (of != family) continue;
    }
    names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

fs::path resolve_scheme_file(const std::string& spec, const fs::path& dir) {
  if (spec.empty()) throw Error("empty scheme name");
  const bool is_path = spec.find('/') != std::string::npos || spec.ends_with(".json");
  if (!is_path && !is_scheme_name(spec))
    throw Error("'" + excerpt(spec) + "' is neither a scheme name (" + kSchemeNameRule +
                ") nor a path to a scheme file (containing '/' or ending in .json)");
  const fs::path file = is_path ? fs::path(spec) : dir / (spec + ".json");
  std::error_code ec;
  const bool found = fs::is_regular_file(file, ec);
  if (ec && ec != std::errc::no_such_file_or_directory) throw Error(excerpt(spec) + ": " + ec.message());
  if (!found) {
    if (is_path) throw Error(excerpt(spec) + ": no such scheme file");
    std::string list;
    for (const auto& n : available_schemes(dir)) list += (list.empty() ? "" : ", ") + n;
    throw Error("unknown scheme '" + spec + "' (no " + file.string() + "); available: " + list);
  }
  return file;
}

std::string scheme_type(const std::string& spec, const fs::path& dir) {
  const fs::path file = resolve_scheme_file(spec, dir);
  const SchemeContext ctx(file.string());
  return read_scheme_document(file, ctx).at("type").get<std::string>();
}

}  // namespace sg
