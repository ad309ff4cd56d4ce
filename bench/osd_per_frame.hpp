#pragma once
// The OpenSubdiv side of the per-frame benchmark: a deforming Catmull-Clark
// mesh, topology and patch tables built once, then per frame new control
// positions in and limit points at fixed (face, u, v) samples out, by
// OpenSubdiv 3.5's two fastest CPU paths:
//  - Far + Osd: adaptive TopologyRefiner, Far::PatchTable (Gregory end caps) and
//    the StencilTable of its refined and local points, built once; per frame
//    Osd::CpuEvaluator (or OmpEvaluator for several threads)::EvalStencils, then
//    ::EvalPatches at precomputed PatchCoords.
//  - Bfr: one Bfr::Surface<float> per face, built once; per frame
//    PreparePatchPoints and Evaluate at each sample (tbb::parallel_for over faces).
// OpenSubdiv stays out of this header (pimpl).
#include <array>
#include <memory>
#include <vector>

namespace osd_bench {

struct FaceSamples {
  // Per face, the (u, v) pairs of its samples (2 floats each), in output order.
  std::vector<std::vector<float>> uv;
};

class PerFrame {
 public:
  // Not timed: both paths' tables and caches, and the patch coordinates of every sample.
  PerFrame(const std::vector<std::array<double, 3>>& positions, const std::vector<int>& face_sizes,
           const std::vector<int>& face_vertices, const FaceSamples& samples);
  ~PerFrame();
  PerFrame(const PerFrame&) = delete;
  PerFrame& operator=(const PerFrame&) = delete;

  std::size_t samples() const;
  // One frame; returns seconds (new positions converted to float, stencils, patches).
  double eval_patches(const std::vector<std::array<double, 3>>& positions, int threads);
  double bfr(const std::vector<std::array<double, 3>>& positions, int threads);
  // xyz per sample of the last frame.
  const std::vector<float>& output() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace osd_bench
