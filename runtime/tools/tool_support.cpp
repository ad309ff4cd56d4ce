#include "stencil_runtime/error.hpp"
#include "tool_support.hpp"

#include "mesh/file_output.hpp"
#include "stencil_runtime/tables.hpp"

#include <glob.h>

#include <unistd.h>
#include <cerrno>
#include <cstring>
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <new>
#include <set>
#include <tuple>

namespace stencil_tools {

namespace fs = std::filesystem;

namespace {

// `--out ""` would otherwise mean "no file" to a tool whose default is
// standard output, and an unnamed file to the others.
void check_no_empty_values(const CLI::App& app) {
  for (const CLI::Option* o : app.get_options())
    if (o->get_type_size_max() > 0)
      for (const std::string& value : o->results())
        if (value.empty()) throw CLI::ValidationError(o->get_name() + ": an empty value");
  for (const CLI::App* sub : app.get_subcommands()) check_no_empty_values(*sub);
}

}  // namespace

int run_tool(CLI::App& app, int argc, char** argv, const std::function<int()>& body) {
  const std::string name = app.get_name();
  try {
    try {
      app.parse(argc, argv);
      check_no_empty_values(app);
    } catch (const CLI::CallForHelp& e) {
      return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
      return app.exit(e);
    } catch (const CLI::ParseError& e) {
      std::cerr << name << ": error: " << e.what() << " (see --help)\n";
      return 1;
    }
    return body();
  } catch (const std::bad_alloc&) {
    std::cerr << name << ": error: out of memory\n";
  } catch (const std::exception& e) {
    std::cerr << name << ": error: " << e.what() << "\n";
  } catch (...) {
    std::cerr << name << ": error: unknown failure\n";
  }
  return 1;
}

bool same_tags(const stencil_runtime::MeshTags& a, const stencil_runtime::MeshTags& b) {
  auto creases = [](const stencil_runtime::MeshTags& t) {
    std::vector<std::tuple<int, int, double>> out;
    for (const auto& c : t.creases)
      if (c.sharpness > 0) out.emplace_back(std::min(c.a, c.b), std::max(c.a, c.b), c.sharpness);
    std::sort(out.begin(), out.end());
    return out;
  };
  auto corners = [](const stencil_runtime::MeshTags& t) {
    std::vector<std::pair<int, double>> out;
    for (const auto& c : t.corners)
      if (c.sharpness > 0) out.emplace_back(c.vertex, c.sharpness);
    std::sort(out.begin(), out.end());
    return out;
  };
  auto holes = [](const stencil_runtime::MeshTags& t) {
    std::vector<int> out;
    for (const auto& h : t.holes) out.push_back(h.face);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  };
  return creases(a) == creases(b) && corners(a) == corners(b) && holes(a) == holes(b) && a.boundary == b.boundary &&
         a.chaikin_creases == b.chaikin_creases && a.smooth_triangles == b.smooth_triangles;
}

bool untagged(const stencil_runtime::MeshTags& tags) { return same_tags(tags, stencil_runtime::MeshTags{}); }

std::string read_text_file(const std::string& path, std::size_t max_bytes) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) throw std::runtime_error(path + ": cannot open (no such file)");
  if (!fs::is_regular_file(status)) throw std::runtime_error(path + ": not a regular file");
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) throw std::runtime_error(path + ": cannot read its size: " + ec.message());
  if (size > max_bytes) throw std::runtime_error(path + ": " + std::to_string(size) + " bytes; the limit is " + std::to_string(max_bytes));
  std::ifstream in(path, std::ios::binary);
  std::string text(static_cast<std::size_t>(size), '\0');
  if (!in.read(text.data(), static_cast<std::streamsize>(size))) throw std::runtime_error(path + ": read failed");
  if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) text.erase(0, 3);  // a UTF-8 byte-order mark (Windows editors)
  return text;
}

void write_text_file(const std::string& path, const std::string& text) {
  stencil_runtime::write_file_atomically(path, [&](FILE* f) { std::fwrite(text.data(), 1, text.size(), f); });
}

ParameterText parse_parameter(const std::string& text) {
  ParameterText p;
  if (text.find_first_of(".eEnN") == std::string::npos) {
    p.fraction = stencil_runtime::parse_fraction(text);
    p.value = p.fraction.to_double();
    return p;
  }
  p.exact = false;
  // One leading '+', as the rationals take it (from_chars does not).
  const bool plus = text.size() > 1 && text[0] == '+' && (std::isdigit(static_cast<unsigned char>(text[1])) || text[1] == '.');
  const char* end = text.data() + text.size();
  const auto [stop, err] = std::from_chars(text.data() + (plus ? 1 : 0), end, p.value);
  if (err != std::errc() || stop != end || !std::isfinite(p.value))
    throw std::runtime_error("parameter " + stencil_runtime::quoted_excerpt(text) + " is neither an exact rational such as 1/3 nor a finite decimal such as 0.3");
  return p;
}

std::pair<std::string, std::string> split_pair(const std::string& text, const std::string& option) {
  const auto comma = text.find(',');
  if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos)
    throw std::runtime_error(option + " expects U,V such as 1/3,1/2 or 0.3,0.7; got " + stencil_runtime::quoted_excerpt(text));
  return {text.substr(0, comma), text.substr(comma + 1)};
}

std::size_t parse_index(const std::string& text, const std::string& what) {
  std::uint64_t value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, err] = std::from_chars(text.data(), end, value);
  if (text.empty() || err != std::errc() || stop != end)
    throw std::runtime_error(what + " " + stencil_runtime::quoted_excerpt(text) + " is not a number 0, 1, 2, ... (numbered from 0)");
  return static_cast<std::size_t>(value);
}

void check_frame_pattern(const std::string& pattern) {
  int conversions = 0;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] != '%') continue;
    if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
      ++i;
      continue;
    }
    std::size_t j = i + 1;
    if (j < pattern.size() && pattern[j] == '0') ++j;
    std::size_t digits = 0;
    while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j]))) ++j, ++digits;
    if (j >= pattern.size() || pattern[j] != 'd' || digits > 2)
      throw std::runtime_error("output pattern " + stencil_runtime::quoted_excerpt(pattern) + ": only %d, %0Nd or %Nd (N < 100) and %% are allowed");
    ++conversions;
    i = j;
  }
  if (conversions != 1)
    throw std::runtime_error("output pattern " + stencil_runtime::quoted_excerpt(pattern) + " needs exactly one frame number such as %04d");
}

std::string frame_name(const std::string& pattern, std::size_t frame) {
  check_frame_pattern(pattern);
  const int size = std::snprintf(nullptr, 0, pattern.c_str(), static_cast<int>(frame));
  std::string out(static_cast<std::size_t>(size) + 1, '\0');
  std::snprintf(out.data(), out.size(), pattern.c_str(), static_cast<int>(frame));
  out.resize(static_cast<std::size_t>(size));
  return out;
}

std::vector<std::string> expand_pattern(const std::string& pattern) {
  glob_t found{};
  const int status = ::glob(pattern.c_str(), GLOB_ERR, nullptr, &found);
  std::vector<std::string> out;
  if (status == 0)
    for (std::size_t k = 0; k < found.gl_pathc; ++k) out.emplace_back(found.gl_pathv[k]);
  ::globfree(&found);
  if (status == GLOB_NOMATCH || out.empty()) throw std::runtime_error(stencil_runtime::quoted_excerpt(pattern) + " names no file");
  if (status != 0) throw std::runtime_error(stencil_runtime::quoted_excerpt(pattern) + ": cannot list the files it names");
  std::sort(out.begin(), out.end());
  return out;
}

void check_output_is_not_input(const std::string& output, const std::vector<std::string>& inputs,
                               const std::vector<std::string>& folders) {
  check_outputs_are_not_inputs({output}, inputs, folders);
}

namespace {

// The path with its links resolved where they can be (its file need not
// exist); where they cannot (a loop of links, /dev/stdout), the path made
// absolute, so that the comparison below still sees "./a" and "a" as one.
fs::path resolved(const std::string& path) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(path, ec);
  if (ec) p = fs::absolute(path, ec).lexically_normal();
  return p;
}

bool inside(const fs::path& path, const fs::path& folder) {
  auto f = folder.begin(), p = path.begin();
  for (; f != folder.end() && !f->empty(); ++f, ++p)
    if (p == path.end() || *p != *f) return false;
  return true;
}

}  // namespace

bool same_path(const std::string& a, const std::string& b) { return !a.empty() && !b.empty() && resolved(a) == resolved(b); }

void check_outputs_are_not_inputs(const std::vector<std::string>& outputs, const std::vector<std::string>& inputs,
                                  const std::vector<std::string>& folders) {
  // Each path resolved once: an animation checks a million frames against a million inputs.
  std::set<fs::path> read;
  for (const std::string& input : inputs)
    if (!input.empty()) read.insert(resolved(input));
  std::vector<std::pair<fs::path, std::string>> read_whole;
  for (const std::string& folder : folders)
    if (!folder.empty()) read_whole.emplace_back(resolved(folder), folder);
  for (const std::string& output : outputs) {
    if (output.empty()) continue;
    const fs::path written = resolved(output);
    if (read.count(written)) throw std::runtime_error(output + " is an input and the output; give the output another name");
    for (const auto& [folder, given] : read_whole)
      if (inside(written, folder))
        throw std::runtime_error(output + " is inside " + given + ", a folder of tables read whole; write the output elsewhere");
  }
}

TableInput table_input(const std::string& spec) {
  const std::string path = stencil_runtime::Tables::file_of(spec);
  std::error_code ec;
  if (fs::is_directory(path, ec)) return {"", path};
  return {path, ""};
}

void check_output_can_be_written(const std::string& output) {
  if (output.empty()) return;
  const fs::path path(stencil_runtime::output_file(output));  // a directory, device or FIFO refused
  std::error_code ec;
  const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
  if (!fs::exists(folder, ec)) throw std::runtime_error(output + ": cannot be written: its folder " + folder.string() + " does not exist");
  if (!fs::is_directory(folder, ec)) throw std::runtime_error(output + ": cannot be written: " + folder.string() + " is not a folder");
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    throw std::runtime_error(output + ": cannot be written: " + folder.string() + ": " + std::strerror(errno));
}

void BoundaryOption::add(CLI::App& app) {
  app.add_option("--boundary", text,
                 "meshes with boundaries, as OpenSubdiv: edge-only (default, as its tools), edge-and-corner (a boundary "
                 "vertex in one face is a corner) or none (faces at boundary vertices have no surface, like holes); "
                 "overrides the mesh's `t interpolateboundary` tag")
      ->check(CLI::IsMember({"none", "edge-only", "edge-and-corner"}));
}

void BoundaryOption::apply(stencil_runtime::Mesh& mesh) const {
  using stencil_runtime::BoundaryInterpolation;
  if (text.empty()) return;
  mesh.tags.boundary = text == "none"        ? BoundaryInterpolation::None
                       : text == "edge-only" ? BoundaryInterpolation::EdgeOnly
                                             : BoundaryInterpolation::EdgeAndCorner;
}

}  // namespace stencil_tools
