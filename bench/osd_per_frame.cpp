#include "osd_per_frame.hpp"

#include <omp.h>
#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/far/patchMap.h>
#include <opensubdiv/far/patchTableFactory.h>
#include <opensubdiv/far/stencilTableFactory.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>
#include <opensubdiv/osd/cpuEvaluator.h>
#include <opensubdiv/osd/cpuPatchTable.h>
#include <opensubdiv/osd/ompEvaluator.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <chrono>
#include <stdexcept>

namespace osd_bench {

using namespace OpenSubdiv;
using Clock = std::chrono::steady_clock;

namespace {

Far::TopologyRefiner* make_refiner(std::size_t vertices, const std::vector<int>& sizes, const std::vector<int>& indices) {
  Sdc::Options sdc;
  sdc.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
  Far::TopologyDescriptor desc;
  desc.numVertices = static_cast<int>(vertices);
  desc.numFaces = static_cast<int>(sizes.size());
  desc.numVertsPerFace = sizes.data();
  desc.vertIndicesPerFace = indices.data();
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  Far::TopologyRefiner* r = Factory::Create(desc, Factory::Options(Sdc::SCHEME_CATMARK, sdc));
  if (!r) throw std::runtime_error("OpenSubdiv refused the mesh");
  return r;
}

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

}  // namespace

struct PerFrame::Impl {
  std::size_t control = 0, total = 0;
  std::vector<std::size_t> first;  // first sample of each face
  std::vector<float> output;
  // Far + Osd
  std::unique_ptr<Far::TopologyRefiner> adaptive;
  std::unique_ptr<const Far::StencilTable> stencils;
  std::unique_ptr<const Far::PatchTable> patches;
  std::unique_ptr<Osd::CpuPatchTable> cpu_patches;
  std::vector<Osd::PatchCoord> coords;
  std::vector<float> vertices;  // control, then refined and local points
  // Bfr
  std::unique_ptr<Far::TopologyRefiner> base;
  std::unique_ptr<Bfr::RefinerSurfaceFactory<>> factory;
  std::vector<Bfr::Surface<float>> surfaces;
  std::vector<std::vector<float>> uv;
  std::vector<float> control_points;

  void load(const std::vector<std::array<double, 3>>& positions, float* into) const {
    for (std::size_t v = 0; v < positions.size(); ++v)
      for (int k = 0; k < 3; ++k) into[3 * v + static_cast<std::size_t>(k)] = static_cast<float>(positions[v][static_cast<std::size_t>(k)]);
  }
};

PerFrame::PerFrame(const std::vector<std::array<double, 3>>& positions, const std::vector<int>& sizes,
                   const std::vector<int>& indices, const FaceSamples& samples)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.control = positions.size();
  m.uv = samples.uv;
  m.first.assign(sizes.size() + 1, 0);
  for (std::size_t f = 0; f < sizes.size(); ++f) m.first[f + 1] = m.first[f] + samples.uv[f].size() / 2;
  m.output.assign(3 * m.first.back(), 0.0f);

  // Far + Osd: adaptive refinement round the extraordinary features, patches with
  // Gregory end caps, one stencil table for refined and local points.
  m.adaptive.reset(make_refiner(positions.size(), sizes, indices));
  Far::TopologyRefiner::AdaptiveOptions adaptive(2);
  m.adaptive->RefineAdaptive(adaptive);
  Far::PatchTableFactory::Options patch_options;
  patch_options.SetEndCapType(Far::PatchTableFactory::Options::ENDCAP_GREGORY_BASIS);
  m.patches.reset(Far::PatchTableFactory::Create(*m.adaptive, patch_options));
  Far::StencilTableFactory::Options stencil_options;
  stencil_options.generateOffsets = true;
  stencil_options.generateIntermediateLevels = true;
  const Far::StencilTable* refined = Far::StencilTableFactory::Create(*m.adaptive, stencil_options);
  if (const Far::StencilTable* local = m.patches->GetLocalPointStencilTable()) {
    const Far::StencilTable* all = Far::StencilTableFactory::AppendLocalPointStencilTable(*m.adaptive, refined, local);
    delete refined;
    refined = all;
  }
  m.stencils.reset(refined);
  m.cpu_patches.reset(Osd::CpuPatchTable::Create(m.patches.get()));
  m.total = static_cast<std::size_t>(m.adaptive->GetNumVerticesTotal()) + static_cast<std::size_t>(m.patches->GetNumLocalPoints());
  m.vertices.assign(3 * m.total, 0.0f);
  const Far::PatchMap map(*m.patches);
  m.coords.reserve(m.first.back());
  for (std::size_t f = 0; f < sizes.size(); ++f)
    for (std::size_t k = 0; k < samples.uv[f].size(); k += 2) {
      const float u = samples.uv[f][k], v = samples.uv[f][k + 1];
      const auto* handle = map.FindPatch(static_cast<int>(f), u, v);
      if (!handle) throw std::runtime_error("no patch for a sample");
      m.coords.emplace_back(*handle, u, v);
    }

  // Bfr: one surface per face.
  m.base.reset(make_refiner(positions.size(), sizes, indices));
  m.factory = std::make_unique<Bfr::RefinerSurfaceFactory<>>(*m.base);
  m.surfaces.resize(sizes.size());
  for (std::size_t f = 0; f < sizes.size(); ++f)
    if (!m.factory->InitVertexSurface(static_cast<int>(f), &m.surfaces[f])) throw std::runtime_error("Bfr has no surface");
  m.control_points.assign(3 * positions.size(), 0.0f);
}

PerFrame::~PerFrame() = default;

std::size_t PerFrame::samples() const { return impl_->first.back(); }
const std::vector<float>& PerFrame::output() const { return impl_->output; }

double PerFrame::eval_patches(const std::vector<std::array<double, 3>>& positions, int threads) {
  Impl& m = *impl_;
  const Osd::BufferDescriptor src(0, 3, 3), dst(static_cast<int>(3 * m.control), 3, 3), out(0, 3, 3);
  const auto t = Clock::now();
  m.load(positions, m.vertices.data());
  const int count = m.stencils->GetNumStencils();
  if (threads == 1) {
    Osd::CpuEvaluator::EvalStencils(m.vertices.data(), src, m.vertices.data(), dst, &m.stencils->GetSizes()[0],
                                    &m.stencils->GetOffsets()[0], &m.stencils->GetControlIndices()[0],
                                    &m.stencils->GetWeights()[0], 0, count);
    Osd::CpuEvaluator::EvalPatches(m.vertices.data(), src, m.output.data(), out, static_cast<int>(m.coords.size()), m.coords.data(),
                                   m.cpu_patches->GetPatchArrayBuffer(), m.cpu_patches->GetPatchIndexBuffer(),
                                   m.cpu_patches->GetPatchParamBuffer());
  } else {
    omp_set_num_threads(threads);
    Osd::OmpEvaluator::EvalStencils(m.vertices.data(), src, m.vertices.data(), dst, &m.stencils->GetSizes()[0],
                                    &m.stencils->GetOffsets()[0], &m.stencils->GetControlIndices()[0],
                                    &m.stencils->GetWeights()[0], 0, count);
    Osd::OmpEvaluator::EvalPatches(m.vertices.data(), src, m.output.data(), out, static_cast<int>(m.coords.size()), m.coords.data(),
                                   m.cpu_patches->GetPatchArrayBuffer(), m.cpu_patches->GetPatchIndexBuffer(),
                                   m.cpu_patches->GetPatchParamBuffer());
  }
  return since(t);
}

double PerFrame::bfr(const std::vector<std::array<double, 3>>& positions, int threads) {
  Impl& m = *impl_;
  tbb::task_arena arena(threads);
  const auto t = Clock::now();
  m.load(positions, m.control_points.data());
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, m.surfaces.size(), 256), [&](const tbb::blocked_range<std::size_t>& r) {
      thread_local std::vector<float> patch;
      for (std::size_t f = r.begin(); f != r.end(); ++f) {
        const Bfr::Surface<float>& s = m.surfaces[f];
        patch.resize(3 * static_cast<std::size_t>(s.GetNumPatchPoints()));
        s.PreparePatchPoints(m.control_points.data(), 3, patch.data(), 3);
        float* o = m.output.data() + 3 * m.first[f];
        const std::vector<float>& uv = m.uv[f];
        for (std::size_t k = 0; k < uv.size(); k += 2, o += 3) s.Evaluate(&uv[k], patch.data(), 3, o);
      }
    });
  });
  return since(t);
}

}  // namespace osd_bench
