#include "stencil_runtime/surface_fit.hpp"

#include <map>
#include <string>
#include <utility>

#include "stencil_runtime/limits.hpp"

namespace stencil_runtime {

namespace {

using Edge = std::pair<int, int>;
Edge key(int a, int b) { return a < b ? Edge{a, b} : Edge{b, a}; }

}  // namespace

Mesh refine_red_green(const Mesh& mesh, const std::vector<bool>& marked, int max_valence) {
  const std::size_t faces = mesh.face_count();
  if (marked.size() != faces)
    throw FitError(std::to_string(marked.size()) + " marks for a control mesh of " + std::to_string(faces) + " faces");
  for (std::size_t f = 0; f < faces; ++f)
    if (mesh.face_sizes[f] != 3)
      throw FitError("red-green refinement splits triangles: face " + std::to_string(f) + " has " +
                     std::to_string(mesh.face_sizes[f]) + " corners");
  if (mesh.face_vertices.size() != 3 * faces)
    throw FitError(std::to_string(mesh.face_vertices.size()) + " face-vertex indices for " + std::to_string(faces) +
                   " triangles");
  for (std::size_t h = 0; h < mesh.face_vertices.size(); ++h)
    if (mesh.face_vertices[h] < 0 || static_cast<std::size_t>(mesh.face_vertices[h]) >= mesh.vertex_count())
      throw FitError("face " + std::to_string(h / 3) + " refers to vertex " + std::to_string(mesh.face_vertices[h]) +
                     ", but the mesh has " + std::to_string(mesh.vertex_count()) + " (numbered from 0)");
  if (max_valence < 3 || max_valence > limits::kMaxValence)
    throw FitError("the largest valence must be 3.." + std::to_string(limits::kMaxValence) + " (got " +
                   std::to_string(max_valence) + ")");
  const auto corner = [&](std::size_t f, int c) { return mesh.face_vertices[3 * f + static_cast<std::size_t>(c)]; };
  std::vector<int> valence(mesh.vertex_count(), 0);
  for (const int v : mesh.face_vertices) ++valence[static_cast<std::size_t>(v)];
  // Red closure: a face with two or more split edges becomes red too, and so
  // does a face with one whose green bisection would raise its opposite
  // corner's valence above max_valence (each green adds one there; red splits
  // keep the old vertices' valences).
  std::vector<bool> red = marked;
  std::map<Edge, int> split;  // edge -> its midpoint's vertex (assigned below)
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t f = 0; f < faces; ++f)
      if (red[f])
        for (int c = 0; c < 3; ++c) split.emplace(key(corner(f, c), corner(f, (c + 1) % 3)), -1);
    std::vector<int> added(mesh.vertex_count(), 0);
    for (std::size_t f = 0; f < faces && !changed; ++f) {
      if (red[f]) continue;
      int count = 0, opposite = -1;
      for (int c = 0; c < 3; ++c)
        if (split.count(key(corner(f, c), corner(f, (c + 1) % 3)))) ++count, opposite = corner(f, (c + 2) % 3);
      if (count == 1) {
        const auto o = static_cast<std::size_t>(opposite);
        if (valence[o] + added[o] + 1 <= max_valence) ++added[o];
        else red[f] = true, changed = true;
      }
      if (count >= 2) red[f] = true, changed = true;
    }
  }
  Mesh out;
  out.positions = mesh.positions;
  for (auto& [edge, vertex] : split) {
    vertex = static_cast<int>(out.positions.size());
    const Point& a = mesh.positions[static_cast<std::size_t>(edge.first)];
    const Point& b = mesh.positions[static_cast<std::size_t>(edge.second)];
    out.positions.push_back({(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2});
  }
  const auto triangle = [&](int a, int b, int c) {
    out.face_sizes.push_back(3);
    out.face_vertices.insert(out.face_vertices.end(), {a, b, c});
  };
  for (std::size_t f = 0; f < faces; ++f) {
    const int v[3] = {corner(f, 0), corner(f, 1), corner(f, 2)};
    int mid[3];  // mid[c]: the midpoint of edge v[c] -> v[c+1], or -1
    for (int c = 0; c < 3; ++c) {
      const auto it = split.find(key(v[c], v[(c + 1) % 3]));
      mid[c] = it == split.end() ? -1 : it->second;
    }
    if (red[f]) {  // 1-to-4, orientation kept
      triangle(v[0], mid[0], mid[2]);
      triangle(mid[0], v[1], mid[1]);
      triangle(mid[2], mid[1], v[2]);
      triangle(mid[0], mid[1], mid[2]);
      continue;
    }
    int c = 0;
    while (c < 3 && mid[c] < 0) ++c;
    if (c == 3) {
      triangle(v[0], v[1], v[2]);
      continue;
    }
    // Green: the one split edge v[c] -> v[c+1] bisected towards the opposite corner.
    const int a = v[c], b = v[(c + 1) % 3], o = v[(c + 2) % 3];
    triangle(a, mid[c], o);
    triangle(mid[c], b, o);
  }
  return out;
}

}  // namespace stencil_runtime
