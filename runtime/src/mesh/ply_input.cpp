#include "ply_input.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

#include "coordinates.hpp"
#include "line_tokens.hpp"
#include "mesh_file.hpp"
#include "stencil_runtime/error.hpp"
#include "stencil_runtime/limits.hpp"
#include "stencil_runtime/mesh_io.hpp"

namespace stencil_runtime::detail {

namespace {

using detail::split_words;


// Bytes of a PLY scalar type; 0 for a name that is none.
int type_bytes(const std::string& type) {
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" || type == "float32") return 4;
  if (type == "double" || type == "float64") return 8;
  return 0;
}
bool float_type(const std::string& type) { return type == "float" || type == "float32" || type == "double" || type == "float64"; }
bool signed_type(const std::string& type) {
  return type == "char" || type == "int8" || type == "short" || type == "int16" || type == "int" || type == "int32";
}

// A binary file's unsigned integer of `bytes` bytes at `at`, in the file's
// byte order (big-endian: the byte at `at` is the most significant).
std::uint64_t unsigned_at(const char* at, int bytes, bool big_endian) {
  std::uint64_t n = 0;
  for (int b = 0; b < bytes; ++b) {
    const int i = big_endian ? b : bytes - 1 - b;  // most significant first
    n = (n << 8) | static_cast<unsigned char>(at[i]);
  }
  return n;
}
// The same, signed (two's complement).
long long signed_at(const char* at, int bytes, bool big_endian) {
  const std::uint64_t n = unsigned_at(at, bytes, big_endian);
  const std::uint64_t sign = std::uint64_t{1} << (8 * bytes - 1);
  return n & sign ? static_cast<long long>(n) - static_cast<long long>(sign << 1) : static_cast<long long>(n);
}
// A float (4 bytes) or double (8) at `at`, in the file's byte order, whatever this machine's.
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

struct Property {
  std::string name;
  std::string type;  // a list's item type
  int bytes = 0;
  int count_bytes = 0;  // a list's count; 0 for a single value
  bool is_signed = false;
};
struct Element {
  std::string name;
  std::size_t count = 0;
  std::vector<Property> properties;
  int face_list = -1;  // the property that lists a face's vertices (element `face` only)
};

// The next line from `at` (without '\n', '\r' or a comment), advancing `at`
// and `number`; false at the end of the data.
bool next_text_line(const std::string& data, std::size_t& at, long& number, std::string_view& line) {
  if (at >= data.size()) return false;
  std::size_t end = data.find('\n', at);
  if (end == std::string::npos) end = data.size();
  line = std::string_view(data).substr(at, end - at);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  at = end + 1;
  ++number;
  return true;
}

bool is_number(std::string_view w) {
  double x = 0;
  return real_number(w, x);
}

}  // namespace

PlyContent read_ply(const std::string& path, const std::string& data, bool faces) {
  // Header lines end in LF or (files written on Windows) CRLF, consistently.
  const bool crlf = data.compare(0, 5, "ply\r\n") == 0;
  const std::string eol = crlf ? "\r\n" : "\n";
  const std::size_t header_end = data.find("end_header" + eol);
  if (data.compare(0, 3 + eol.size(), "ply" + eol) != 0 || header_end == std::string::npos)
    throw LoadError(path + ": not a PLY file (no 'ply' line or no 'end_header')");
  std::string header_text = data.substr(0, header_end);
  if (crlf) header_text.erase(std::remove(header_text.begin(), header_text.end(), '\r'), header_text.end());
  std::istringstream header(header_text);
  std::string line, format;
  long line_number = 0;
  std::size_t count = 0;
  bool in_vertex = false, seen_vertex = false;
  std::vector<Property> properties;  // the vertex's
  std::vector<Element> later;        // faces, say: walked so that the file must hold what they declare
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
        throw LoadError(where + ": PLY format " + quoted_excerpt(format) +
                        " is not one of ascii, binary_little_endian and binary_big_endian");
    } else if (key == "element") {
      std::string name, n;
      words >> name >> n;
      if (seen_vertex) {
        in_vertex = false;
        std::size_t k = 0;
        const auto [stop, err] = std::from_chars(n.data(), n.data() + n.size(), k);
        if (err != std::errc() || stop != n.data() + n.size() || k > limits::kMaxMeshElements)
          throw LoadError(where + ": element " + quoted_excerpt(name) + " has no valid count");
        later.push_back({name, k, {}, -1});
        continue;
      }
      if (name != "vertex") throw LoadError(where + ": the first element must be 'vertex', got " + quoted_excerpt(name));
      const auto [stop, err] = std::from_chars(n.data(), n.data() + n.size(), count);
      if (err != std::errc() || stop != n.data() + n.size() || count > limits::kMaxMeshElements)
        throw LoadError(where + ": the vertex count " + quoted_excerpt(n) + " is not a number from 0 to 2^30");
      in_vertex = seen_vertex = true;
    } else if (key == "property" && !seen_vertex) {
      throw LoadError(where + ": a property before any element");
    } else if (key == "property" && !in_vertex) {
      std::string type, item, name;
      words >> type;
      Property q;
      if (type == "list") {
        std::string count_type;
        words >> count_type >> item;
        q.count_bytes = type_bytes(count_type);
        if (q.count_bytes <= 0 || float_type(count_type))
          throw LoadError(where + ": a list's count type " + quoted_excerpt(count_type) + " is not an integer type");
      } else {
        item = type;
      }
      words >> name;
      q.name = name, q.type = item, q.bytes = type_bytes(item), q.is_signed = signed_type(item);
      if (q.bytes <= 0) throw LoadError(where + ": unknown property type " + quoted_excerpt(item));
      Element& e = later.back();
      if (e.name == "face" && q.count_bytes > 0 && (name == "vertex_indices" || name == "vertex_index")) {
        if (float_type(item)) throw LoadError(where + ": a face's vertex indices must be integers, not " + quoted_excerpt(item));
        if (e.face_list >= 0) throw LoadError(where + ": the faces list their vertices twice");
        e.face_list = static_cast<int>(e.properties.size());
      }
      e.properties.push_back(q);
    } else if (key == "property") {
      std::string type, name;
      words >> type >> name;
      for (const Property& q : properties)
        if (q.name == name) throw LoadError(where + ": vertex property " + quoted_excerpt(name) + " is declared twice");
      if (type == "list") throw LoadError(where + ": list properties of vertices are not supported");
      const int bytes = type_bytes(type);
      if (bytes == 0) throw LoadError(where + ": unknown property type " + quoted_excerpt(type));
      properties.push_back({name, type, float_type(type) ? bytes : -bytes, 0, false});  // an integer: skipped
    }
  }
  if (format.empty()) throw LoadError(path + ": no 'format' line in the PLY header");
  if (!seen_vertex || count == 0) throw LoadError(path + ": no points (the PLY file has no vertex element or 0 vertices)");
  int slot[3] = {-1, -1, -1};
  for (std::size_t i = 0; i < properties.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (properties[i].name == std::string(1, "xyz"[k])) {
        if (properties[i].bytes != 4 && properties[i].bytes != 8)
          throw LoadError(path + ": vertex property " + properties[i].name + " must be float or double");
        slot[k] = static_cast<int>(i);
      }
  if (slot[0] < 0 || slot[1] < 0 || slot[2] < 0) throw LoadError(path + ": the vertices have no x, y and z properties");
  PlyContent out;
  const Element* face_element = nullptr;
  for (const Element& e : later)
    if (e.face_list >= 0) face_element = &e;
  out.has_faces = face_element != nullptr;
  const bool keep_faces = faces && face_element;
  if (keep_faces) out.face_sizes.reserve(face_element->count);

  const std::size_t body = header_end + std::strlen("end_header") + eol.size();
  // A count the file cannot hold is refused before anything is allocated: a
  // binary vertex takes its properties' bytes, an ASCII one at least two
  // bytes per value ("0 ").
  std::size_t least = 0;
  for (const Property& p : properties) least += format == "ascii" ? 2 : static_cast<std::size_t>(std::abs(p.bytes));
  const std::size_t available = data.size() > body ? data.size() - body : 0;
  if (least == 0 || count > available / least)
    throw LoadError(path + ": truncated: " + std::to_string(count) + " points cannot fit in the " + std::to_string(available) +
                    " bytes after the PLY header");
  out.points.resize(count);
  if (format == "ascii") {
    std::size_t start = body;
    long number = line_number + 1;  // the end_header line
    std::string_view text;
    for (std::size_t p = 0; p < count; ++p) {
      if (!next_text_line(data, start, number, text))
        throw LoadError(path + ":" + std::to_string(number + 1) + ": the file ends after " + std::to_string(p) + " of " +
                        std::to_string(count) + " points");
      const std::string where = path + ":" + std::to_string(number);
      const std::vector<std::string_view> values = split_words(text);
      if (values.size() < properties.size()) throw LoadError(where + ": expected " + std::to_string(properties.size()) + " values");
      if (values.size() > properties.size())
        throw LoadError(where + ": more than the " + std::to_string(properties.size()) + " values the header declares");
      for (std::size_t i = 0; i < properties.size(); ++i) {
        double x = 0;
        const auto [stop, err] = std::from_chars(values[i].data(), values[i].data() + values[i].size(), x);
        if (err != std::errc() || stop != values[i].data() + values[i].size())
          throw LoadError(where + ": " + quoted_excerpt(values[i]) + " is not a number");
        for (int k = 0; k < 3; ++k)
          if (slot[k] == static_cast<int>(i)) out.points[p][static_cast<std::size_t>(k)] = checked_file_coordinate(x, where);
      }
    }
    // The later elements, an item a line (blank lines skipped): each line
    // must hold what its element's properties declare; more lines is a file
    // whose header says less than it holds, fewer one that was cut short.
    std::size_t later_lines = 0, lines = 0;
    for (const Element& e : later) later_lines += e.properties.empty() ? 0 : e.count;
    for (const Element& e : later) {
      if (e.properties.empty()) continue;
      for (std::size_t item = 0; item < e.count; ++item) {
        do {
          if (!next_text_line(data, start, number, text))
            throw LoadError(path + ": truncated: the file ends after " + std::to_string(lines) + " of the " +
                            std::to_string(later_lines) + " lines of the elements after the points (" + later.front().name + ", ...)");
        } while (split_words(text).empty());
        ++lines;
        const std::string where = path + ":" + std::to_string(number);
        const std::vector<std::string_view> values = split_words(text);
        std::size_t v = 0;
        for (std::size_t i = 0; i < e.properties.size(); ++i) {
          const Property& q = e.properties[i];
          long long n = 1;
          if (q.count_bytes > 0) {
            if (v >= values.size() || !whole_number(values[v], n) || n < 0)
              throw LoadError(where + ": " + e.name + " " + std::to_string(item + 1) + ": expected the count of its list '" + q.name + "'");
            ++v;
          }
          if (static_cast<long long>(values.size() - v) < n)
            throw LoadError(where + ": " + e.name + " " + std::to_string(item + 1) + ": fewer values than its properties declare");
          const bool face = keep_faces && &e == face_element && static_cast<int>(i) == e.face_list;
          if (face) out.face_sizes.push_back(n);
          for (long long k = 0; k < n; ++k, ++v) {
            long long index = 0;
            if (face ? !whole_number(values[v], index) : !is_number(values[v]))
              throw LoadError(where + ": " + quoted_excerpt(values[v]) + (face ? " is not a vertex index" : " is not a number"));
            if (face) out.face_vertices.push_back(index);
          }
        }
        if (v < values.size())
          throw LoadError(where + ": " + e.name + " " + std::to_string(item + 1) + ": more values than its properties declare");
      }
    }
    while (next_text_line(data, start, number, text))
      if (!split_words(text).empty())
        throw LoadError(path + ":" + std::to_string(number) + ": more lines than the header's " + std::to_string(count) + " points" +
                        (later.empty() ? "" : " and later elements") + " declare");
    return out;
  }
  const bool big_endian = format == "binary_big_endian";
  std::size_t stride = 0;
  for (const Property& q : properties) stride += static_cast<std::size_t>(std::abs(q.bytes));
  if ((data.size() - body) / stride < count)
    throw LoadError(path + ": truncated: " + std::to_string(count) + " points of " + std::to_string(stride) +
                    " bytes need more than the file holds");
  for (std::size_t p = 0; p < count; ++p) {
    std::size_t offset = body + p * stride;
    for (std::size_t i = 0; i < properties.size(); ++i) {
      const int bytes = std::abs(properties[i].bytes);
      for (int k = 0; k < 3; ++k)
        if (slot[k] == static_cast<int>(i))
          out.points[p][static_cast<std::size_t>(k)] = checked_file_coordinate(
              real_at(data.data() + offset, bytes, big_endian), path + ": point " + std::to_string(p + 1) + " of " + std::to_string(count) + " (binary)");
      offset += static_cast<std::size_t>(bytes);
    }
  }
  // The later elements, walked item by item through their lists' counts;
  // the file must end where they do.
  std::size_t offset = body + count * stride;
  for (const Element& e : later)
    for (std::size_t item = 0; item < e.count && !e.properties.empty(); ++item)  // each item takes a byte at least: bounded by the file
      for (std::size_t i = 0; i < e.properties.size(); ++i) {
        const Property& q = e.properties[i];
        const auto cut = [&] {
          return LoadError(path + ": truncated: the file ends within " + e.name + " " + std::to_string(item + 1) + " of " +
                           std::to_string(e.count) + " (binary)");
        };
        std::size_t items = 1;
        if (q.count_bytes > 0) {
          if (data.size() - std::min(offset, data.size()) < static_cast<std::size_t>(q.count_bytes)) throw cut();
          // Unsigned: a signed count's negative values are huge and refused below.
          items = unsigned_at(data.data() + offset, q.count_bytes, big_endian);
          offset += static_cast<std::size_t>(q.count_bytes);
        }
        const std::size_t rest = data.size() - std::min(offset, data.size());
        if (items > rest / static_cast<std::size_t>(q.bytes)) throw cut();
        if (keep_faces && &e == face_element && static_cast<int>(i) == e.face_list) {
          out.face_sizes.push_back(static_cast<long long>(items));
          for (std::size_t k = 0; k < items; ++k)
            out.face_vertices.push_back(q.is_signed ? signed_at(data.data() + offset + k * q.bytes, q.bytes, big_endian)
                                                    : static_cast<long long>(unsigned_at(data.data() + offset + k * q.bytes, q.bytes, big_endian)));
        }
        offset += items * static_cast<std::size_t>(q.bytes);
      }
  if (offset != data.size())
    throw LoadError(path + ": " + std::to_string(data.size() - offset) + " bytes after the " + std::to_string(count) +
                    " points the header declares" + (later.empty() ? " (and no further element)" : " and the elements after them"));
  return out;
}

}  // namespace stencil_runtime::detail

namespace stencil_runtime {

Mesh read_ply_mesh(const std::string& path) {
  std::ifstream in = detail::open_mesh_file(path);
  const std::string data{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) throw LoadError(path + ": read error");
  detail::PlyContent content = detail::read_ply(path, data, true);
  if (!content.has_faces)
    throw LoadError(path + ": no faces (a PLY control mesh needs an element 'face' with a list 'vertex_indices')");
  Mesh mesh;
  mesh.source = path;
  mesh.positions = std::move(content.points);
  const auto vertices = static_cast<long long>(mesh.positions.size());
  std::size_t at = 0;
  for (std::size_t f = 0; f < content.face_sizes.size(); ++f) {
    const long long n = content.face_sizes[f];
    const std::string face = path + ": face " + std::to_string(f) + " (numbered from 0)";
    if (n < 3) throw LoadError(face + " has " + std::to_string(n) + " vertices; a face needs at least three");
    if (n > limits::kMaxFaceSize)
      throw LoadError(face + " has more than " + std::to_string(limits::kMaxFaceSize) + " vertices");
    for (long long k = 0; k < n; ++k, ++at) {
      const long long index = content.face_vertices[at];
      if (index < 0 || index >= vertices)
        throw LoadError(face + ": vertex index " + std::to_string(index) + " refers to no vertex (PLY counts them from 0; the file has " +
                        std::to_string(vertices) + ")");
      mesh.face_vertices.push_back(static_cast<int>(index));
    }
    mesh.face_sizes.push_back(static_cast<int>(n));
  }
  if (mesh.face_sizes.empty()) throw LoadError(path + ": no faces");
  return mesh;
}

}  // namespace stencil_runtime
