#pragma once
// Per-face tessellation rates for stenciltess: uniform, from a file, from a
// curvature estimate with a tolerance, or view-dependent (camera + target
// edge length in pixels). Rates are for the original faces; each is rounded up
// to a rate the tables hold.
#include <array>
#include <string>
#include <vector>

#include "stencil_runtime/mesh.hpp"
#include "stencil_runtime/surface_table.hpp"

namespace stencil_tools {

// One integer per line (blank lines and # comments skipped), one per face.
std::vector<int> rates_from_file(const std::string& path, std::size_t faces);

// Curvature estimate: the largest second difference D of the face's control
// polygon and its neighbours (|p(i-1) - 2 p(i) + p(i+1)| over the face's
// 4x4 neighbourhood rows and columns, measured on the one-ring) bounds the
// deviation of a sampled patch from the surface by about D / (8 n^2); the rate
// is the smallest n with D / (8 n^2) <= tolerance.
std::vector<int> rates_for_tolerance(const stencil_runtime::Mesh& mesh, double tolerance);

struct Camera {
  std::array<double, 3> eye{0, 0, 5}, target{0, 0, 0};
  double fov_degrees = 60;
  int width_pixels = 1920;
};
// The face's longest edge, projected (perspective) to pixels, divided by the
// target edge length; faces behind the camera get rate 1.
std::vector<int> rates_for_view(const stencil_runtime::Mesh& mesh, const Camera& camera, double target_pixels);

// Each rate rounded up to one the tables hold.
void snap_to_tables(std::vector<int>& rates, const stencil_runtime::SurfaceTables& tables);

}  // namespace stencil_tools
