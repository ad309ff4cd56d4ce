#pragma once
// A triangle control mesh bound to a triangle scheme's tables (Loop): evaluates
// limit points at the rational grid parameters the tables hold. The same layer
// as LimitSurface for quads: patch(face) gives a prepared face's control points
// and valence, stencil weights come straight from the tables.
#include <array>
#include <string>
#include <vector>

#include "limit_surface.hpp"
#include "triangle_patch.hpp"
#include "triangle_preparation.hpp"

namespace stencil_runtime {

class TriangleSurface {
 public:
  // Prepares the mesh (see prepare_triangle_mesh), which gathers every face's patch.
  TriangleSurface(const TriangleTables& tables, const Mesh& mesh, const std::string& scheme_name);

  std::size_t original_faces() const { return original_faces_; }
  const PreparedMesh& prepared() const { return prepared_; }
  const TrianglePatch& patch(std::size_t prepared_face) const { return patches_[prepared_face]; }
  const TriangleTopology& topology() const { return topology_; }  // of the prepared mesh
  const TriangleTables& tables() const { return tables_; }

  // Limit point of original face `face` at (i/n, j/n), i, j >= 0, i + j <= n, in
  // the face's parameterisation ((0,0) at its first vertex, u along v0->v1, v
  // along v0->v2). n must be a rate of the tables. Throws std::out_of_range
  // naming what is missing.
  Point evaluate(std::size_t face, long i, long j, long n) const;

  // Weights over patch(face).points at prepared-face parameter (a/(3n), b/(3n)):
  // a node (a, b multiples of 3), an up centre (both = 1 mod 3) or a down
  // centre (both = 2 mod 3). Throws std::out_of_range for other points.
  const double* stencil(std::size_t prepared_face, long a, long b, long n) const;

  // The n^2 centres of a prepared face's small triangles as floats: first the
  // n(n+1)/2 up centres ((3i+1)/(3n), (3j+1)/(3n)), i + j <= n-1, then the
  // n(n-1)/2 down centres ((3i+2)/(3n), (3j+2)/(3n)), i + j <= n-2, each row by
  // row (j-major), in the face's own parameterisation.
  void evaluate_centres(std::size_t prepared_face, int n, std::array<float, 3>* out) const;

 private:
  TriangleSurface(const TriangleTables& tables, std::size_t original_faces, PreparedTriangleMesh&& prepared);

  const TriangleTables& tables_;
  std::size_t original_faces_;
  PreparedMesh prepared_;
  TriangleTopology topology_;
  std::vector<TrianglePatch> patches_;
};

// Index of up centre (i, j) and down centre (i, j) among a face's n^2 centres
// (evaluate_centres order).
inline int up_centre_index(int i, int j, int n) { return j * n - j * (j - 1) / 2 + i; }
inline int down_centre_index(int i, int j, int n) { return n * (n + 1) / 2 + j * (n - 1) - j * (j - 1) / 2 + i; }

}  // namespace stencil_runtime
