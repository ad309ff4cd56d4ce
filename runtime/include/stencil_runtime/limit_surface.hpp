#pragma once
// A control mesh bound to a scheme's tables: evaluates limit points at the
// rational grid parameters the tables hold. This is the layer later queries
// (tangents, closest points, fitting) sit on: patch(face) gives the control
// points and table of a face, stencil() the weights at a grid parameter.
#include <array>
#include <string>
#include <vector>

#include "mesh_preparation.hpp"
#include "patch.hpp"
#include "surface_table.hpp"

namespace stencil_runtime {

using Point = std::array<double, 3>;

// sum_h weights[h] * positions[points[h]]: a stencil applied to a patch's control points.
inline Point apply_stencil(const double* weights, const std::vector<int>& points,
                           const std::vector<std::array<double, 3>>& positions) {
  Point out{0, 0, 0};
  for (std::size_t h = 0; h < points.size(); ++h) {
    const auto& q = positions[static_cast<std::size_t>(points[h])];
    for (int k = 0; k < 3; ++k) out[k] += weights[h] * q[k];
  }
  return out;
}

class LimitSurface {
 public:
  // Prepares the mesh (see prepare_mesh) and gathers every face's patch.
  LimitSurface(const SurfaceTables& tables, const Mesh& mesh, const std::string& scheme_name);

  std::size_t original_faces() const { return original_faces_; }
  const PreparedMesh& prepared() const { return prepared_; }
  const Patch& patch(std::size_t prepared_face) const { return patches_[prepared_face]; }
  const QuadTopology& topology() const { return topology_; }  // of the prepared mesh

  // Limit point of original face `face` at (i/n, j/n), 0 <= i, j <= n, in the
  // face's parameterisation ((0,0) at its first vertex, u along v0->v1, v along
  // v0->v3). n must be a rate of the tables. Throws std::out_of_range naming
  // what is missing.
  Point evaluate(std::size_t face, long i, long j, long n) const;

  // Weights of the prepared face's patch at face grid point (a/g, b/g) with
  // g = 2n (nodes: a, b even; cell centres: a, b odd) into `weights`
  // (patch(face).points.size() entries).
  void stencil(std::size_t prepared_face, long a, long b, long n, double* weights) const;

  // The n*n cell centres ((2i+1)/(2n), (2j+1)/(2n)) of a prepared face, row by
  // row (index j*n + i), as floats. Regular faces use the tensor-product form
  // (separable, 4+4 weights per point), the others the stored stencils directly.
  void evaluate_centres(std::size_t prepared_face, int n, std::array<float, 3>* out) const;

  const SurfaceTables& tables() const { return tables_; }

 private:
  const SurfaceTables& tables_;
  std::size_t original_faces_;
  PreparedMesh prepared_;
  QuadTopology topology_;
  std::vector<Patch> patches_;
};

}  // namespace stencil_runtime
