#include "common/scheme_registry.hpp"

#include <algorithm>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "common/read_file.hpp"
#include "common/scheme_file.hpp"

namespace sg {
namespace fs = std::filesystem;
using nlohmann::json;

fs::path default_schemes_dir() {
  if (const char* env = std::getenv("STENCILGEN_SCHEMES_DIR"); env && *env) return env;
  return STENCILGEN_SCHEMES_DIR;
}

std::vector<std::string> available_schemes(const fs::path& dir, SchemeFamily family) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    if (entry.path().extension() != ".json") continue;
    if (family != SchemeFamily::Any) {
      std::string type;
      try {
        type = json::parse(read_file(entry.path())).value("type", "");
      } catch (const std::exception&) {
        continue;  // unreadable files belong to no family; loading them reports why
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
  const fs::path file = is_path ? fs::path(spec) : dir / (spec + ".json");
  if (!fs::is_regular_file(file)) {
    if (is_path) throw Error(spec + ": no such scheme file");
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
