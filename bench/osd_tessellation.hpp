#pragma once
// The OpenSubdiv side of the tessellation throughput benchmark: exactly what
// OpenSubdiv 3.5's CPU tessellation path (Bfr::SurfaceFactory, Bfr::Surface,
// Bfr::Tessellation) does for a Catmull-Clark surface, face by face, the way
// its own tutorials (bfr/tutorial_1_2) do it, but writing into preallocated
// flat arrays instead of an OBJ file.
//
// OpenSubdiv stays out of this header (pimpl); link the source with
// libosdCPU (find_library(osdCPU)) and oneTBB (TBB::tbb).
#include <array>
#include <cstddef>
#include <memory>
#include <vector>

namespace osd_bench {

// The same layout as stencil_runtime::Mesh (runtime/include/stencil_runtime/mesh.hpp):
// positions, per-face vertex counts, concatenated counter-clockwise face-vertex indices.
// The vectors are read only by the constructor.
struct Input {
  const std::vector<std::array<double, 3>>* positions;
  const std::vector<int>* face_sizes;
  const std::vector<int>* face_vertices;
  bool loop = false;  // Loop (triangle meshes) instead of Catmull-Clark
  // Optional semi-sharp creases: two vertices per edge, one sharpness per edge.
  const std::vector<int>* crease_pairs = nullptr;
  const std::vector<float>* crease_sharpness = nullptr;
};

struct Result {
  std::size_t triangles = 0;  // facets written (all triangles)
  std::size_t points = 0;     // points evaluated (points on shared edges counted once per face, as Bfr does)
  double seconds = 0;         // wall time of the per-face work only
};

// How the one SurfaceFactory shared by all threads caches the irregular
// patches it builds (only faces next to extraordinary vertices use the cache).
enum class FactoryCache {
  ThreadSafe,  // Bfr::SurfaceFactoryCacheThreaded over std::shared_mutex (the docs' preferred setup)
  Disabled,    // SurfaceFactory::Options::EnableCaching(false): no shared mutable state at all
};

class BfrTessellator {
 public:
  // Setup, not timed: converts positions to float, builds the
  // Far::TopologyRefiner (SCHEME_CATMARK or SCHEME_LOOP, VTX_BOUNDARY_EDGE_ONLY) and one
  // Bfr::RefinerSurfaceFactory. Throws std::invalid_argument on an
  // inconsistent mesh and std::runtime_error if OpenSubdiv rejects it.
  explicit BfrTessellator(const Input& mesh, FactoryCache cache = FactoryCache::ThreadSafe);
  ~BfrTessellator();
  BfrTessellator(const BfrTessellator&) = delete;
  BfrTessellator& operator=(const BfrTessellator&) = delete;

  // Tessellates every face into triangles with a uniform per-face rate
  // face_rates[f] >= 1 (rate N on a quad: (N+1)^2 points, 2 N^2 triangles),
  // positions only, Bfr::Surface<float>. Before the clock starts, the output
  // arrays are sized from the tessellation counts and the per-thread scratch
  // is reserved. Timed: for every face, InitVertexSurface from the factory,
  // the Bfr::Tessellation and its coordinates, PreparePatchPoints, Evaluate at
  // every coordinate straight into the flat position array, GetFacets straight
  // into the flat index array and TransformFacetCoordIndices to global point
  // indices. threads == 1 runs a plain loop; threads > 1 a tbb::parallel_for
  // over faces in a task_arena of that many threads, each thread with its own
  // Surface and buffers. Neighbouring faces with different rates are not
  // stitched (edge rates are not matched), just as with a uniform per-face rate in Bfr.
  Result run(const std::vector<int>& face_rates, int threads);

  // The output of the last run: xyz per point, three point indices per triangle
  // (counter-clockwise seen from outside for a consistently oriented input).
  const std::vector<float>& positions() const;
  const std::vector<int>& triangles() const;
  // First point / first triangle of face f in the last run (size face_count() + 1).
  const std::vector<std::size_t>& point_offsets() const;
  const std::vector<std::size_t>& triangle_offsets() const;

  std::size_t face_count() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace osd_bench
