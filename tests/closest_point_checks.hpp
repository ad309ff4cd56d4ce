#pragma once
// Closest points checked against dense exact samples of the surface, as the
// tests of boundaries, creases, sectors and random meshes check them.
#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "runtime_api.hpp"
#include "runtime_checks.hpp"
#include "stencil_runtime/closest_point.hpp"

namespace test_runtime {

// Every node at rate n of every face of `mesh` that has a surface and is a
// triangle (triangle schemes) or a quad (quad schemes): dense exact samples.
inline std::vector<stencil_runtime::Point> surface_nodes(const stencil_runtime::Surface& surface, const stencil_runtime::Mesh& mesh,
                                                         long n) {
  const bool triangle = surface.topology().tables().family() == stencil_runtime::SchemeFamily::Triangle;
  std::vector<stencil_runtime::Point> out;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    if (surface.topology().is_hole(f) || mesh.face_sizes[f] != (triangle ? 3 : 4)) continue;
    for (long j = 0; j <= n; ++j)
      for (long i = 0; i + (triangle ? j : 0) <= n; ++i) out.push_back(surface.evaluate(f, grid(i, j, n)));
  }
  return out;
}

// A point uniform in the box of `samples` widened on each side by `margin`.
inline stencil_runtime::Point random_query(const std::vector<stencil_runtime::Point>& samples, double margin, std::mt19937& rng) {
  stencil_runtime::Point lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300}, q{};
  for (const stencil_runtime::Point& s : samples)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], s[k]), hi[k] = std::max(hi[k], s[k]);
  for (int k = 0; k < 3; ++k) q[k] = std::uniform_real_distribution<double>(lo[k] - margin, hi[k] + margin)(rng);
  return q;
}

// What is wrong with `found`, the closest point to q, or "" when nothing is:
// it is found, it is the surface's point at its parameters, it lies at the
// distance it states, and it is no farther than the nearest of `samples`
// (plus `slack`). `size`: the mesh's, for the tolerances.
inline std::string closest_point_defect(const stencil_runtime::Surface& surface, const stencil_runtime::Point& q,
                                        const stencil_runtime::ClosestPoint& found, const std::vector<stencil_runtime::Point>& samples,
                                        double size, double slack) {
  if (!found.found) return "closest point: none found";
  if (distance(surface.evaluate(found.face, found.u, found.v, 1e-12).point, found.point) > 1e-9 * size)
    return "closest point: not the surface's point at its parameters";
  if (std::abs(distance(q, found.point) - found.distance) > 1e-9 * size) return "closest point: not at the distance it states";
  double nearest = 1e300;
  for (const stencil_runtime::Point& s : samples) nearest = std::min(nearest, distance(q, s));
  if (found.distance > nearest + slack)
    return "closest point: " + std::to_string(found.distance / size) + " of the size away, a sample is at " + std::to_string(nearest / size);
  return "";
}

}  // namespace test_runtime
