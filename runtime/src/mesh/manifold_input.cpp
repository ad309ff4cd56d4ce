#include "manifold_input.hpp"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <regex>
#include <unordered_map>

#include "polygon_links.hpp"
#include "sharpness.hpp"
#include "union_find.hpp"

namespace stencil_runtime {

ManifoldInput make_manifold(const Connectivity& mesh, const MeshFeatures& features) {
  ManifoldInput out;
  const PolygonLinks links = link_polygons(mesh, true, Fans::Any);  // names any other fault
  const std::vector<int>& face_vertices = mesh.face_vertices;
  const std::size_t vertex_count = mesh.vertex_count, nh = face_vertices.size();
  // A vertex's corners in one fan are joined across the edges two faces share
  // (twin runs b -> a, its next corner is at a again).
  std::vector<std::size_t> parent(nh);
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  for (std::size_t h = 0; h < nh; ++h)
    if (links.twin[h] != PolygonLinks::kNoTwin) parent[find_root(parent, h)] = find_root(parent, links.next[links.twin[h]]);
  std::vector<std::size_t> fan_root(vertex_count, SIZE_MAX);
  std::vector<char> several(vertex_count, 0);
  for (std::size_t h = 0; h < nh; ++h) {
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
  // Each tagged edge on the fan that has it: one of its half-edges, found by a
  // pass over them all.
  auto key = [&](int a, int b) {
    const auto [lo, hi] = std::minmax(a, b);
    return static_cast<std::uint64_t>(lo) * vertex_count + static_cast<std::uint64_t>(hi);
  };
  std::unordered_map<std::uint64_t, std::size_t> tagged;
  for (const MeshFeatures::Edge& e : features.edges) tagged.emplace(key(e.a, e.b), SIZE_MAX);
  if (!tagged.empty())
    for (std::size_t h = 0; h < nh; ++h)
      if (auto it = tagged.find(key(face_vertices[h], face_vertices[links.next[h]])); it != tagged.end()) it->second = h;
  for (const MeshFeatures::Edge& e : features.edges) {
    const std::size_t h = tagged.at(key(e.a, e.b));
    if (h == SIZE_MAX) continue;  // checked before (LevelSharpness::of): cannot happen
    const int x = out.face_vertices[h], y = out.face_vertices[links.next[h]];
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
