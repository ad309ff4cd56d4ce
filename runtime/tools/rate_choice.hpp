#pragma once
// Per-face tessellation rates for stenciltess: uniform, from a file, from a
// curvature estimate with a tolerance, or view-dependent (camera + target
// edge length in pixels). Rates are for the original faces; each is rounded up
// to a rate the tables hold.
#include <array>
#include <string>
#include <vector>

#include "stencil_runtime/mesh.hpp"

namespace stencil_tools {

// One integer per line (blank lines and # comments skipped), one per face.
std::vector<int> rates_from_file(const std::string& path, std::size_t faces);

// Curvature estimate: the largest second difference D of the control net at
// the face's corners (|a - 2 p + b| along the lattice lines through each corner
// p, and for quads the face's twist) bounds the deviation of a sampled patch
// from the surface by about D / (8 n^2); the rate is the smallest n with
// D / (8 n^2) <= tolerance. `corners`: 4 for a quad mesh, 3 for a triangle mesh.
std::vector<int> rates_for_tolerance(const stencil_runtime::Mesh& mesh, double tolerance, int corners);

struct Camera {
  std::array<double, 3> eye{0, 0, 5}, target{0, 0, 0};
  double fov_degrees = 60;
  int width_pixels = 1920;
};
// The face's longest edge, projected (perspective) to pixels, divided by the
// target edge length; faces behind the camera get rate 1.
std::vector<int> rates_for_view(const stencil_runtime::Mesh& mesh, const Camera& camera, double target_pixels);

// Each rate rounded up to one of the tables' rates (ascending).
void snap_to_tables(std::vector<int>& rates, const std::vector<int>& table_rates);

}  // namespace stencil_tools
