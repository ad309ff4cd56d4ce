#include "stencil_runtime/polygon_links.hpp"

#include <cstdint>
#include <string>
#include <unordered_map>

namespace stencil_runtime {

namespace {
std::string edge_name(int a, int b) { return "(" + std::to_string(a) + ", " + std::to_string(b) + ")"; }
}  // namespace

PolygonLinks link_polygons(const Mesh& mesh) {
  const std::size_t nf = mesh.face_count(), nv = mesh.vertex_count();
  PolygonLinks l;
  l.start.assign(nf + 1, 0);
  for (std::size_t f = 0; f < nf; ++f) {
    if (mesh.face_sizes[f] < 3) throw MeshError("face " + std::to_string(f) + " has fewer than 3 vertices");
    l.start[f + 1] = l.start[f] + static_cast<std::size_t>(mesh.face_sizes[f]);
    for (std::size_t h = l.start[f]; h < l.start[f + 1]; ++h) {
      const int v = mesh.face_vertices[h];
      if (v < 0 || static_cast<std::size_t>(v) >= nv)
        throw MeshError("face " + std::to_string(f) + " refers to vertex " + std::to_string(v) + ", which does not exist");
      l.face_of.push_back(f);
      l.next.push_back(h + 1 < l.start[f + 1] ? h + 1 : l.start[f]);
    }
  }
  const std::size_t nh = l.start[nf];
  auto vert = [&](std::size_t h) { return mesh.face_vertices[h]; };
  auto key = [](int a, int b) { return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b); };
  std::unordered_map<std::uint64_t, std::size_t> directed;
  directed.reserve(nh);
  for (std::size_t h = 0; h < nh; ++h) {
    const int a = vert(h), b = vert(l.next[h]);
    const auto [it, fresh] = directed.emplace(key(a, b), h);
    if (!fresh)
      throw MeshError("edge " + edge_name(a, b) + " is used twice in the same direction (faces " +
                      std::to_string(l.face_of[it->second]) + " and " + std::to_string(l.face_of[h]) +
                      "): the mesh is non-manifold or inconsistently oriented");
  }
  l.twin.assign(nh, 0);
  l.valence.assign(nv, 0);
  for (std::size_t h = 0; h < nh; ++h) {
    const int a = vert(h), b = vert(l.next[h]);
    const auto it = directed.find(key(b, a));
    if (it == directed.end())
      throw MeshError("edge " + edge_name(a, b) + " of face " + std::to_string(l.face_of[h]) +
                      " has no neighbouring face: the mesh has a boundary (only closed meshes are supported)");
    l.twin[h] = it->second;
    ++l.valence[static_cast<std::size_t>(a)];
  }
  for (std::size_t v = 0; v < nv; ++v)
    if (l.valence[v] == 0) throw MeshError("vertex " + std::to_string(v) + " belongs to no face");
  return l;
}

}  // namespace stencil_runtime
