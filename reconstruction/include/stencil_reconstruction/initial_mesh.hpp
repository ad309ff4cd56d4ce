#pragma once
// Seed 004's step: a first control mesh from points alone, through CGAL
// (docs/fitting.md, "The initial mesh"): a large scan reduced to a subset,
// advancing-front surface reconstruction, the holes it leaves filled, then edge-collapse
// simplification down to the requested number of vertices. The result is a
// closed, manifold, consistently oriented triangle mesh whose vertices lie
// near the points; quad schemes take it through their polygon step.
// This library uses CGAL's exact predicates (GMP), so it stays out of the
// runtime; its interface has no CGAL types.
#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "stencil_runtime/mesh.hpp"

namespace stencil_reconstruction {

// The one error type of this layer.
struct ReconstructionError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct InitialMeshOptions {
  std::size_t control_points = 1000;  // vertices of the result (at least 4)
  // Scans larger than max(max_points_per_control_point * control_points,
  // min_points) are reduced to that many points (a fixed pseudo-random subset)
  // before the reconstruction, which with the simplification grows faster than
  // linearly in the points.
  std::size_t max_points_per_control_point = 40;
  std::size_t min_points = 50000;
  // Called with a short description of each stage as it starts.
  std::function<void(const std::string&)> progress;
};

struct InitialMeshReport {
  std::size_t points_used = 0;  // after the reduction of a large scan
  std::size_t reconstructed_vertices = 0, reconstructed_faces = 0;
  std::size_t holes_filled = 0, components_dropped = 0;
  double reconstruction_seconds = 0, repair_seconds = 0, simplification_seconds = 0;
};

// Throws ReconstructionError when there are fewer than 4 points, the points
// are coplanar, a
// coordinate is not finite, the reconstruction yields no closed surface, or
// control_points is below 4 or above the reconstructed vertex count.
stencil_runtime::Mesh initial_control_mesh(const std::vector<stencil_runtime::Point>& points,
                                           const InitialMeshOptions& options, InitialMeshReport* report = nullptr);

}  // namespace stencil_reconstruction
