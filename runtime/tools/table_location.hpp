#pragma once
// Shared by the runtime's command-line tools: finding the table file behind
// --tables, and parsing exact parameters like "1/3".
#include <filesystem>
#include <numeric>
#include <stdexcept>
#include <string>

namespace stencil_tools {

// --tables is a table file (.sgs for a quad scheme, .sgt for a triangle
// scheme), a directory holding exactly one (e.g. tables/nonpoly), or a
// directory of exact quad JSON tables only (loaded from JSON, slower).
inline std::filesystem::path find_table_file(const std::string& spec) {
  namespace fs = std::filesystem;
  fs::path p = fs::path(spec).lexically_normal();
  if (p.filename().empty()) p = p.parent_path();  // "tables/nonpoly/"; the scheme name is the last component
  if (fs::is_regular_file(p)) return p;
  if (!fs::is_directory(p)) throw std::runtime_error(spec + ": no such table file or directory");
  fs::path found;
  for (const auto& e : fs::directory_iterator(p))
    if (e.path().extension() == ".sgs" || e.path().extension() == ".sgt") {
      if (!found.empty()) throw std::runtime_error(spec + ": holds several table files (.sgs, .sgt); name one");
      found = e.path();
    }
  if (found.empty() && fs::is_directory(p / "regular")) return p;  // JSON tables
  if (found.empty())
    throw std::runtime_error(spec + ": no .sgs or .sgt table file here (make one with: stencilgen --scheme nonpoly "
                                    "--valence 3-8 --n 24 --out tables, or --scheme loop)");
  return found;
}

// A triangle-scheme table (Loop, sqrt(3)) rather than a quad one.
inline bool is_triangle_table(const std::filesystem::path& file) { return file.extension() == ".sgt"; }

struct Fraction {
  long num = 0, den = 1;
};

// "1/3", "0", "1", "2/4" (reduced); must lie in [0, 1].
inline Fraction parse_parameter(const std::string& text) {
  Fraction f;
  try {
    std::size_t used = 0;
    f.num = std::stol(text, &used);
    if (used < text.size()) {
      if (text[used] != '/') throw std::invalid_argument(text);
      const std::string rest = text.substr(used + 1);
      f.den = std::stol(rest, &used);
      if (used != rest.size()) throw std::invalid_argument(text);
    }
  } catch (const std::exception&) {
    throw std::runtime_error("parameter '" + text + "' is not an exact rational such as 1/3");
  }
  if (f.den <= 0) throw std::runtime_error("parameter '" + text + "' has a zero or negative denominator");
  const long g = std::gcd(f.num, f.den);
  f.num /= g, f.den /= g;
  if (f.num < 0 || f.num > f.den) throw std::runtime_error("parameter '" + text + "' is outside [0, 1]");
  return f;
}

}  // namespace stencil_tools
