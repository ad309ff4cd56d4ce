#pragma once
// A Loop surface against OpenSubdiv's Bfr with the same features and boundary
// option: every node of every face with a surface at rates 1..8, and d/du,
// d/dv at four parameters per face.
#include <algorithm>
#include <memory>
#include <set>
#include <utility>

#include "bfr_reference.hpp"
#include "runtime_api.hpp"
#include "runtime_checks.hpp"
#include "sharp_features.hpp"

// Largest differences over the mesh size: (positions, first derivatives).
// Checks that both have a surface on the same faces. `skip`: vertices whose
// own nodes are left out (darts: OpenSubdiv's limit there is the smooth one).
inline std::pair<double, double> loop_bfr_difference(const std::shared_ptr<const stencil_runtime::Tables>& tables,
                                                     const stencil_runtime::Mesh& mesh, const SharpFeatures& f,
                                                     const std::set<int>& skip = {}) {
  using namespace stencil_runtime;
  using namespace test_runtime;
  const Surface surface(SurfaceTopology::create(tables, mesh.vertex_count(), mesh.face_sizes, mesh.face_vertices, {}, f.ours),
                        mesh.positions);
  bfr_reference::BfrLimit reference(mesh.positions, mesh.face_sizes, mesh.face_vertices, bfr_reference::osd::Sdc::SCHEME_LOOP, {},
                                    f.osd);
  const double size = extent(mesh);
  double positions = 0, derivatives = 0;
  for (std::size_t face = 0; face < mesh.face_count(); ++face) {
    REQUIRE(reference.has_surface(static_cast<int>(face)) == !surface.topology().is_hole(face));
    if (surface.topology().is_hole(face)) continue;
    for (long n = 1; n <= 8; ++n)
      for (long j = 0; j <= n; ++j)
        for (long i = 0; i + j <= n; ++i) {
          const int corner = i == 0 && j == 0 ? 0 : i == n ? 1 : j == n ? 2 : -1;
          if (corner >= 0 && skip.count(mesh.face_vertices[3 * face + static_cast<std::size_t>(corner)])) continue;
          const auto ref = reference.evaluate(static_cast<int>(face), static_cast<double>(i) / n, static_cast<double>(j) / n);
          positions = std::max(positions, distance(surface.evaluate(face, grid(i, j, n)), ref) / size);
        }
    for (const auto& [u, v] : {std::pair{0.25, 0.25}, {0.6, 0.1}, {0.1, 0.7}, {0.4, 0.4}}) {
      const Derivatives d = surface.derivatives(face, u, v);
      const auto ref = reference.derivatives(static_cast<int>(face), u, v);
      derivatives = std::max({derivatives, distance(d.du, ref[1]) / size, distance(d.dv, ref[2]) / size});
    }
  }
  return {positions, derivatives};
}
