#include "fitting/control_laplacian.hpp"

#include <algorithm>

namespace stencil_runtime::fitting {

Eigen::SparseMatrix<double> control_laplacian(std::size_t vertex_count, const std::vector<int>& face_sizes,
                                              const std::vector<int>& face_vertices) {
  // Each undirected edge once per side; a closed manifold mesh lists every
  // edge in two faces, so neighbours are deduplicated.
  std::vector<std::vector<int>> neighbours(vertex_count);
  std::size_t offset = 0;
  for (const int size : face_sizes) {
    for (int c = 0; c < size; ++c) {
      const int a = face_vertices[offset + static_cast<std::size_t>(c)];
      const int b = face_vertices[offset + static_cast<std::size_t>((c + 1) % size)];
      neighbours[static_cast<std::size_t>(a)].push_back(b);
      neighbours[static_cast<std::size_t>(b)].push_back(a);
    }
    offset += static_cast<std::size_t>(size);
  }
  std::vector<Eigen::Triplet<double>> entries;
  for (std::size_t i = 0; i < vertex_count; ++i) {
    auto& ring = neighbours[i];
    std::sort(ring.begin(), ring.end());
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    if (ring.empty()) continue;
    entries.emplace_back(static_cast<int>(i), static_cast<int>(i), 1.0);
    const double w = -1.0 / static_cast<double>(ring.size());
    for (const int j : ring) entries.emplace_back(static_cast<int>(i), j, w);
  }
  Eigen::SparseMatrix<double> laplacian(static_cast<Eigen::Index>(vertex_count), static_cast<Eigen::Index>(vertex_count));
  laplacian.setFromTriplets(entries.begin(), entries.end());
  return laplacian;
}

}  // namespace stencil_runtime::fitting
