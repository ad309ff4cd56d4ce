#pragma once
// Conveniences over the runtime's public interface for the tests: a surface
// from tables and a mesh, and evaluation at grid parameters (i/n, j/n).
#include <array>
#include <memory>

#include "stencil_runtime/mesh_io.hpp"
#include "stencil_runtime/surface.hpp"
#include "stencil_runtime/tessellation.hpp"

namespace test_runtime {

using namespace stencil_runtime;

inline std::shared_ptr<const SurfaceTopology> topology_of(const std::shared_ptr<const Tables>& tables, const Mesh& mesh) {
  return SurfaceTopology::create(tables, mesh.vertex_count(), mesh.face_sizes, mesh.face_vertices);
}

inline Surface surface_of(const std::shared_ptr<const Tables>& tables, const Mesh& mesh) {
  return Surface(topology_of(tables, mesh), mesh.positions);
}

inline ExactParameter grid(long i, long j, long n) { return {Fraction::make(i, n), Fraction::make(j, n)}; }

inline Point at_grid(const Surface& surface, std::size_t face, long i, long j, long n) {
  return surface.evaluate(face, grid(i, j, n));
}

// Central difference quotients of exact limit points at `at` with the step h,
// along u and along v: (f(u + h, v) - f(u - h, v)) / 2h and likewise in v.
// `inverse_2h` is 1 / 2h as a double.
inline std::array<Point, 2> central_quotients(const Surface& surface, std::size_t face, const ExactParameter& at,
                                              const Fraction& h, double inverse_2h) {
  auto quotient = [&](const ExactParameter& plus, const ExactParameter& minus) {
    const Point a = surface.evaluate(face, plus), b = surface.evaluate(face, minus);
    return Point{(a[0] - b[0]) * inverse_2h, (a[1] - b[1]) * inverse_2h, (a[2] - b[2]) * inverse_2h};
  };
  return {quotient({add(at.u, h), at.v}, {subtract(at.u, h), at.v}), quotient({at.u, add(at.v, h)}, {at.u, subtract(at.v, h)})};
}

}  // namespace test_runtime
