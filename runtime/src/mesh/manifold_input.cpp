#include "manifold_input.hpp"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <regex>
#include <unordered_map>

#include "sharpness.hpp"
#include "stencil_runtime/limits.hpp"
#include "union_find.hpp"

namespace stencil_runtime {

ManifoldInput make_manifold(std::size_t vertex_count, const std::vector<int>& face_sizes,
                            const std::vector<int>& face_vertices, const MeshFeatures& features) {
  ManifoldInput out;
  // The corners' next corner in their face; anything link_polygons refuses leaves the mesh as it is.
  std::vector<std::size_t> next(face_vertices.size());
  std::size_t first = 0;
  for (int k : face_sizes) {
    if (k < 3 || first + static_cast<std::size_t>(k) > face_vertices.size()) return out;
    for (std::size_t c = 0; c < static_cast<std::size_t>(k); ++c) {
      const int v = face_vertices[first + c];
      if (v < 0 || static_cast<std::size_t>(v) >= vertex_count) return out;
      for (std::size_t d = 0; d < c; ++d)
        if (face_vertices[first + d] == v) return out;
      next[first + c] = first + (c + 1) % static_cast<std::size_t>(k);
    }
    first += static_cast<std::size_t>(k);
  }
  if (first != face_vertices.size()) return out;
  // Outgoing corners by vertex (CSR), as link_polygons finds twins: linear, no hashing.
  const std::size_t nh = face_vertices.size();
  std::vector<std::size_t> start(vertex_count + 1, 0);
  for (int v : face_vertices) ++start[static_cast<std::size_t>(v) + 1];
  for (std::size_t v = 0; v < vertex_count; ++v) start[v + 1] += start[v];
  std::vector<std::size_t> outgoing(nh), fill(start.begin(), start.end() - 1);
  for (std::size_t h = 0; h < nh; ++h) outgoing[fill[static_cast<std::size_t>(face_vertices[h])]++] = h;
  // The corner at a whose edge runs a -> b, or SIZE_MAX.
  auto corner_of_edge = [&](int a, int b) {
    for (std::size_t k = start[static_cast<std::size_t>(a)]; k < start[static_cast<std::size_t>(a) + 1]; ++k)
      if (face_vertices[next[outgoing[k]]] == b) return outgoing[k];
    return SIZE_MAX;
  };
  for (std::size_t v = 0; v < vertex_count; ++v)  // link_polygons names a valence out of range
    if (start[v + 1] - start[v] > static_cast<std::size_t>(limits::kMaxValence)) return out;
  for (std::size_t v = 0; v < vertex_count; ++v)  // an edge used twice in one direction: link_polygons names it
    for (std::size_t a = start[v]; a < start[v + 1]; ++a)
      for (std::size_t b = start[v]; b < a; ++b)
        if (face_vertices[next[outgoing[a]]] == face_vertices[next[outgoing[b]]]) return out;

  // A vertex's corners in one fan are joined across the edges two faces share.
  std::vector<std::size_t> parent(face_vertices.size());
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  for (std::size_t h = 0; h < nh; ++h) {
    const std::size_t twin = corner_of_edge(face_vertices[next[h]], face_vertices[h]);
    if (twin != SIZE_MAX) parent[find_root(parent, h)] = find_root(parent, next[twin]);  // both at face_vertices[h]
  }
  std::vector<std::size_t> fan_root(vertex_count, SIZE_MAX);
  std::vector<char> several(vertex_count, 0);
  for (std::size_t h = 0; h < face_vertices.size(); ++h) {
    const auto v = static_cast<std::size_t>(face_vertices[h]);
    const std::size_t root = find_root(parent, h);
    if (fan_root[v] == SIZE_MAX) fan_root[v] = root;
    else if (fan_root[v] != root) several[v] = 1;
  }
  const bool unused = std::find(fan_root.begin(), fan_root.end(), SIZE_MAX) != fan_root.end();
  const bool split = std::find(several.begin(), several.end(), 1) != several.end();
  if (!unused && !split) return out;

  // New numbers: the used vertices in order (their first fan), then one per further fan.
  std::vector<int> number(vertex_count, -1);
  for (std::size_t v = 0; v < vertex_count; ++v)
    if (fan_root[v] != SIZE_MAX) {
      number[v] = static_cast<int>(out.origin.size());
      out.origin.push_back(static_cast<int>(v));
    }
  std::unordered_map<std::size_t, int> fan_number;  // by root, for the further fans
  std::vector<std::vector<int>> copies(vertex_count);
  out.face_vertices.resize(face_vertices.size());
  for (std::size_t h = 0; h < face_vertices.size(); ++h) {
    const auto v = static_cast<std::size_t>(face_vertices[h]);
    const std::size_t root = find_root(parent, h);
    if (root == fan_root[v]) {
      out.face_vertices[h] = number[v];
      continue;
    }
    auto [it, fresh] = fan_number.emplace(root, static_cast<int>(out.origin.size()));
    if (fresh) {
      out.origin.push_back(static_cast<int>(v));
      copies[v].push_back(it->second);
    }
    out.face_vertices[h] = it->second;
  }

  out.features = features;
  out.features.edges.clear();
  out.features.vertices.clear();
  for (const MeshFeatures::Edge& e : features.edges) {  // on the fan that has the edge
    std::size_t h = corner_of_edge(e.a, e.b);
    if (h == SIZE_MAX) h = corner_of_edge(e.b, e.a);
    if (h == SIZE_MAX) continue;  // checked before: cannot happen
    const int x = out.face_vertices[h], y = out.face_vertices[next[h]];
    const bool forward = face_vertices[h] == e.a;
    out.features.edges.push_back({forward ? x : y, forward ? y : x, e.sharpness});
  }
  auto each_copy = [&](std::size_t v, double sharpness) {
    out.features.vertices.push_back({number[v], sharpness});
    for (int c : copies[v]) out.features.vertices.push_back({c, sharpness});
  };
  for (const MeshFeatures::Vertex& t : features.vertices)  // checked before; a vertex in no face drops its tag
    if (t.vertex >= 0 && static_cast<std::size_t>(t.vertex) < vertex_count && number[static_cast<std::size_t>(t.vertex)] >= 0)
      each_copy(static_cast<std::size_t>(t.vertex), t.sharpness);
  for (std::size_t v = 0; v < vertex_count; ++v)
    if (several[v]) each_copy(v, kInfiniteSharpness);  // as OpenSubdiv sharpens a non-manifold vertex, whatever its tag
  out.changed = true;
  return out;
}

std::string name_control_vertices(const std::string& message, const std::vector<int>& origin) {
  static const std::regex vertex(R"(vertex (\d+))");
  std::string out;
  auto last = message.cbegin();
  for (std::sregex_iterator it(message.begin(), message.end(), vertex), end; it != end; ++it) {
    out.append(last, (*it)[0].first);
    const std::string digits = (*it)[1].str();
    const unsigned long k = digits.size() < 10 ? std::stoul(digits) : origin.size();
    out += "vertex " + (k < origin.size() ? std::to_string(origin[k]) : digits);
    last = (*it)[0].second;
  }
  out.append(last, message.cend());
  return out;
}

}  // namespace stencil_runtime
