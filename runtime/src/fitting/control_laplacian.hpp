#pragma once
// The smoothing term's operator: the umbrella Laplacian of the control mesh,
// row i = P_i - (mean of the vertices that share an edge with i).
#include <Eigen/SparseCore>

#include <cstddef>
#include <vector>

namespace stencil_runtime::fitting {

Eigen::SparseMatrix<double> control_laplacian(std::size_t vertex_count, const std::vector<int>& face_sizes,
                                              const std::vector<int>& face_vertices);

}  // namespace stencil_runtime::fitting
