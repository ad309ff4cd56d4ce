#include "points_file.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <stdexcept>

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

double checked_coordinate(double x, const std::string& where) {
  if (!std::isfinite(x) || std::fabs(x) > limits::kMaxCoordinate) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", x);
    throw std::runtime_error(where + ": coordinate " + text + " is not a finite number of magnitude at most 1e37");
  }
  return x;
}

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
    words.clear();
    std::size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
      std::size_t j = i;
      while (j < line.size() && !std::isspace(static_cast<unsigned char>(line[j]))) ++j;
      if (j > i) words.push_back(line.substr(i, j - i));
      i = j;
    }
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
    checked_coordinate(p[static_cast<std::size_t>(k)], where);
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

// The elements of a PLY file after its vertices (faces, say): not read, but
// the file must hold exactly what they declare, or it was cut short or its
// header does not describe it.
struct LaterProperty {
  int count_bytes = 0;  // a list's count; 0 for a single value
  int bytes = 0;
};
struct LaterElement {
  std::string name;
  std::size_t count = 0;
  std::vector<LaterProperty> properties;
};

// Bytes of a PLY scalar type; 0 for a name that is none.
int ply_type_bytes(const std::string& type) {
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" || type == "float32") return 4;
  if (type == "double" || type == "float64") return 8;
  return 0;
}

bool ply_float_type(const std::string& type) {
  return type == "float" || type == "float32" || type == "double" || type == "float64";
}

// A binary PLY file's unsigned integer of `bytes` bytes at `at`, in the
// file's byte order (big-endian: the byte at `at` is the most significant).
std::uint64_t unsigned_at(const char* at, int bytes, bool big_endian) {
  std::uint64_t n = 0;
  for (int b = 0; b < bytes; ++b) {
    const int i = big_endian ? b : bytes - 1 - b;  // most significant first
    n = (n << 8) | static_cast<unsigned char>(at[i]);
  }
  return n;
}

// A binary PLY file's float (4 bytes) or double (8) at `at`, in the file's
// byte order, whatever this machine's.
double real_at(const char* at, int bytes, bool big_endian) {
  std::array<char, 8> raw{};
  std::memcpy(raw.data(), at, static_cast<std::size_t>(bytes));
  if (big_endian != (std::endian::native == std::endian::big)) std::reverse(raw.begin(), raw.begin() + bytes);
  if (bytes == 4) {
    float f = 0;
    std::memcpy(&f, raw.data(), 4);
    return f;
  }
  double x = 0;
  std::memcpy(&x, raw.data(), 8);
  return x;
}

// Where the later elements of a binary file end, walking their lists' counts
// from `offset`; an error where the file ends first.
std::size_t later_elements_end(const std::string& path, const std::string& data, std::size_t offset,
                               const std::vector<LaterElement>& later, bool big_endian) {
  for (const LaterElement& e : later)
    for (std::size_t i = 0; i < e.count && !e.properties.empty(); ++i)  // each item takes a byte at least: bounded by the file
      for (const LaterProperty& q : e.properties) {
        const std::size_t left = data.size() - std::min(offset, data.size());
        std::size_t items = 1;
        if (q.count_bytes > 0) {
          if (left < static_cast<std::size_t>(q.count_bytes)) items = std::size_t(-1);
          else {
            // Unsigned: a signed count's negative values are huge and refused below.
            items = unsigned_at(data.data() + offset, q.count_bytes, big_endian);
            offset += static_cast<std::size_t>(q.count_bytes);
          }
        }
        const std::size_t rest = data.size() - std::min(offset, data.size());
        if (items == std::size_t(-1) || items > rest / static_cast<std::size_t>(q.bytes))
          throw std::runtime_error(path + ": truncated: the file ends within " + e.name + " " + std::to_string(i + 1) + " of " +
                                   std::to_string(e.count) + " (binary)");
        offset += items * static_cast<std::size_t>(q.bytes);
      }
  return offset;
}

std::vector<Point> read_ply(const std::string& path, const std::string& data) {
  // Header lines end in LF or (files written on Windows) CRLF, consistently.
  const bool crlf = data.compare(0, 5, "ply\r\n") == 0;
  const std::string eol = crlf ? "\r\n" : "\n";
  const std::size_t header_end = data.find("end_header" + eol);
  if (data.compare(0, 3 + eol.size(), "ply" + eol) != 0 || header_end == std::string::npos)
    throw std::runtime_error(path + ": not a PLY file (no 'ply' line or no 'end_header')");
  std::string header_text = data.substr(0, header_end);
  if (crlf) header_text.erase(std::remove(header_text.begin(), header_text.end(), '\r'), header_text.end());
  std::istringstream header(header_text);
  std::string line, format;
  std::size_t line_number = 0, count = 0;
  bool in_vertex = false, seen_vertex = false;
  struct Property {
    std::string name;
    int bytes = 0;  // 4 float, 8 double; negative: an integer of that many bytes, skipped
  };
  std::vector<Property> properties;
  std::vector<LaterElement> later;  // faces, say: not read, but the file must hold what they declare
  while (std::getline(header, line)) {
    ++line_number;
    const std::string where = path + ":" + std::to_string(line_number);
    std::istringstream words(line);
    std::string key;
    words >> key;
    if (key == "format") {
      std::string version;
      words >> format >> version;
      if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian")
        throw std::runtime_error(where + ": PLY format " + stencil_runtime::quoted_excerpt(format) +
                                 " is not one of ascii, binary_little_endian and binary_big_endian");
    } else if (key == "element") {
      std::string name, n;
      words >> name >> n;
      if (seen_vertex) {
        in_vertex = false;
        std::size_t k = 0;
        const auto [stop, err] = std::from_chars(n.data(), n.data() + n.size(), k);
        if (err != std::errc() || stop != n.data() + n.size() || k > limits::kMaxMeshElements)
          throw std::runtime_error(where + ": element " + stencil_runtime::quoted_excerpt(name) + " has no valid count");
        later.push_back({name, k, {}});
        continue;
      }
      if (name != "vertex") throw std::runtime_error(where + ": the first element must be 'vertex', got " + stencil_runtime::quoted_excerpt(name));
      {
        const auto [stop, err] = std::from_chars(n.data(), n.data() + n.size(), count);
        if (err != std::errc() || stop != n.data() + n.size() || count > limits::kMaxMeshElements)
          throw std::runtime_error(where + ": the vertex count " + stencil_runtime::quoted_excerpt(n) +
                                   " is not a number from 0 to 2^30");
      }
      in_vertex = seen_vertex = true;
    } else if (key == "property" && !seen_vertex) {
      throw std::runtime_error(where + ": a property before any element");
    } else if (key == "property" && !in_vertex) {
      std::string type, item;
      words >> type;
      LaterProperty q;
      if (type == "list") {
        std::string count_type;
        words >> count_type >> item;
        q.count_bytes = ply_type_bytes(count_type);
        if (q.count_bytes <= 0 || ply_float_type(count_type))
          throw std::runtime_error(where + ": a list's count type " + stencil_runtime::quoted_excerpt(count_type) +
                                   " is not an integer type");
      } else {
        item = type;
      }
      q.bytes = ply_type_bytes(item);
      if (q.bytes <= 0) throw std::runtime_error(where + ": unknown property type " + stencil_runtime::quoted_excerpt(item));
      later.back().properties.push_back(q);
    } else if (key == "property") {
      std::string type, name;
      words >> type >> name;
      for (const Property& q : properties)
        if (q.name == name)
          throw std::runtime_error(where + ": vertex property " + stencil_runtime::quoted_excerpt(name) + " is declared twice");
      if (type == "list") throw std::runtime_error(where + ": list properties of vertices are not supported");
      const int bytes = ply_type_bytes(type);
      if (bytes == 0) throw std::runtime_error(where + ": unknown property type " + stencil_runtime::quoted_excerpt(type));
      properties.push_back({name, ply_float_type(type) ? bytes : -bytes});  // an integer: skipped
    }
  }
  if (format.empty()) throw std::runtime_error(path + ": no 'format' line in the PLY header");
  if (!seen_vertex || count == 0) throw std::runtime_error(path + ": no points (the PLY file has no vertex element or 0 vertices)");
  int slot[3] = {-1, -1, -1};
  for (std::size_t i = 0; i < properties.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (properties[i].name == std::string(1, "xyz"[k])) {
        if (properties[i].bytes != 4 && properties[i].bytes != 8)
          throw std::runtime_error(path + ": vertex property " + properties[i].name + " must be float or double");
        slot[k] = static_cast<int>(i);
      }
  if (slot[0] < 0 || slot[1] < 0 || slot[2] < 0) throw std::runtime_error(path + ": the vertices have no x, y and z properties");

  const std::size_t body = header_end + std::strlen("end_header") + eol.size();
  // A count the file cannot hold is refused before anything is allocated: a
  // binary vertex takes its properties' bytes, an ASCII one at least two
  // bytes per value ("0 ").
  std::size_t least = 0;
  for (const Property& p : properties) least += format == "ascii" ? 2 : static_cast<std::size_t>(std::abs(p.bytes));
  const std::size_t available = data.size() > body ? data.size() - body : 0;
  if (least == 0 || count > available / least)
    throw std::runtime_error(path + ": truncated: " + std::to_string(count) + " points cannot fit in the " +
                             std::to_string(available) + " bytes after the PLY header");
  std::vector<Point> points(count);
  if (format == "ascii") {
    std::size_t start = body;
    for (std::size_t p = 0; p < count; ++p) {
      ++line_number;
      const std::string where = path + ":" + std::to_string(line_number + 1);
      if (start >= data.size()) throw std::runtime_error(where + ": the file ends after " + std::to_string(p) + " of " + std::to_string(count) + " points");
      std::size_t end = data.find('\n', start);
      if (end == std::string::npos) end = data.size();
      std::istringstream values(data.substr(start, end - start));
      start = end + 1;
      for (std::size_t i = 0; i < properties.size(); ++i) {
        std::string word;
        if (!(values >> word)) throw std::runtime_error(where + ": expected " + std::to_string(properties.size()) + " values");
        double x = 0;
        const auto [stop, err] = std::from_chars(word.data(), word.data() + word.size(), x);
        if (err != std::errc() || stop != word.data() + word.size())
          throw std::runtime_error(where + ": " + stencil_runtime::quoted_excerpt(word) + " is not a number");
        for (int k = 0; k < 3; ++k)
          if (slot[k] == static_cast<int>(i)) points[p][static_cast<std::size_t>(k)] = checked_coordinate(x, where);
      }
      std::string more;
      if (values >> more) throw std::runtime_error(where + ": more than the " + std::to_string(properties.size()) + " values the header declares");
    }
    // What follows is the later elements, a line each: more is a file whose
    // header says less than it holds, fewer one that was cut short.
    std::size_t later_lines = 0;
    for (const LaterElement& e : later) later_lines += e.properties.empty() ? 0 : e.count;  // an empty line is not counted
    std::size_t lines = 0;
    for (std::size_t at = start; at < data.size();) {
      std::size_t end = data.find('\n', at);
      if (end == std::string::npos) end = data.size();
      if (data.find_first_not_of(" \t\r", at) < end) {
        ++lines;
        if (lines > later_lines)
          throw std::runtime_error(path + ":" + std::to_string(line_number + 1 + lines) + ": more lines than the header's " +
                                   std::to_string(count) + " points" + (later.empty() ? "" : " and later elements") + " declare");
      }
      at = end + 1;
    }
    if (lines < later_lines)
      throw std::runtime_error(path + ": truncated: the file ends after " + std::to_string(lines) + " of the " +
                               std::to_string(later_lines) + " lines of the elements after the points (" + later.front().name + ", ...)");
    return points;
  }
  std::size_t stride = 0;
  for (const Property& q : properties) stride += static_cast<std::size_t>(std::abs(q.bytes));
  if ((data.size() - body) / stride < count)
    throw std::runtime_error(path + ": truncated: " + std::to_string(count) + " points of " + std::to_string(stride) +
                             " bytes need more than the file holds");
  const bool big_endian = format == "binary_big_endian";
  const std::size_t end = later_elements_end(path, data, body + count * stride, later, big_endian);
  if (end != data.size())
    throw std::runtime_error(path + ": " + std::to_string(data.size() - end) + " bytes after the " + std::to_string(count) +
                             " points the header declares" + (later.empty() ? " (and no further element)" : " and the elements after them"));
  for (std::size_t p = 0; p < count; ++p) {
    std::size_t offset = body + p * stride;
    for (std::size_t i = 0; i < properties.size(); ++i) {
      const int bytes = std::abs(properties[i].bytes);
      for (int k = 0; k < 3; ++k)
        if (slot[k] == static_cast<int>(i)) {
          const double x = real_at(data.data() + offset, bytes, big_endian);
          points[p][static_cast<std::size_t>(k)] =
              checked_coordinate(x, path + ": point " + std::to_string(p + 1) + " of " + std::to_string(count) + " (binary)");
        }
      offset += static_cast<std::size_t>(bytes);
    }
  }
  return points;
}

}  // namespace

std::vector<Point> read_points(const std::string& path) {
  const std::string text = read_text_file(path, kMaxPointsFileBytes);
  const std::string ext = stencil_runtime::lowercase_extension(path);
  if (ext == ".ply") return read_ply(path, text);
  if (ext == ".off") return read_off(path, text);
  return read_xyz(path, text);
}

}  // namespace stencil_tools
