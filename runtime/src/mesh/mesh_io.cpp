#include "stencil_runtime/mesh_io.hpp"

#include <algorithm>
#include <charconv>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <string_view>

#include "coordinates.hpp"
#include "file_output.hpp"
#include "line_tokens.hpp"
#include "mesh_file.hpp"
#include "obj_tags.hpp"
#include "stencil_runtime/limits.hpp"

namespace stencil_runtime {

namespace fs = std::filesystem;

namespace {

using detail::next_line;
using detail::next_token;

// Whether `line` ends in OBJ's line continuation, a backslash (before a
// '\r' of a CRLF file), and is not a comment: a comment ending in one (a
// Windows folder) must not swallow the line after it.
bool continues(const std::string& line) {
  std::size_t end = line.size();
  if (end > 0 && line[end - 1] == '\r') --end;
  if (end == 0 || line[end - 1] != '\\') return false;
  const std::size_t first = line.find_first_not_of(" \t");
  return first != std::string::npos && line[first] != '#';
}

}  // namespace

std::ifstream detail::open_mesh_file(const std::string& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) throw LoadError(path + ": cannot open (no such file)");
  if (!fs::is_regular_file(status)) throw LoadError(path + ": not a regular file");
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) throw LoadError(path + ": cannot read its size: " + ec.message());
  if (size > limits::kMaxMeshFileBytes)
    throw LoadError(path + ": " + std::to_string(size) + " bytes; meshes are limited to " +
                    std::to_string(limits::kMaxMeshFileBytes) + " bytes");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw LoadError(path + ": cannot open");
  return in;
}

Mesh read_obj(const std::string& path) {
  std::ifstream in = detail::open_mesh_file(path);
  Mesh mesh;
  mesh.source = path;
  std::string line, more;
  std::string first_word;  // the file's first word, for the message when there are no faces
  long number = 0;    // the line that messages name: the first of a continued line
  long physical = 0;  // lines read
  auto fail = [&](const std::string& what) { throw LoadError(path + ":" + std::to_string(number) + ": " + what); };
  const auto too_long = [&](const std::string& what) {
    number = physical + 1;
    fail(what);
  };
  while (next_line(*in.rdbuf(), line, too_long)) {
    number = ++physical;
    // A backslash at the end joins the next line to this one (the OBJ
    // format's continuation, for long faces), in place of the backslash.
    while (continues(line)) {
      line.resize(line.find_last_of('\\'));
      if (!next_line(*in.rdbuf(), more, too_long)) break;  // the file's last line: nothing to join
      ++physical;
      if (line.size() + 1 + more.size() > limits::kMaxMeshLineBytes) {
        number = physical;
        fail("line longer than " + std::to_string(limits::kMaxMeshLineBytes) + " bytes (with the lines it continues)");
      }
      line += ' ';
      line += more;
    }
    std::size_t pos = 0;
    if (number == 1 && line.compare(0, 3, "\xEF\xBB\xBF") == 0) pos = 3;  // a UTF-8 byte-order mark (Windows editors)
    const std::string_view tag = next_token(line, pos);
    if (first_word.empty() && !tag.empty() && tag[0] != '#') first_word = tag.substr(0, 16);
    if (tag == "v") {
      Point p{};
      for (int k = 0; k < 3; ++k) {
        const std::string_view t = next_token(line, pos);
        const auto [end, err] = std::from_chars(t.data(), t.data() + t.size(), p[static_cast<std::size_t>(k)]);
        if (err == std::errc::result_out_of_range)
          fail("coordinate " + std::string(t) + " is not a finite number of magnitude at most 1e37");
        if (t.empty() || err != std::errc() || end != t.data() + t.size())
          fail("a vertex needs three numbers, got " + quoted_excerpt(t));
        if (!std::isfinite(p[static_cast<std::size_t>(k)]) || std::fabs(p[static_cast<std::size_t>(k)]) > limits::kMaxCoordinate)
          fail("coordinate " + std::string(t) + " is not a finite number of magnitude at most 1e37");
      }
      // What may follow: a weight w, or a colour (r g b, with alpha), as numbers.
      int extra = 0;
      for (std::string_view t = next_token(line, pos); !t.empty() && t[0] != '#'; t = next_token(line, pos), ++extra) {
        double x = 0;
        const auto [end, err] = std::from_chars(t.data(), t.data() + t.size(), x);
        if (err != std::errc() || end != t.data() + t.size() || extra == 4)
          fail("a vertex is three coordinates (then at most a weight or a colour, as numbers), got " + quoted_excerpt(t) +
               " after them");
      }
      if (mesh.positions.size() >= limits::kMaxMeshElements) fail("more than 2^30 vertices");
      mesh.positions.push_back(p);
    } else if (tag == "f") {
      int count = 0;
      for (std::string_view item = next_token(line, pos); !item.empty() && item[0] != '#'; item = next_token(line, pos)) {
        long long index = 0;
        const auto [end, err] = std::from_chars(item.data(), item.data() + item.size(), index);
        if (err != std::errc() || end == item.data() || (end != item.data() + item.size() && *end != '/'))
          fail("bad face index " + quoted_excerpt(item));
        // v/vt, v//vn or v/vt/vn: the texture and normal indices are not used, but must be indices or empty.
        {
          std::string_view rest = item.substr(static_cast<std::size_t>(end - item.data()));
          auto is_index = [](std::string_view t) {  // empty, or an optionally negative run of digits
            if (t.empty()) return true;
            if (t[0] == '-') t.remove_prefix(1);
            return !t.empty() && std::all_of(t.begin(), t.end(), [](char c) { return c >= '0' && c <= '9'; });
          };
          int parts = 0;
          bool ok = true;
          while (!rest.empty() && ok) {  // rest starts with '/'
            rest.remove_prefix(1);
            const std::size_t slash = std::min(rest.find('/'), rest.size());
            ok = ++parts <= 2 && is_index(rest.substr(0, slash));
            rest.remove_prefix(slash);
          }
          if (!ok) fail("bad face vertex " + quoted_excerpt(item) + " (expected v, v/vt, v//vn or v/vt/vn)");
        }
        const auto n = static_cast<long long>(mesh.positions.size());
        if (index < 0) index += n + 1;
        if (index < 1 || index > n) fail("face index " + std::string(item) + " refers to no vertex defined so far");
        if (count == limits::kMaxFaceSize) fail("a face has more than " + std::to_string(limits::kMaxFaceSize) + " vertices");
        mesh.face_vertices.push_back(static_cast<int>(index - 1));
        ++count;
      }
      if (count < 3) fail("a face needs at least three vertices");
      if (mesh.face_sizes.size() >= limits::kMaxMeshElements) fail("more than 2^30 faces");
      mesh.face_sizes.push_back(count);
    } else if (tag == "t") {
      detail::read_obj_tag(std::string_view(line).substr(pos), number, path + ":" + std::to_string(number), mesh, fail);
    }
  }
  if (mesh.face_sizes.empty()) {
    // An OFF or PLY file read as OBJ has no OBJ lines at all: say what it is.
    const std::string_view word = first_word;
    const bool off = word.size() >= 3 && word.substr(word.size() - 3) == "OFF";
    throw LoadError(path + ": no faces" +
                    (off ? " (it starts like an OFF file: name it .off to read it as one)"
                         : word == "ply" ? " (it is a PLY file: name it .ply to read it as one)" : ""));
  }
  detail::check_obj_tags(mesh, [&](long at, const std::string& what) {
    throw LoadError(path + ":" + std::to_string(at) + ": " + what);
  });
  return mesh;
}

namespace {

void write_obj(const PolygonSoup& s, std::FILE* f) {
  for (const auto& p : s.positions) std::fprintf(f, "v %.9g %.9g %.9g\n", p[0], p[1], p[2]);
  const bool normals = !s.normals.empty();
  for (const auto& n : s.normals) std::fprintf(f, "vn %.7g %.7g %.7g\n", n[0], n[1], n[2]);
  auto corner = [&](int i) { normals ? std::fprintf(f, " %d//%d", i + 1, i + 1) : std::fprintf(f, " %d", i + 1); };
  for (const auto& q : s.quads) {
    std::fputc('f', f);
    for (int i : q) corner(i);
    std::fputc('\n', f);
  }
  for (const auto& t : s.triangles) {
    std::fputc('f', f);
    for (int i : t) corner(i);
    std::fputc('\n', f);
  }
}

void write_ply(const PolygonSoup& s, std::FILE* f) {
  const bool normals = !s.normals.empty();
  std::fprintf(f,
               "ply\nformat binary_little_endian 1.0\nelement vertex %zu\nproperty float x\nproperty float y\n"
               "property float z\n%selement face %zu\nproperty list uchar int vertex_indices\nend_header\n",
               s.positions.size(), normals ? "property float nx\nproperty float ny\nproperty float nz\n" : "",
               s.quads.size() + s.triangles.size());
  if (normals) {
    for (std::size_t i = 0; i < s.positions.size(); ++i) {
      std::fwrite(s.positions[i].data(), sizeof(float), 3, f);
      std::fwrite(s.normals[i].data(), sizeof(float), 3, f);
    }
  } else {
    std::fwrite(s.positions.data(), sizeof(float) * 3, s.positions.size(), f);
  }
  for (const auto& q : s.quads) {
    const unsigned char n = 4;
    std::fwrite(&n, 1, 1, f);
    std::fwrite(q.data(), sizeof(int), 4, f);
  }
  for (const auto& t : s.triangles) {
    const unsigned char n = 3;
    std::fwrite(&n, 1, 1, f);
    std::fwrite(t.data(), sizeof(int), 3, f);
  }
}

}  // namespace


Mesh read_mesh(const std::string& path) {
  const std::string ext = lowercase_extension(path);
  return ext == ".off" ? read_off(path) : ext == ".ply" ? read_ply_mesh(path) : read_obj(path);
}

std::string lowercase_extension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

void write_polygons(const PolygonSoup& soup, const std::string& path) {
  const std::string ext = lowercase_extension(path);
  if (ext != ".obj" && ext != ".ply") throw LoadError(path + ": output must end in .obj or .ply");
  if (!soup.positions.empty()) {
    // Floats keep 24 bits down to 1.2e-38 (the smallest normal float) and
    // fewer below: a shape all of whose coordinates are smaller has lost its
    // digits (or become a point) in the soup's floats.
    float largest = 0;
    for (std::size_t k = 0; k < soup.positions.size(); ++k)
      for (const float x : soup.positions[k]) {
        if (!std::isfinite(x))
          throw MeshError(path + ": point " + std::to_string(k) + " of the tessellation has the coordinate " + number_text(x));
        largest = std::max(largest, std::fabs(x));
      }
    if (largest < std::numeric_limits<float>::min()) {
      char text[32];
      std::snprintf(text, sizeof text, "%.3g", static_cast<double>(largest));
      throw LoadError(path + ": every coordinate of the tessellation is at most " + text +
                      " in magnitude, too small for its floats (below 1.2e-38 they lose digits); scale the mesh up");
    }
  }
  if (!soup.normals.empty() && soup.normals.size() != soup.positions.size())
    throw LoadError(path + ": the tessellation has " + std::to_string(soup.normals.size()) + " normals for " +
                    std::to_string(soup.positions.size()) + " points");
  for (std::size_t k = 0; k < soup.normals.size(); ++k)
    for (const float x : soup.normals[k])
      if (!std::isfinite(x))
        throw MeshError(path + ": normal " + std::to_string(k) + " of the tessellation has the coordinate " + number_text(x));
  // Every polygon names points that exist (a soup made in code may not).
  const std::size_t points = soup.positions.size();
  auto check_polygon = [&](const auto& polygon, const char* kind, std::size_t k) {
    for (const int i : polygon)
      if (i < 0 || static_cast<std::size_t>(i) >= points)
        throw MeshError(path + ": " + kind + " " + std::to_string(k) + " of the tessellation refers to point " +
                        std::to_string(i) + ", but it has " + std::to_string(points) + " (numbered from 0)");
  };
  for (std::size_t k = 0; k < soup.quads.size(); ++k) check_polygon(soup.quads[k], "quad", k);
  for (std::size_t k = 0; k < soup.triangles.size(); ++k) check_polygon(soup.triangles[k], "triangle", k);
  write_file_atomically(path, [&](std::FILE* f) {
    if (ext == ".obj") write_obj(soup, f);
    else write_ply(soup, f);
  });
}

namespace {

// What read_obj would refuse, refused before anything is written (write_obj
// promises a file that reads back as the same surface, and must not read past
// a face list that its sizes overrun).
void check_writable(const Mesh& mesh, const std::string& path) {
  auto fail = [&](const std::string& what) { throw MeshError(path + ": the mesh cannot be written: " + what); };
  if (mesh.face_sizes.empty()) fail("it has no faces");
  if (mesh.positions.size() > limits::kMaxMeshElements || mesh.face_sizes.size() > limits::kMaxMeshElements)
    fail("it has more than 2^30 vertices or faces");
  if (const std::string fault = coordinate_fault(mesh.positions.data(), mesh.positions.size()); !fault.empty()) fail(fault);
  std::size_t offset = 0;
  for (std::size_t f = 0; f < mesh.face_sizes.size(); ++f) {
    const int size = mesh.face_sizes[f];
    if (size < 3 || size > limits::kMaxFaceSize)
      fail("face " + std::to_string(f) + " has " + std::to_string(size) + " vertices (faces have 3.." +
           std::to_string(limits::kMaxFaceSize) + ")");
    if (static_cast<std::size_t>(size) > mesh.face_vertices.size() - offset)
      fail("the face sizes add up to more than the " + std::to_string(mesh.face_vertices.size()) + " face-vertex indices");
    for (int c = 0; c < size; ++c) {
      const int v = mesh.face_vertices[offset + static_cast<std::size_t>(c)];
      if (v < 0 || static_cast<std::size_t>(v) >= mesh.positions.size())
        fail("face " + std::to_string(f) + " refers to vertex " + std::to_string(v) + ", but the mesh has " +
             std::to_string(mesh.positions.size()) + " (numbered from 0)");
    }
    offset += static_cast<std::size_t>(size);
  }
  if (offset != mesh.face_vertices.size())
    fail("the face sizes add up to " + std::to_string(offset) + " face-vertex indices, but " +
         std::to_string(mesh.face_vertices.size()) + " are given");
  detail::check_obj_tags(mesh, [&](long, const std::string& what) { fail(what); });
}

}  // namespace

void write_obj(const Mesh& mesh, const std::string& path) {
  if (lowercase_extension(path) != ".obj") throw LoadError(path + ": a control mesh is written as .obj");
  check_writable(mesh, path);
  write_file_atomically(path, [&](std::FILE* f) {
    for (const Point& p : mesh.positions) std::fprintf(f, "v %.17g %.17g %.17g\n", p[0], p[1], p[2]);
    std::size_t offset = 0;
    for (const int size : mesh.face_sizes) {
      std::fputc('f', f);
      for (int c = 0; c < size; ++c) std::fprintf(f, " %d", mesh.face_vertices[offset + static_cast<std::size_t>(c)] + 1);
      std::fputc('\n', f);
      offset += static_cast<std::size_t>(size);
    }
    // The tags, so that the file describes the same surface (OpenSubdiv's format, as read_obj reads it).
    const MeshTags& t = mesh.tags;
    for (const auto& c : t.creases) std::fprintf(f, "t crease 2/1/0 %d %d %.17g\n", c.a, c.b, c.sharpness);
    for (const auto& c : t.corners) std::fprintf(f, "t corner 1/1/0 %d %.17g\n", c.vertex, c.sharpness);
    for (const auto& h : t.holes) std::fprintf(f, "t hole 1/0/0 %d\n", h.face);
    if (t.boundary != BoundaryInterpolation::EdgeOnly)
      std::fprintf(f, "t interpolateboundary 1/0/0 %d\n", t.boundary == BoundaryInterpolation::None ? 0 : 1);
    if (t.chaikin_creases) std::fprintf(f, "t creasemethod 0/0/1 chaikin\n");
    if (t.smooth_triangles) std::fprintf(f, "t smoothtriangles 0/0/1 smooth\n");
  });
}

}  // namespace stencil_runtime
