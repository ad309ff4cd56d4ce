#include "points_file.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "mesh/coordinates.hpp"
#include "mesh/line_tokens.hpp"
#include "mesh/ply_input.hpp"
#include "stencil_runtime/error.hpp"
#include "stencil_runtime/limits.hpp"
#include "stencil_runtime/mesh_io.hpp"
#include "tool_support.hpp"

namespace stencil_tools {

namespace {

using stencil_runtime::Point;
namespace limits = stencil_runtime::limits;

// Points files are limited like meshes (limits.hpp).
constexpr std::size_t kMaxPointsFileBytes = std::size_t{4} << 30;

using stencil_runtime::checked_file_coordinate;

// The text's lines in order, without comments ('#' to the end of the line),
// split into words; blank lines are skipped. `each` gets the line number too.
template <class Each>
void for_each_line(const std::string& text, Each each) {
  std::size_t line_number = 0, start = 0;
  std::vector<std::string_view> words;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string_view line(text.data() + start, end - start);
    start = end + 1;
    ++line_number;
    if (const auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    words = stencil_runtime::detail::split_words(line);
    if (!words.empty() && !each(line_number, words)) return;
  }
}

Point parse_point(const std::vector<std::string_view>& words, const std::string& where) {
  Point p{};
  for (int k = 0; k < 3; ++k) {
    const auto w = words[static_cast<std::size_t>(k)];
    const auto [stop, err] = std::from_chars(w.data(), w.data() + w.size(), p[static_cast<std::size_t>(k)]);
    if (err != std::errc() || stop != w.data() + w.size())
      throw std::runtime_error(where + ": " + stencil_runtime::quoted_excerpt(w) + " is not a number");
    checked_file_coordinate(p[static_cast<std::size_t>(k)], where);
  }
  return p;
}

std::vector<Point> read_xyz(const std::string& path, const std::string& text) {
  std::vector<Point> points;
  for_each_line(text, [&](std::size_t line, const std::vector<std::string_view>& words) {
    const std::string where = path + ":" + std::to_string(line);
    // `x y z`, or `x y z nx ny nz` as scanners write it (the normal is not used, but checked).
    if (words.size() != 3 && words.size() != 6)
      throw std::runtime_error(where + ": expected three numbers `x y z` (or six, with a normal), got " +
                               std::to_string(words.size()) + " columns");
    if (words.size() == 6) parse_point({words.begin() + 3, words.end()}, where);
    points.push_back(parse_point(words, where));
    return true;
  });
  if (points.empty()) throw std::runtime_error(path + ": no points (expected lines `x y z`)");
  return points;
}

// OFF: the line `OFF`, then `vertices faces edges`, then one `x y z` line per
// vertex (the faces that follow are not read).
std::vector<Point> read_off(const std::string& path, const std::string& text) {
  std::vector<Point> points;
  std::size_t expected = 0, faces = 0, face_lines = 0;
  int stage = 0;  // 0: the OFF line, 1: the counts, 2: vertices, 3: faces (counted, not read)
  for_each_line(text, [&](std::size_t line, const std::vector<std::string_view>& words) {
    const std::string where = path + ":" + std::to_string(line);
    if (stage == 0) {
      if (words.size() != 1 || words[0] != "OFF")
        throw std::runtime_error(where + ": not an OFF file (its first line must be `OFF` alone)");
      stage = 1;
      return true;
    }
    if (stage == 1) {
      if (words.size() != 3)
        throw std::runtime_error(where + ": expected the counts `vertices faces edges`, got " +
                                 std::to_string(words.size()) + " columns");
      const auto w = words[0];
      const auto [stop, err] = std::from_chars(w.data(), w.data() + w.size(), expected);
      if (err != std::errc() || stop != w.data() + w.size() || expected == 0 || expected > limits::kMaxMeshElements)
        throw std::runtime_error(where + ": the vertex count " + stencil_runtime::quoted_excerpt(w) +
                                 " is not a number from 1 to " + std::to_string(limits::kMaxMeshElements));
      // Each vertex line takes at least 6 bytes ("0 0 0\n"): a count the file cannot hold is refused before any allocation.
      if (expected > text.size() / 6)
        throw std::runtime_error(where + ": " + std::to_string(expected) + " vertices cannot fit in a file of " +
                                 std::to_string(text.size()) + " bytes");
      const auto f = words[1];
      const auto [fstop, ferr] = std::from_chars(f.data(), f.data() + f.size(), faces);
      if (ferr != std::errc() || fstop != f.data() + f.size() || faces > limits::kMaxMeshElements)
        throw std::runtime_error(where + ": the face count " + stencil_runtime::quoted_excerpt(f) + " is not a number from 0 to " +
                                 std::to_string(limits::kMaxMeshElements));
      points.reserve(expected);
      stage = 2;
      return true;
    }
    if (stage == 3) {  // a face per line: more is a file whose header says less than it holds
      if (++face_lines > faces)
        throw std::runtime_error(where + ": more lines than the header's " + std::to_string(expected) + " vertices and " +
                                 std::to_string(faces) + " faces declare");
      return true;
    }
    if (words.size() < 3)
      throw std::runtime_error(where + ": expected a vertex `x y z`, got " + std::to_string(words.size()) + " columns");
    points.push_back(parse_point(words, where));
    if (points.size() == expected) stage = 3;
    return true;
  });
  if (stage == 0) throw std::runtime_error(path + ": the file is empty (an OFF file starts with a line `OFF`)");
  if (stage == 1) throw std::runtime_error(path + ": the file ends before its counts line `vertices faces edges`");
  if (points.size() < expected)
    throw std::runtime_error(path + ": the file ends after " + std::to_string(points.size()) + " of " +
                             std::to_string(expected) + " vertices");
  if (face_lines < faces)
    throw std::runtime_error(path + ": truncated: the file ends after " + std::to_string(face_lines) + " of the " +
                             std::to_string(faces) + " faces its header declares");
  return points;
}

}  // namespace

std::vector<Point> read_points(const std::string& path) {
  const std::string text = read_text_file(path, kMaxPointsFileBytes);
  const std::string ext = stencil_runtime::lowercase_extension(path);
  if (ext == ".ply") return stencil_runtime::detail::read_ply(path, text, false).points;  // the library's PLY reader
  if (ext == ".off") return read_off(path, text);
  return read_xyz(path, text);
}

}  // namespace stencil_tools
