#pragma once
// What the tessellation benchmarks share: the median of three timed runs, and
// one whole static tessellation (plan and points) as bench_tessellation times it.
#include <algorithm>
#include <chrono>
#include <cstddef>
#include <vector>

#include "stencil_runtime/tessellation.hpp"

namespace bench_timing {

// The median of three calls of f, each returning its own seconds.
template <class F>
double median3(F f) {
  double t[3] = {f(), f(), f()};
  std::sort(t, t + 3);
  return t[1];
}

// Seconds for a plan and the points of the surface at `rates`; `triangles` gets the count.
inline double tessellation_seconds(const stencil_runtime::Surface& surface, const std::vector<int>& rates, int threads,
                                   std::size_t& triangles) {
  const auto start = std::chrono::steady_clock::now();
  const stencil_runtime::TessellationPlan plan(surface.shared_topology(), rates, {threads});
  stencil_runtime::PolygonSoup soup = plan.make_soup();
  plan.evaluate(surface, soup.positions.data());
  triangles = soup.triangle_count();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace bench_timing
