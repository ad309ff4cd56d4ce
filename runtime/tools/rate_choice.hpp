#pragma once
// Per-face tessellation rates for stenciltess: uniform, from a file, from a
// curvature estimate with a tolerance, or view-dependent (camera + target
// edge length in pixels). Rates are for the original faces, within
// 1..limits::kMaxRate; the tessellation rounds each up to a rate the tables hold.
#include <array>
#include <string>
#include <vector>

#include "stencil_runtime/mesh.hpp"

namespace stencil_tools {

// One integer per line (blank lines and # comments skipped), one per face.
std::vector<int> rates_from_file(const std::string& path, std::size_t faces);

// Curvature estimate: the largest second difference D of the control net at
// the face's corners (|a - 2 p + b| along the lines through each corner p:
// a the next corner, b the neighbour opposite it half the valence round; for
// quads also the face's twist) bounds the deviation of a sampled patch from
// the surface by about D / (8 n^2); the rate is the smallest n with
// D / (8 n^2) <= tolerance, at most limits::kMaxRate. Any polygon mesh.
std::vector<int> rates_for_tolerance(const stencil_runtime::Mesh& mesh, double tolerance);

struct Camera {
  std::array<double, 3> eye{0, 0, 5}, target{0, 0, 0};
  double fov_degrees = 60;
  int width_pixels = 1920;
};
// "EX,EY,EZ,TX,TY,TZ" (eye and target).
Camera parse_camera(const std::string& text);
// The face's longest edge, projected (perspective) to pixels, divided by the
// target edge length; faces behind the camera get rate 1; at most limits::kMaxRate.
std::vector<int> rates_for_view(const stencil_runtime::Mesh& mesh, const Camera& camera, double target_pixels);

}  // namespace stencil_tools
