#include "json_directory.hpp"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <map>

#include "fuzz_support.hpp"

namespace fuzz {

namespace fs = std::filesystem;

namespace {

// The fixture's files (relative path -> bytes), read once.
const std::map<std::string, std::string>& fixture_files() {
  static const std::map<std::string, std::string> files = [] {
    std::map<std::string, std::string> out;
    const fs::path root = fixtures_dir() / "nonpoly-json";
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
      if (!entry.is_regular_file()) continue;
      std::ifstream in(entry.path(), std::ios::binary);
      out[fs::relative(entry.path(), root).generic_string()] = {std::istreambuf_iterator<char>(in), {}};
    }
    if (out.empty()) harness_failure("no fixture files under " + root.string());
    return out;
  }();
  return files;
}

bool acceptable_path(std::string_view path) {
  int components = 0;
  std::size_t start = 0;
  while (start <= path.size()) {
    const std::size_t slash = std::min(path.find('/', start), path.size());
    const std::string_view part = path.substr(start, slash - start);
    if (part.empty() || part.size() > 32 || part == "." || part == ".." || ++components > 3) return false;
    if (!std::all_of(part.begin(), part.end(), [](char c) {
          return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '_' ||
                 c == '+' || c == '-';
        }))
      return false;
    start = slash + 1;
  }
  return true;
}

// The input's sections: path -> content (a later section for the same path wins).
std::map<std::string, std::string> sections(std::string_view input, const std::string& default_file) {
  static constexpr std::string_view kHeader = "@@ ", kNextHeader = "\n@@ ";
  if (!input.starts_with(kHeader)) return {{default_file, std::string(input)}};
  std::map<std::string, std::string> out;
  std::size_t at = 0;
  while (at < input.size()) {
    const std::size_t line_end = std::min(input.find('\n', at), input.size());
    const std::string_view path = input.substr(at + kHeader.size(), line_end - at - kHeader.size());
    const std::size_t body = std::min(line_end + 1, input.size());
    const std::size_t next = std::min(input.find(kNextHeader, line_end), input.size());
    const std::size_t body_end = std::max(body, next);
    if (acceptable_path(path)) out[std::string(path)] = std::string(input.substr(body, body_end - body));
    at = next == input.size() ? next : next + 1;
  }
  return out;
}

}  // namespace

std::string json_table_directory(std::string_view input, const std::string& default_file) {
  const fs::path dir = scratch_dir() / "tables";
  fs::remove_all(dir);
  std::map<std::string, std::string> files = fixture_files();
  for (auto& [path, content] : sections(input, default_file)) files[path] = std::move(content);
  for (const auto& [path, content] : files) {
    const fs::path file = dir / path;
    std::error_code ec;
    fs::create_directories(file.parent_path(), ec);
    if (ec || fs::is_directory(file)) continue;  // the input names a path both as a file and as a directory
    write_file(file, content);
  }
  return dir.string();
}

}  // namespace fuzz
