#pragma once
// A polygon mesh as OpenSubdiv's Far::TopologyDescriptor takes it: per-face
// vertex counts, the concatenated face-vertex indices, and positions.
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace stencil_runtime {

struct MeshError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Mesh {
  std::vector<std::array<double, 3>> positions;
  std::vector<int> face_sizes;
  std::vector<int> face_vertices;  // concatenated, counter-clockwise seen from outside

  std::size_t face_count() const { return face_sizes.size(); }
  std::size_t vertex_count() const { return positions.size(); }
};

// Wavefront OBJ: `v x y z` and `f a b c ...` lines (1-based or negative
// indices, `a/t/n` forms accepted, other lines ignored). Throws MeshError
// naming the file and line.
Mesh read_obj(const std::string& path);

// Output of a tessellation: positions and polygons (triangles and quads).
struct PolygonSoup {
  std::vector<std::array<float, 3>> positions;
  std::vector<std::array<int, 4>> quads;
  std::vector<std::array<int, 3>> triangles;
  std::size_t triangle_count() const { return triangles.size() + 2 * quads.size(); }
};

// OBJ (text) or binary little-endian PLY, chosen by the extension (.obj/.ply).
// Writes to a temporary file and renames it, so a failure leaves nothing behind.
void write_polygons(const PolygonSoup& soup, const std::string& path);

}  // namespace stencil_runtime
