#pragma once
// Conveniences over the runtime's public interface for the tests: a surface
// from tables and a mesh, and evaluation at grid parameters (i/n, j/n).
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

}  // namespace test_runtime
