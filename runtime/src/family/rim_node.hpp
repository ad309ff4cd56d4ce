#pragma once
// A point of a tessellation's rim (family/seam_polygons.hpp): where the surface
// ends, at the mesh's boundary or round a hole.
#include <cstdint>

namespace stencil_runtime {

struct RimNode {
  std::uint32_t face = 0;    // a prepared face that has the point on its edge `corner` -> `corner` + 1
  int corner = 0, t = 0;     // grid node t (0..n) along that edge at the face's rate n
  std::uint32_t beside = 0;  // a face point next to it (a tessellation point index)
};

}  // namespace stencil_runtime
