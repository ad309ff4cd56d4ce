#pragma once
// What the checks of the refinement round semi-sharp features share
// (test_semi_sharp_levels.cpp for quads, test_loop_semi_sharp_levels.cpp):
// surfaces prepared one way or the other, and comparisons at the faces' nodes.
#include <algorithm>
#include <catch2/catch.hpp>
#include <map>
#include <memory>
#include <random>

#include "bfr_reference.hpp"
#include "closest_point_checks.hpp"
#include "runtime_api.hpp"
#include "runtime_checks.hpp"
#include "sharp_features.hpp"
#include "family/semi_sharp_levels.hpp"

namespace test_runtime {

// Chooses the families' way with semi-sharp features while alive.
struct RefinementChoice {
  stencil_runtime::CreaseRefinementChoice before = stencil_runtime::crease_refinement_choice();
  explicit RefinementChoice(stencil_runtime::CreaseRefinementChoice c) { stencil_runtime::set_crease_refinement_choice(c); }
  ~RefinementChoice() { stencil_runtime::set_crease_refinement_choice(before); }
};

inline stencil_runtime::Surface surface_of(const std::shared_ptr<const stencil_runtime::Tables>& tables,
                                           const stencil_runtime::Mesh& mesh, const SharpFeatures& f) {
  return stencil_runtime::Surface(
      stencil_runtime::SurfaceTopology::create(tables, mesh.vertex_count(), mesh.face_sizes, mesh.face_vertices, {}, f.ours),
      mesh.positions);
}

// The surface prepared the given way.
inline stencil_runtime::Surface surface_by(stencil_runtime::CreaseRefinementChoice choice,
                                           const std::shared_ptr<const stencil_runtime::Tables>& tables,
                                           const stencil_runtime::Mesh& mesh, const SharpFeatures& f) {
  const RefinementChoice chosen(choice);
  return surface_of(tables, mesh, f);
}

// Whether the mesh's faces are triangles (Loop's nodes: i + j <= n).
inline bool triangle_mesh(const stencil_runtime::Mesh& mesh) { return !mesh.face_sizes.empty() && mesh.face_sizes[0] == 3; }

// Largest distance over the size between two surfaces at every node of every face at rates 1..8.
inline double node_difference(const stencil_runtime::Surface& a, const stencil_runtime::Surface& b,
                              const stencil_runtime::Mesh& mesh) {
  const bool triangles = triangle_mesh(mesh);
  double worst = 0;
  for (std::size_t face = 0; face < mesh.face_count(); ++face)
    for (long n = 1; n <= 8 && !a.topology().is_hole(face); ++n)
      for (long j = 0; j <= n; ++j)
        for (long i = 0; i + (triangles ? j : 0) <= n; ++i)
          worst = std::max(worst, distance(a.evaluate(face, grid(i, j, n)), b.evaluate(face, grid(i, j, n))));
  return worst / extent(mesh);
}

// Largest distance over the size from our surface at every node of rate `n` of every face to Bfr's.
inline double bfr_node_difference(const stencil_runtime::Surface& ours, const stencil_runtime::Mesh& mesh,
                                  const SharpFeatures& f, long n) {
  const bool triangles = triangle_mesh(mesh);
  bfr_reference::BfrLimit bfr(mesh.positions, mesh.face_sizes, mesh.face_vertices,
                              triangles ? bfr_reference::osd::Sdc::SCHEME_LOOP : bfr_reference::osd::Sdc::SCHEME_CATMARK, {},
                              f.osd);
  double worst = 0;
  for (std::size_t face = 0; face < mesh.face_count(); ++face)
    for (long j = 0; j <= n && !ours.topology().is_hole(face); ++j)
      for (long i = 0; i + (triangles ? j : 0) <= n; ++i)
        worst = std::max(worst, distance(ours.evaluate(face, grid(i, j, n)),
                                         bfr.evaluate(static_cast<int>(face), static_cast<double>(i) / n, static_cast<double>(j) / n)));
  return worst / extent(mesh);
}

// Whether every edge of the soup is shared by exactly two of its polygons (a closed surface).
inline bool closed(const stencil_runtime::PolygonSoup& soup) {
  std::map<std::pair<int, int>, int> uses;
  auto edge = [&](int a, int b) { ++uses[{std::min(a, b), std::max(a, b)}]; };
  for (const auto& q : soup.quads)
    for (int k = 0; k < 4; ++k) edge(q[static_cast<std::size_t>(k)], q[static_cast<std::size_t>((k + 1) % 4)]);
  for (const auto& t : soup.triangles)
    for (int k = 0; k < 3; ++k) edge(t[static_cast<std::size_t>(k)], t[static_cast<std::size_t>((k + 1) % 3)]);
  for (const auto& [e, n] : uses)
    if (n != 2) return false;
  return !uses.empty();
}

// Closest points on `ours`, at 100 queries on `reference` (the same surface
// prepared another way) and round it: each at the surface's point at its
// parameters, and no dense sample of `reference` nearer.
inline void check_closest_points(const stencil_runtime::Surface& ours, const stencil_runtime::Surface& reference,
                                 const stencil_runtime::Mesh& mesh, std::mt19937& rng) {
  const stencil_runtime::ClosestPointQuery query(ours);
  const std::vector<stencil_runtime::Point> samples = surface_nodes(reference, mesh, 8);
  for (int k = 0; k < 100; ++k) {
    const stencil_runtime::Point q = k % 2 ? random_query(samples, 0.3 * extent(mesh), rng) : samples[rng() % samples.size()];
    INFO("closest point query " << k);
    CHECK(closest_point_defect(ours, q, query.find(q), samples, extent(mesh), 1e-9 * extent(mesh)) == "");
  }
}

}  // namespace test_runtime
