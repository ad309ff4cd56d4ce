#include "obj_tags.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <unordered_set>
#include <vector>

#include "line_tokens.hpp"
#include "stencil_runtime/limits.hpp"

namespace stencil_runtime::detail {

namespace {

struct Tag {
  std::string name;
  std::vector<long long> ints;
  std::vector<double> floats;
  std::vector<std::string> strings;
};

// A count of the `I/F/S` field: a non-negative integer no larger than the
// tokens a line can hold.
std::size_t parse_count(std::string_view text, const TagFail& fail) {
  long long n = -1;
  const auto [end, err] = std::from_chars(text.data(), text.data() + text.size(), n);
  if (err != std::errc() || end != text.data() + text.size() || n < 0 ||
      n > static_cast<long long>(limits::kMaxMeshLineBytes / 2))
    fail("tag argument count " + quoted_excerpt(text) + " is not a non-negative integer");
  return static_cast<std::size_t>(n);
}

Tag parse(std::string_view rest, const TagFail& fail) {
  Tag t;
  std::size_t pos = 0;
  const std::string_view name = next_token(rest, pos);
  if (name.empty()) fail("a tag line needs a name and its argument counts `I/F/S`");
  t.name = std::string(name);
  const std::string_view counts = next_token(rest, pos);
  std::size_t n[3] = {0, 0, 0};
  {
    std::size_t k = 0, start = 0;
    for (std::size_t i = 0; i <= counts.size(); ++i)
      if (i == counts.size() || counts[i] == '/') {
        if (k == 3) fail("tag `" + t.name + "`: argument counts " + quoted_excerpt(counts) + " are not `I/F/S`");
        n[k++] = parse_count(counts.substr(start, i - start), fail);
        start = i + 1;
      }
    if (counts.empty() || k < 2) fail("tag `" + t.name + "`: argument counts " + quoted_excerpt(counts) + " are not `I/F/S`");
  }
  for (std::size_t i = 0; i < n[0]; ++i) {
    const std::string_view x = next_token(rest, pos);
    long long v = 0;
    const auto [end, err] = std::from_chars(x.data(), x.data() + x.size(), v);
    if (x.empty()) fail("tag `" + t.name + "`: " + std::to_string(n[0]) + " integers announced, " + std::to_string(i) + " given");
    if (err != std::errc() || end != x.data() + x.size()) fail("tag `" + t.name + "`: " + quoted_excerpt(x) + " is not an integer");
    t.ints.push_back(v);
  }
  for (std::size_t i = 0; i < n[1]; ++i) {
    const std::string_view x = next_token(rest, pos);
    double v = 0;
    const auto [end, err] = std::from_chars(x.data(), x.data() + x.size(), v);
    if (x.empty()) fail("tag `" + t.name + "`: " + std::to_string(n[1]) + " numbers announced, " + std::to_string(i) + " given");
    if (err != std::errc() || end != x.data() + x.size() || !std::isfinite(v))
      fail("tag `" + t.name + "`: " + quoted_excerpt(x) + " is not a finite number");
    t.floats.push_back(v);
  }
  for (std::size_t i = 0; i < n[2]; ++i) {
    const std::string_view x = next_token(rest, pos);
    if (x.empty()) fail("tag `" + t.name + "`: " + std::to_string(n[2]) + " strings announced, " + std::to_string(i) + " given");
    t.strings.emplace_back(x);
  }
  if (!next_token(rest, pos).empty()) fail("tag `" + t.name + "` has more arguments than its counts " + quoted_excerpt(counts) + " say");
  return t;
}

int index_argument(long long v, const std::string& tag, const TagFail& fail) {
  if (v < 0 || v >= static_cast<long long>(limits::kMaxMeshElements))
    fail("tag `" + tag + "`: index " + std::to_string(v) + " is negative or too large (tags number vertices and faces from 0)");
  return static_cast<int>(v);
}

double sharpness_argument(double s, const std::string& tag, const TagFail& fail) {
  if (s < 0) fail("tag `" + tag + "`: sharpness " + number_text(s) + " is negative");
  return s;
}

// One sharpness for all, or one per item.
double sharpness_of(const Tag& t, std::size_t item, std::size_t items, const TagFail& fail) {
  if (t.floats.size() != 1 && t.floats.size() != items)
    fail("tag `" + t.name + "` needs one sharpness or one per " + (t.name == "crease" ? "edge" : "vertex") + " (" +
         std::to_string(items) + "), got " + std::to_string(t.floats.size()));
  return sharpness_argument(t.floats[t.floats.size() == 1 ? 0 : item], t.name, fail);
}

}  // namespace

void read_obj_tag(std::string_view rest, long line, const std::string& where, Mesh& mesh, const TagFail& fail) {
  const Tag t = parse(rest, fail);
  MeshTags& tags = mesh.tags;
  if (t.name == "crease") {  // a chain of vertices: edges (v0 v1), (v1 v2), ...
    if (t.ints.size() < 2) fail("tag `crease` needs at least two vertices");
    for (std::size_t e = 0; e + 1 < t.ints.size(); ++e)
      tags.creases.push_back({index_argument(t.ints[e], t.name, fail), index_argument(t.ints[e + 1], t.name, fail),
                              sharpness_of(t, e, t.ints.size() - 1, fail), line});
  } else if (t.name == "corner") {
    if (t.ints.empty()) fail("tag `corner` needs at least one vertex");
    for (std::size_t k = 0; k < t.ints.size(); ++k)
      tags.corners.push_back({index_argument(t.ints[k], t.name, fail), sharpness_of(t, k, t.ints.size(), fail), line});
  } else if (t.name == "hole") {
    if (t.ints.empty()) fail("tag `hole` needs at least one face");
    for (long long f : t.ints) tags.holes.push_back({index_argument(f, t.name, fail), line});
  } else if (t.name == "interpolateboundary") {
    // RenderMan's numbering, as OpenSubdiv's shapes use it.
    if (t.ints.size() != 1 || t.ints[0] < 0 || t.ints[0] > 2)
      fail("tag `interpolateboundary` needs one integer: 0 (none), 1 (edge and corner) or 2 (edge only)");
    tags.boundary = t.ints[0] == 0 ? BoundaryInterpolation::None
                    : t.ints[0] == 1 ? BoundaryInterpolation::EdgeAndCorner
                                     : BoundaryInterpolation::EdgeOnly;
  } else if (t.name == "creasemethod") {
    if (t.strings.size() != 1 || (t.strings[0] != "normal" && t.strings[0] != "chaikin"))
      fail("tag `creasemethod` needs one string: normal or chaikin");
    tags.chaikin_creases = t.strings[0] == "chaikin";
  } else if (t.name == "smoothtriangles") {
    // Older shapes give an integer (non-zero: smooth), newer ones a string.
    bool smooth = false;
    if (t.strings.size() == 1 && t.ints.empty() && (t.strings[0] == "smooth" || t.strings[0] == "catmark"))
      smooth = t.strings[0] == "smooth";
    else if (t.ints.size() == 1 && t.strings.empty())
      smooth = t.ints[0] != 0;
    else
      fail("tag `smoothtriangles` needs one string (smooth or catmark) or one integer");
    tags.smooth_triangles = smooth;
    tags.smooth_triangles_line = line;
  } else {
    mesh.warnings.push_back(where + ": warning: unknown tag `" + t.name + "` ignored");
  }
}

void check_obj_tags(const Mesh& mesh, const std::function<void(long, const std::string&)>& fail_at) {
  const MeshTags& tags = mesh.tags;
  const auto vertices = static_cast<int>(mesh.vertex_count());
  auto vertex_ok = [&](int v, long line, const std::string& what) {
    if (v < 0 || v >= vertices)
      fail_at(line, what + " refers to vertex " + std::to_string(v) + ", but the mesh has " + std::to_string(vertices) +
                        " (tags number vertices from 0)");
  };
  std::unordered_set<std::uint64_t> edges;
  if (!tags.creases.empty()) {
    std::size_t offset = 0;
    for (int size : mesh.face_sizes) {
      for (int k = 0; k < size; ++k) {
        const auto a = static_cast<std::uint32_t>(mesh.face_vertices[offset + static_cast<std::size_t>(k)]);
        const auto b = static_cast<std::uint32_t>(mesh.face_vertices[offset + static_cast<std::size_t>((k + 1) % size)]);
        edges.insert((static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b));
      }
      offset += static_cast<std::size_t>(size);
    }
  }
  auto sharpness_ok = [&](double s, long line, const std::string& what) {
    if (!(s >= 0)) fail_at(line, what + ": sharpness " + number_text(s) + " is not a number >= 0");
  };
  for (const auto& c : tags.creases) {
    sharpness_ok(c.sharpness, c.line, "tag `crease`");
    vertex_ok(c.a, c.line, "tag `crease`");
    vertex_ok(c.b, c.line, "tag `crease`");
    const auto a = static_cast<std::uint32_t>(c.a), b = static_cast<std::uint32_t>(c.b);
    if (!edges.count((static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b)))
      fail_at(c.line, "tag `crease`: vertices " + std::to_string(c.a) + " and " + std::to_string(c.b) +
                          " are not joined by an edge of the mesh (tags number vertices from 0)");
  }
  for (const auto& c : tags.corners) {
    sharpness_ok(c.sharpness, c.line, "tag `corner`");
    vertex_ok(c.vertex, c.line, "tag `corner`");
  }
  for (const auto& h : tags.holes)
    if (h.face < 0 || static_cast<std::size_t>(h.face) >= mesh.face_count())
      fail_at(h.line, "tag `hole` refers to face " + std::to_string(h.face) + ", but the mesh has " +
                          std::to_string(mesh.face_count()) + " (tags number faces from 0)");
}

}  // namespace stencil_runtime::detail
