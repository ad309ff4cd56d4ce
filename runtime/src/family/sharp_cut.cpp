#include "sharp_cut.hpp"

#include <numeric>
#include <string>

#include "mesh/union_find.hpp"

namespace stencil_runtime {

SharpCut cut_along_sharp_edges(const Connectivity& mesh, const PolygonLinks& links, const LevelSharpness& sharpness,
                               bool edge_and_corner) {
  const std::size_t corners = mesh.face_vertices.size(), nv = mesh.vertex_count;
  auto vertex = [&](std::size_t h) { return mesh.face_vertices[h]; };
  auto infinite = [&](std::size_t h) { return sharpness.edge(vertex(h), vertex(links.next[h])) >= kInfiniteSharpness; };
  // Sharp edges at each vertex: infinitely sharp ones and boundary ones (counted once per edge).
  std::vector<int> sharp(nv, 0);
  for (std::size_t h = 0; h < corners; ++h) {
    const bool boundary = links.twin[h] == PolygonLinks::kNoTwin;
    if (!boundary && links.twin[h] < h) continue;  // each inner edge once
    if (boundary || infinite(h)) {
      ++sharp[static_cast<std::size_t>(vertex(h))];
      ++sharp[static_cast<std::size_t>(vertex(links.next[h]))];
    }
  }
  SharpCut out;
  out.mesh = mesh;
  std::vector<SectorRule> vertex_rule(nv, SectorRule::Crease);
  for (std::size_t v = 0; v < nv; ++v) {
    const bool boundary = links.boundary[v] != 0;
    const bool sharp_vertex = sharpness.vertex(static_cast<int>(v)) >= kInfiniteSharpness ||
                              (boundary && edge_and_corner && links.valence[v] == 1);
    const int infinite_edges = sharp[v] - (boundary ? 2 : 0);
    if (!boundary && sharp_vertex && infinite_edges == 0) vertex_rule[v] = SectorRule::Cone;  // not cut: its ring stays closed
    else if (sharp_vertex || sharp[v] >= 3) vertex_rule[v] = SectorRule::Corner;
    else if (sharp[v] == 1) vertex_rule[v] = SectorRule::Dart;  // inside, on one infinitely sharp edge
  }
  // Corners at the same vertex stay together across every edge that is not infinitely sharp.
  std::vector<std::size_t> parent(corners);
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  for (std::size_t h = 0; h < corners; ++h) {
    const std::size_t t = links.twin[h];
    if (t == PolygonLinks::kNoTwin || t < h || infinite(h)) continue;
    // h runs a -> b in its face; t runs b -> a in the other: a's corners are h and next(t), b's next(h) and t.
    parent[find_root(parent, h)] = find_root(parent, links.next[t]);
    parent[find_root(parent, links.next[h])] = find_root(parent, t);
  }
  std::vector<int> id_of_root(corners, -1);
  std::vector<char> used(nv, 0);
  out.origin.resize(nv);
  std::iota(out.origin.begin(), out.origin.end(), 0);
  for (std::size_t h = 0; h < corners; ++h) {
    const std::size_t root = find_root(parent, h);
    int& id = id_of_root[root];
    if (id < 0) {
      const auto v = static_cast<std::size_t>(vertex(h));
      if (!used[v]) {
        id = static_cast<int>(v);
        used[v] = 1;
      } else {
        id = static_cast<int>(out.origin.size());
        out.origin.push_back(static_cast<int>(v));
        out.cut = true;
      }
    }
    out.mesh.face_vertices[h] = id;
  }
  out.mesh.vertex_count = out.origin.size();
  out.rule.resize(out.origin.size());
  for (std::size_t v = 0; v < out.origin.size(); ++v) out.rule[v] = vertex_rule[static_cast<std::size_t>(out.origin[v])];
  return out;
}

std::vector<char> surfaceless_vertices(const Connectivity& mesh, const PolygonLinks& links, const LevelSharpness& sharpness) {
  std::vector<char> out(mesh.vertex_count, 0);
  for (std::size_t h = 0; h < mesh.face_vertices.size(); ++h) {
    if (links.twin[h] != PolygonLinks::kNoTwin) continue;
    const int a = mesh.face_vertices[h], b = mesh.face_vertices[links.next[h]];
    if (sharpness.edge(a, b) < kInfiniteSharpness) out[static_cast<std::size_t>(a)] = out[static_cast<std::size_t>(b)] = 1;
  }
  return out;
}

}  // namespace stencil_runtime
