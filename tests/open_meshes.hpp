#pragma once
// Meshes with boundaries for the tests: open grids, tubes, bundled meshes
// without a face.
#include <cmath>
#include <functional>
#include <filesystem>
#include <string>
#include <vector>

#include "bundled_meshes.hpp"
#include "stencil_runtime/mesh.hpp"
#include "stencil_runtime/mesh_io.hpp"

namespace test_meshes {

using stencil_runtime::Mesh;

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

// A vertex on the boundary in k faces: k sectors of K x K quads round it,
// spanning a half disc (sector s's (0, b) is sector s+1's (b, 0); the first
// sector's (a, 0) and the last one's (0, b) run along the boundary), with
// uneven heights. Vertex 0 is the one in k faces.
inline Mesh boundary_fan(int k, int K) {
  Mesh m;
  std::vector<int> id(static_cast<std::size_t>(k * (K + 1) * (K + 1)), -1);
  std::function<int(int, int, int)> vertex = [&](int s, int a, int b) -> int {
    if (a == 0 && b == 0) s = 0;
    else if (a == 0 && s + 1 < k) return vertex(s + 1, b, 0);  // sector s's (0, b) is sector s+1's (b, 0)
    int& slot = id[static_cast<std::size_t>((s * (K + 1) + a) * (K + 1) + b)];
    if (slot < 0) {
      slot = static_cast<int>(m.positions.size());
      const double r = a + b, angle = M_PI * (s + (r > 0 ? b / r : 0)) / k;
      m.positions.push_back({r * std::cos(angle) + 0.05 * b, r * std::sin(angle) + 0.03 * a * b,
                             0.25 * std::sin(0.9 * a + 1.3 * b + s) + 0.05 * r * r});
    }
    return slot;
  };
  for (int s = 0; s < k; ++s)
    for (int b = 0; b < K; ++b)
      for (int a = 0; a < K; ++a) {
        m.face_sizes.push_back(4);
        m.face_vertices.insert(m.face_vertices.end(),
                               {vertex(s, a, b), vertex(s, a + 1, b), vertex(s, a + 1, b + 1), vertex(s, a, b + 1)});
      }
  return m;
}

// An L of three quads of an open 2x2 grid: its inner corner (vertex 4) is on the boundary in three faces.
inline Mesh l_shape() {
  Mesh m = open_grid(2, 2);
  m.face_sizes.pop_back();
  m.face_vertices.resize(m.face_vertices.size() - 4);
  m.positions.pop_back();  // the far corner is in no face now
  return m;
}

}  // namespace test_meshes
