#pragma once
// A polygon mesh as OpenSubdiv's Far::TopologyDescriptor takes it: per-face
// vertex counts, the concatenated face-vertex indices (counter-clockwise seen
// from outside), and positions; and the polygons a tessellation produces.
#include <array>
#include <cstddef>
#include <vector>

#include "error.hpp"

namespace stencil_runtime {

using Point = std::array<double, 3>;

struct Mesh {
  std::vector<Point> positions;
  std::vector<int> face_sizes;
  std::vector<int> face_vertices;  // concatenated, counter-clockwise seen from outside

  std::size_t face_count() const { return face_sizes.size(); }
  std::size_t vertex_count() const { return positions.size(); }
};

// Output of a tessellation: positions (and unit normals when asked for) and
// polygons (quads and triangles) indexing them.
struct PolygonSoup {
  std::vector<std::array<float, 3>> positions;
  std::vector<std::array<float, 3>> normals;  // empty, or one per position
  std::vector<std::array<int, 4>> quads;
  std::vector<std::array<int, 3>> triangles;
  std::size_t triangle_count() const { return triangles.size() + 2 * quads.size(); }
};

}  // namespace stencil_runtime
