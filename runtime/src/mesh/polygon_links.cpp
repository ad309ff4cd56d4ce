#include "polygon_links.hpp"

#include "stencil_runtime/limits.hpp"

#include <cstdint>
#include <string>

namespace stencil_runtime {

namespace {
std::string edge_name(int a, int b) { return "(" + std::to_string(a) + ", " + std::to_string(b) + ")"; }
}  // namespace

PolygonLinks link_polygons(const Connectivity& mesh, bool boundaries, Fans fans) {
  const std::size_t nf = mesh.face_count(), nv = mesh.vertex_count;
  PolygonLinks l;
  l.start.assign(nf + 1, 0);
  for (std::size_t f = 0; f < nf; ++f) {
    if (mesh.face_sizes[f] < 3) throw MeshError("face " + std::to_string(f) + " has fewer than 3 vertices");
    l.start[f + 1] = l.start[f] + static_cast<std::size_t>(mesh.face_sizes[f]);
    if (l.start[f + 1] > mesh.face_vertices.size())
      throw MeshError("face " + std::to_string(f) + ": the face sizes add up to more than the " +
                      std::to_string(mesh.face_vertices.size()) + " face-vertex indices given");
  }
  if (l.start[nf] != mesh.face_vertices.size())
    throw MeshError("the face sizes add up to " + std::to_string(l.start[nf]) + " face-vertex indices, but " +
                    std::to_string(mesh.face_vertices.size()) + " are given");
  const std::size_t nh = l.start[nf];
  l.face_of.resize(nh);
  l.next.resize(nh);
  for (std::size_t f = 0; f < nf; ++f)
    for (std::size_t h = l.start[f]; h < l.start[f + 1]; ++h) {
      const int v = mesh.face_vertices[h];
      if (v < 0 || static_cast<std::size_t>(v) >= nv)
        throw MeshError("face " + std::to_string(f) + " refers to vertex " + std::to_string(v) + ", which does not exist");
      for (std::size_t g = l.start[f]; g < h; ++g)
        if (mesh.face_vertices[g] == v)
          throw MeshError("face " + std::to_string(f) + " uses vertex " + std::to_string(v) + " twice");
      l.face_of[h] = f;
      l.next[h] = h + 1 < l.start[f + 1] ? h + 1 : l.start[f];
    }
  auto vert = [&](std::size_t h) { return mesh.face_vertices[h]; };
  // Outgoing half-edges by vertex (CSR): twins are found among the few
  // half-edges leaving the next vertex, in linear time and without hashing.
  l.valence.assign(nv, 0);
  for (std::size_t h = 0; h < nh; ++h) ++l.valence[static_cast<std::size_t>(vert(h))];
  for (std::size_t v = 0; v < nv; ++v)
    if (l.valence[v] > limits::kMaxValence)
      throw MeshError("vertex " + std::to_string(v) + " has valence " + std::to_string(l.valence[v]) +
                      "; the runtime supports valences up to " + std::to_string(limits::kMaxValence) + " (split the faces round it)");
  std::vector<std::size_t> first(nv + 1, 0);
  for (std::size_t v = 0; v < nv; ++v) first[v + 1] = first[v] + static_cast<std::size_t>(l.valence[v]);
  std::vector<std::size_t> outgoing(nh), fill(first.begin(), first.end() - 1);
  for (std::size_t h = 0; h < nh; ++h) outgoing[fill[static_cast<std::size_t>(vert(h))]++] = h;
  if (fans == Fans::Any) l.non_manifold.assign(nh, 0);
  for (std::size_t v = 0; v < nv; ++v)  // an edge used twice in the same direction
    for (std::size_t a = first[v]; a < first[v + 1]; ++a)
      for (std::size_t b = first[v]; b < a; ++b)
        if (vert(l.next[outgoing[a]]) == vert(l.next[outgoing[b]])) {
          if (fans == Fans::Any) {
            l.non_manifold[outgoing[a]] = l.non_manifold[outgoing[b]] = 1;
            continue;
          }
          throw MeshError("edge " + edge_name(static_cast<int>(v), vert(l.next[outgoing[a]])) +
                          " is used twice in the same direction (faces " + std::to_string(l.face_of[outgoing[b]]) + " and " +
                          std::to_string(l.face_of[outgoing[a]]) + "): the mesh is non-manifold or inconsistently oriented");
        }
  l.twin.assign(nh, 0);
  for (std::size_t h = 0; h < nh; ++h) {
    const int a = vert(h), b = vert(l.next[h]);
    std::size_t found = nh, reverse = 0;
    for (std::size_t k = first[static_cast<std::size_t>(b)]; k < first[static_cast<std::size_t>(b) + 1]; ++k)
      if (vert(l.next[outgoing[k]]) == a) found = outgoing[k], ++reverse;
    if (!l.non_manifold.empty() && (l.non_manifold[h] || reverse > 1)) {  // in three faces or more, or misoriented
      l.non_manifold[h] = 1;
      l.twin[h] = PolygonLinks::kNoTwin;
      continue;
    }
    if (found == nh) {
      if (!boundaries)
        throw MeshError("edge " + edge_name(a, b) + " of face " + std::to_string(l.face_of[h]) +
                        " has no neighbouring face: the mesh has a boundary (only closed meshes are supported here)");
      found = PolygonLinks::kNoTwin;
      l.has_boundary = true;
    }
    l.twin[h] = found;
  }
  l.boundary.assign(nv, 0);
  if (fans == Fans::Any) {
    for (std::size_t h = 0; h < nh; ++h)
      if (l.twin[h] == PolygonLinks::kNoTwin && !l.non_manifold[h]) l.boundary[static_cast<std::size_t>(vert(h))] = 1;
    return l;
  }
  for (std::size_t v = 0; v < nv; ++v)
    if (l.valence[v] == 0) throw MeshError("vertex " + std::to_string(v) + " belongs to no face");
  // Each vertex must have a single fan of faces: turning round it from one
  // outgoing half-edge (to the previous half-edge of the face, then across)
  // must visit all of its faces. A boundary vertex has exactly one outgoing
  // boundary half-edge, where its open fan starts.
  for (std::size_t v = 0; v < nv; ++v) {
    std::size_t start = outgoing[first[v]];
    int open = 0;
    for (std::size_t k = first[v]; k < first[v + 1]; ++k)
      if (l.twin[outgoing[k]] == PolygonLinks::kNoTwin) start = outgoing[k], ++open;
    if (open > 1)
      throw MeshError("vertex " + std::to_string(v) + " is non-manifold (its faces form " + std::to_string(open) +
                      " fans, which meet only at the vertex)");
    l.boundary[v] = open == 1;
    int count = 0;
    std::size_t e = start;
    do {
      ++count;
      const std::size_t f = l.face_of[e];
      const std::size_t prev = e == l.start[f] ? l.start[f + 1] - 1 : e - 1;
      e = l.twin[prev];
    } while (e != start && e != PolygonLinks::kNoTwin && count <= l.valence[v]);
    if (count != l.valence[v])
      throw MeshError("vertex " + std::to_string(v) + " is non-manifold (its faces form more than one fan)");
  }
  return l;
}

}  // namespace stencil_runtime
