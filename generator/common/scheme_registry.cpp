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

std::vector<SchemeEntry> scheme_catalogue(const fs::path& dir) {
  std::vector<SchemeEntry> entries;
  std::error_code ec;
  fs::directory_iterator it(dir, ec);
  const auto unreadable = [&dir](const std::error_code& e) {
    return Error("schemes directory " + dir.string() + ": " + e.message() +
                 " (STENCILGEN_SCHEMES_DIR, when set, names the folder that holds the scheme files)");
  };
  if (ec) throw unreadable(ec);
  for (; it != fs::directory_iterator(); it.increment(ec)) {
    if (ec) throw unreadable(ec);
    if (it->path().extension() != ".json") continue;
    SchemeEntry entry;
    entry.name = it->path().stem().string();
    try {
      const SchemeContext ctx(it->path().string());
      const json doc = read_scheme_document(it->path(), ctx);
      const std::string type = doc.at("type").get<std::string>();
      entry.family = type == "quad" ? SchemeFamily::Quad : type == "triangle" ? SchemeFamily::Triangle : SchemeFamily::Curve;
      check_scheme_file_name(entry.name, doc.at("name").get<std::string>(), it->path());
    } catch (const std::exception& e) {
      entry.family = SchemeFamily::Any;
      entry.problem = e.what();
    }
    entries.push_back(std::move(entry));
  }
  if (ec) throw unreadable(ec);
  std::sort(entries.begin(), entries.end(), [](const SchemeEntry& a, const SchemeEntry& b) { return a.name < b.name; });
  return entries;
}

std::vector<std::string> available_schemes(const fs::path& dir, SchemeFamily family) {
  std::vector<std::string> names;
  for (const SchemeEntry& entry : scheme_catalogue(dir))
    if (entry.problem.empty() && (family == SchemeFamily::Any || entry.family == family)) names.push_back(entry.name);
  return names;
}

namespace {

// A `--scheme` argument naming a file rather than a scheme in the directory.
bool is_scheme_path(const std::string& spec) { return spec.find('/') != std::string::npos || spec.ends_with(".json"); }

}  // namespace

fs::path resolve_scheme_file(const std::string& spec, const fs::path& dir) {
  if (spec.empty()) throw Error("empty scheme name");
  const bool is_path = is_scheme_path(spec);
  if (!is_path && !is_scheme_name(spec))
    throw Error("'" + excerpt(spec) + "' is neither a scheme name (" + kSchemeNameRule +
                ") nor a path to a scheme file (containing '/' or ending in .json)");
  const fs::path file = is_path ? fs::path(spec) : dir / (spec + ".json");
  std::error_code ec;
  const bool found = fs::is_regular_file(file, ec);
  if (ec && ec != std::errc::no_such_file_or_directory) throw Error(excerpt(spec) + ": " + ec.message());
  if (!found) {
    if (fs::exists(file, ec)) throw Error(excerpt(spec) + ": not a regular file (a scheme file is a JSON file)");
    if (is_path) throw Error(excerpt(spec) + ": no such scheme file");
    std::string list;
    for (const auto& n : available_schemes(dir)) list += (list.empty() ? "" : ", ") + n;
    throw Error("unknown scheme '" + spec + "' (no " + file.string() + "); available: " + list);
  }
  return file;
}

void check_scheme_file_name(const std::string& spec, const std::string& name, const fs::path& file) {
  if (is_scheme_path(spec) || name == spec) return;
  throw Error(file.string() + ": name: '" + excerpt(name) + "' differs from the file's name '" + excerpt(spec) +
              "' (the scheme is found by its file's name and its tables are named by this field: make them agree)");
}

std::string scheme_type(const std::string& spec, const fs::path& dir) {
  const fs::path file = resolve_scheme_file(spec, dir);
  const SchemeContext ctx(file.string());
  return read_scheme_document(file, ctx).at("type").get<std::string>();
}

}  // namespace sg
