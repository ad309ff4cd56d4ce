#pragma once
// Triangle meshes for Loop's boundaries and creases: uniformly triangulated
// tubes and tori (every inner vertex of valence 6, every rim vertex in three
// faces), and the same with one diagonal flipped (valence 5 and 7 next to it).
#include <algorithm>
#include <cmath>

#include "stencil_runtime/mesh.hpp"

namespace loop_meshes {

using stencil_runtime::Mesh;

// Vertex (i, j) of an `around` x `rows` lattice, i wrapping round, j wrapping
// when `rows_wrap` (a torus) and not otherwise (a tube with rows + 1 rings).
inline int lattice_vertex(int around, int rows, bool rows_wrap, int i, int j) {
  return (rows_wrap ? ((j % rows) + rows) % rows : j) * around + ((i % around) + around) % around;
}

// Each quad (i, j)-(i+1, j)-(i+1, j+1)-(i, j+1) split along the same diagonal.
inline void add_lattice_faces(Mesh& m, int around, int rows, bool rows_wrap) {
  auto at = [&](int i, int j) { return lattice_vertex(around, rows, rows_wrap, i, j); };
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < around; ++i) {
      m.face_sizes.insert(m.face_sizes.end(), {3, 3});
      m.face_vertices.insert(m.face_vertices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
}

// A tube of `around` x `rows` quads, each split into two triangles along the
// same diagonal: every inner vertex of valence 6, every rim vertex in three faces.
inline Mesh triangle_tube(int around, int rows) {
  Mesh m;
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i < around; ++i) {
      const double a = 2 * M_PI * (i + 0.5 * j) / around, r = 1 + 0.15 * std::cos(2.0 * j + i);
      m.positions.push_back({r * std::cos(a), r * std::sin(a), 0.6 * j + 0.05 * (i % 3)});
    }
  add_lattice_faces(m, around, rows, false);
  return m;
}

// A torus of `around` x `rows` quads split the same way: every vertex of valence 6.
inline Mesh triangle_torus(int around, int rows) {
  Mesh m;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < around; ++i) {
      const double a = 2 * M_PI * (i + 0.5 * j) / around, b = 2 * M_PI * j / rows;
      const double r = 0.6 + 0.08 * std::cos(3.0 * i + j), R = 2 + 0.1 * std::sin(1.0 * i * j);
      m.positions.push_back({(R + r * std::cos(b)) * std::cos(a), (R + r * std::cos(b)) * std::sin(a), r * std::sin(b)});
    }
  add_lattice_faces(m, around, rows, true);
  return m;
}

// `m` (from triangle_tube or triangle_torus) with the diagonal of quad
// (0, row) flipped: its two corners off the old diagonal go from valence 6 to 7,
// the two on it to 5 (inside; on a rim, from three faces to two or four).
inline Mesh with_flip(Mesh m, int around, int row) {
  const std::size_t f = 2 * static_cast<std::size_t>(row * around);  // quad (0, row): faces f, f + 1
  const int a = m.face_vertices[3 * f], b = m.face_vertices[3 * f + 1], c = m.face_vertices[3 * f + 2],
            d = m.face_vertices[3 * f + 5];
  // (a, b, c), (a, c, d) -> (a, b, d), (b, c, d)
  const int flipped[6] = {a, b, d, b, c, d};
  std::copy(flipped, flipped + 6, m.face_vertices.begin() + static_cast<long>(3 * f));
  return m;
}

}  // namespace loop_meshes
