#include "manifold_input.hpp"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <regex>
#include <set>
#include <tuple>
#include <unordered_map>

#include "polygon_links.hpp"
#include "sharpness.hpp"
#include "union_find.hpp"

namespace stencil_runtime {

namespace {

// Per vertex: whether it is on a non-manifold crease, which OpenSubdiv (Far's
// prepareComponentTagsAndSharpness) leaves smooth along its two non-manifold
// edges instead of sharpening it: exactly two non-manifold edges, no boundary
// edge, and more faces than edges (a fin along the crease).
std::vector<char> non_manifold_creases(const Connectivity& mesh, const PolygonLinks& links) {
  struct Use {
    int a, b;  // a < b
    char non_manifold;
  };
  std::vector<Use> uses(mesh.face_vertices.size());
  for (std::size_t h = 0; h < uses.size(); ++h) {
    const auto [a, b] = std::minmax(mesh.face_vertices[h], mesh.face_vertices[links.next[h]]);
    uses[h] = {a, b, links.non_manifold[h]};
  }
  std::sort(uses.begin(), uses.end(), [](const Use& x, const Use& y) { return std::tie(x.a, x.b) < std::tie(y.a, y.b); });
  std::vector<int> edges(mesh.vertex_count, 0), torn(mesh.vertex_count, 0), boundary(mesh.vertex_count, 0);
  for (std::size_t i = 0, j = 0; i < uses.size(); i = j) {
    for (j = i + 1; j < uses.size() && uses[j].a == uses[i].a && uses[j].b == uses[i].b;) ++j;
    const auto a = static_cast<std::size_t>(uses[i].a), b = static_cast<std::size_t>(uses[i].b);
    ++edges[a], ++edges[b];
    if (uses[i].non_manifold) ++torn[a], ++torn[b];
    else if (j - i == 1) ++boundary[a], ++boundary[b];
  }
  std::vector<char> out(mesh.vertex_count, 0);
  for (std::size_t v = 0; v < out.size(); ++v)
    out[v] = torn[v] == 2 && boundary[v] == 0 && links.valence[v] > edges[v];
  return out;
}

// A vertex on a non-manifold crease is one vertex to OpenSubdiv, with one
// rule: the crease's, along its two non-manifold edges. Here each of its fans
// becomes a copy with a rule of its own, which is the same only where every
// fan runs from one of the two edges to the other, no other edge there is
// tagged sharp (OpenSubdiv counts it for the whole vertex), and, with
// edge-and-corner (which makes a boundary vertex in one face a corner), no
// fan is a single face. Anything else is refused, naming the vertex.
void check_crease_fans(const Connectivity& mesh, const PolygonLinks& links, std::vector<std::size_t>& parent,
                       const std::vector<char>& crease, const MeshFeatures& features) {
  struct Ends {
    int faces = 0, outs = 0, ins = 0, out = -1, in = -1;
  };
  std::unordered_map<std::size_t, Ends> fans;  // by the root of a crease vertex's corners
  for (std::size_t h = 0; h < mesh.face_vertices.size(); ++h) {
    if (!crease[static_cast<std::size_t>(mesh.face_vertices[h])]) continue;
    Ends& e = fans[find_root(parent, h)];
    ++e.faces;
    if (links.twin[h] == PolygonLinks::kNoTwin) ++e.outs, e.out = mesh.face_vertices[links.next[h]];
    const std::size_t f = links.face_of[h];
    const std::size_t before = h == links.start[f] ? links.start[f + 1] - 1 : h - 1;  // the half-edge into the vertex
    if (links.twin[before] == PolygonLinks::kNoTwin) ++e.ins, e.in = mesh.face_vertices[before];
  }
  auto refuse = [](std::size_t v, const std::string& why) {
    throw MeshError("vertex " + std::to_string(v) + " is on a non-manifold crease (two edges in more than two faces) " + why +
                    "; OpenSubdiv subdivides it with one rule for all its faces, which the runtime, treating each piece apart, "
                    "does not reproduce there");
  };
  const bool edge_and_corner = features.boundary == BoundaryInterpolation::EdgeAndCorner;
  for (std::size_t h = 0; h < mesh.face_vertices.size(); ++h) {
    const auto v = static_cast<std::size_t>(mesh.face_vertices[h]);
    if (!crease[v]) continue;
    const Ends& e = fans.at(find_root(parent, h));
    if (e.outs != 1 || e.ins != 1 || e.out == e.in) refuse(v, "with a piece of surface that does not run from one of the two edges to the other");
    if (edge_and_corner && e.faces == 1) refuse(v, "with a piece of one face under edge-and-corner boundary interpolation");
  }
  // The crease's two edges at each crease vertex: the ends of its pieces.
  std::unordered_map<int, std::vector<int>> ends;
  for (const auto& [root, e] : fans) {
    std::vector<int>& at = ends[mesh.face_vertices[root]];
    at.push_back(e.out);
    at.push_back(e.in);
  }
  for (const MeshFeatures::Edge& t : features.edges) {
    if (t.sharpness <= 0) continue;
    for (const int v : {t.a, t.b}) {
      if (!crease[static_cast<std::size_t>(v)]) continue;
      const int other = v == t.a ? t.b : t.a;
      const std::vector<int>& at = ends.at(v);  // the tag on one of the two edges is sharp there anyway
      if (std::find(at.begin(), at.end(), other) == at.end())
        refuse(static_cast<std::size_t>(v), "with a further sharp edge (" + std::to_string(t.a) + ", " + std::to_string(t.b) + ")");
    }
  }
}

}  // namespace

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
  const bool torn = std::find(links.non_manifold.begin(), links.non_manifold.end(), 1) != links.non_manifold.end();
  if (!unused && !split && !torn) return out;

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
  // OpenSubdiv makes a non-manifold edge infinitely sharp: here its faces no
  // longer share it, and each copy is tagged so (a boundary edge tagged so
  // keeps its faces' surface under `none`, as the uncut edge does there).
  std::vector<char> sharpened = several;
  if (torn) {
    const std::vector<char> crease = non_manifold_creases(mesh, links);
    check_crease_fans(mesh, links, parent, crease, features);
    std::set<std::pair<int, int>> done;
    for (std::size_t h = 0; h < nh; ++h) {
      if (!links.non_manifold[h]) continue;
      const int x = out.face_vertices[h], y = out.face_vertices[links.next[h]];
      if (done.insert(std::minmax(x, y)).second) out.features.edges.push_back({x, y, kInfiniteSharpness});
      sharpened[static_cast<std::size_t>(face_vertices[h])] = sharpened[static_cast<std::size_t>(face_vertices[links.next[h]])] = 1;
    }
    for (std::size_t v = 0; v < vertex_count; ++v)
      if (crease[v]) sharpened[v] = 0;  // its copies follow the crease along the two edges
  }
  for (std::size_t v = 0; v < vertex_count; ++v)
    if (sharpened[v]) each_copy(v, kInfiniteSharpness);  // as OpenSubdiv sharpens a non-manifold vertex, whatever its tag
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
