#pragma once
// Meshes with boundaries for the tests: open grids, tubes, bundled meshes
// without a face.
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "stencil_runtime/mesh.hpp"
#include "stencil_runtime/mesh_io.hpp"

namespace test_meshes {

using stencil_runtime::Mesh;

inline const std::filesystem::path kMeshes = std::filesystem::path(STENCIL_SOURCE_DIR) / "meshes";

// An open (columns x rows) grid of quads with uneven heights.
inline Mesh open_grid(int columns, int rows) {
  Mesh m;
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i <= columns; ++i)
      m.positions.push_back({i + 0.1 * std::sin(3.0 * j), j + 0.07 * i * i / columns, 0.3 * std::sin(1.3 * i + 0.7 * j)});
  auto at = [&](int i, int j) { return j * (columns + 1) + i; };
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      m.face_sizes.push_back(4);
      m.face_vertices.insert(m.face_vertices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return m;
}

// A tube of `around` x `rows` quads, open at both ends: every boundary vertex in two faces.
inline Mesh tube(int around, int rows) {
  Mesh m;
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i < around; ++i) {
      const double a = 2 * M_PI * i / around, r = 1 + 0.15 * std::cos(2.0 * j + i);
      m.positions.push_back({r * std::cos(a), r * std::sin(a), 0.6 * j + 0.05 * (i % 3)});
    }
  auto at = [&](int i, int j) { return j * around + (i % around); };
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < around; ++i) {
      m.face_sizes.push_back(4);
      m.face_vertices.insert(m.face_vertices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return m;
}

// A bundled closed mesh without its first face (for the cube: a box open at
// the top, its rim vertices in two faces, extraordinary vertices next to them).
inline Mesh without_first_face(const std::string& name) {
  Mesh m = stencil_runtime::read_obj((kMeshes / (name + ".obj")).string());
  const int k = m.face_sizes.front();
  m.face_sizes.erase(m.face_sizes.begin());
  m.face_vertices.erase(m.face_vertices.begin(), m.face_vertices.begin() + k);
  return m;
}

// The cube with a pyramid roof of four triangles over its first face (the
// polygon step); `open`: without its second face too, a mesh with a boundary.
inline Mesh house(bool open = false) {
  Mesh m = stencil_runtime::read_obj((kMeshes / "cube.obj").string());
  const std::vector<int> top(m.face_vertices.begin(), m.face_vertices.begin() + 4);
  stencil_runtime::Point centre{0, 0, 0};
  for (int v : top)
    for (std::size_t k = 0; k < 3; ++k) centre[k] += m.positions[static_cast<std::size_t>(v)][k] / 4;
  const int apex = static_cast<int>(m.positions.size());
  m.positions.push_back({1.5 * centre[0], 1.5 * centre[1], 1.5 * centre[2]});
  const std::size_t dropped = open ? 2 : 1, corners = open ? 8 : 4;  // the top (and the next face), quads
  std::vector<int> sizes(m.face_sizes.begin() + static_cast<long>(dropped), m.face_sizes.end());
  std::vector<int> vertices(m.face_vertices.begin() + static_cast<long>(corners), m.face_vertices.end());
  for (int c = 0; c < 4; ++c) {
    sizes.push_back(3);
    vertices.insert(vertices.end(), {top[static_cast<std::size_t>(c)], top[static_cast<std::size_t>((c + 1) % 4)], apex});
  }
  m.face_sizes = sizes;
  m.face_vertices = vertices;
  return m;
}

}  // namespace test_meshes
