// OpenSubdiv 3.5 Bfr tessellation, face by face, as in OpenSubdiv's
// bfr/tutorial_1_2 (Surface<float>, uniform Tessellation, PreparePatchPoints,
// Evaluate per coordinate, GetFacets), timed over the per-face work only.
#include "osd_tessellation.hpp"

#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/bfr/surfaceFactoryCache.h>
#include <opensubdiv/bfr/tessellation.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefiner.h>
#include <opensubdiv/far/topologyRefinerFactory.h>
#include <opensubdiv/sdc/options.h>
#include <opensubdiv/sdc/types.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <chrono>
#include <climits>
#include <mutex>
#include <shared_mutex>
#include <stdexcept>
#include <string>

namespace osd_bench {
namespace {

using namespace OpenSubdiv;

using ThreadSafeCache =
    Bfr::SurfaceFactoryCacheThreaded<std::shared_mutex, std::shared_lock<std::shared_mutex>,
                                     std::unique_lock<std::shared_mutex>>;
using ThreadSafeFactory = Bfr::RefinerSurfaceFactory<ThreadSafeCache>;
// With caching disabled the factory keeps no mutable state: thread-safe as is.
using UncachedFactory = Bfr::RefinerSurfaceFactory<>;

constexpr int kPointSize = 3;  // xyz, positions only
constexpr int kFacetSize = 3;  // triangles

// Per-thread scratch, reused face after face (as the tutorials advise).
struct Worker {
  Bfr::Surface<float> surface;
  std::vector<float> patch_points;
  std::vector<float> coords;
};

Far::TopologyRefiner* make_refiner(const Input& mesh) {
  if (!mesh.positions || !mesh.face_sizes || !mesh.face_vertices)
    throw std::invalid_argument("osd_bench: Input has a null vector");
  const auto& sizes = *mesh.face_sizes;
  const auto& verts = *mesh.face_vertices;
  const long long nv = static_cast<long long>(mesh.positions->size());
  if (nv == 0 || sizes.empty()) throw std::invalid_argument("osd_bench: empty mesh");
  if (nv > INT_MAX || sizes.size() > static_cast<std::size_t>(INT_MAX) || verts.size() > static_cast<std::size_t>(INT_MAX))
    throw std::invalid_argument("osd_bench: mesh too large for OpenSubdiv's int indices");
  std::size_t total = 0;
  for (int s : sizes) {
    if (s < 3) throw std::invalid_argument("osd_bench: face with fewer than 3 vertices");
    total += static_cast<std::size_t>(s);
  }
  if (total != verts.size()) throw std::invalid_argument("osd_bench: face_sizes do not add up to face_vertices.size()");
  for (int v : verts)
    if (v < 0 || v >= nv) throw std::invalid_argument("osd_bench: face vertex index out of range");

  Sdc::Options sdc;
  sdc.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);

  Far::TopologyDescriptor desc;
  desc.numVertices = static_cast<int>(nv);
  desc.numFaces = static_cast<int>(sizes.size());
  desc.numVertsPerFace = sizes.data();
  desc.vertIndicesPerFace = verts.data();
  if (mesh.crease_pairs && mesh.crease_sharpness) {
    if (mesh.crease_pairs->size() != 2 * mesh.crease_sharpness->size())
      throw std::invalid_argument("osd_bench: two crease vertices per sharpness");
    desc.numCreases = static_cast<int>(mesh.crease_sharpness->size());
    desc.creaseVertexIndexPairs = mesh.crease_pairs->data();
    desc.creaseWeights = mesh.crease_sharpness->data();
  }

  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  Far::TopologyRefiner* refiner = Factory::Create(desc, Factory::Options(mesh.loop ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK, sdc));
  if (!refiner) throw std::runtime_error("osd_bench: OpenSubdiv rejected the mesh topology");
  return refiner;
}

}  // namespace

struct BfrTessellator::Impl {
  std::unique_ptr<Far::TopologyRefiner> refiner;
  std::unique_ptr<Bfr::RefinerSurfaceFactoryBase> factory;
  std::vector<float> mesh_points;  // xyz per mesh vertex, float like the tutorials
  Bfr::Tessellation::Options tess_options;

  std::vector<Worker> workers;
  std::vector<float> out_positions;
  std::vector<int> out_triangles;
  std::vector<std::size_t> point_offsets{0};
  std::vector<std::size_t> triangle_offsets{0};

  int face_count() const { return factory->GetNumFaces(); }

  // The timed per-face work.
  void tessellate_face(int face, int rate, Worker& w) {
    Bfr::Surface<float>& surface = w.surface;
    if (!factory->InitVertexSurface<float>(face, &surface)) return;  // no limit surface (hole): counted as 0 at sizing

    Bfr::Tessellation tess(surface.GetParameterization(), rate, tess_options);
    const int num_coords = tess.GetNumCoords();
    w.coords.resize(static_cast<std::size_t>(num_coords) * 2);
    tess.GetCoords(w.coords.data());

    w.patch_points.resize(static_cast<std::size_t>(surface.GetNumPatchPoints()) * kPointSize);
    surface.PreparePatchPoints(mesh_points.data(), kPointSize, w.patch_points.data(), kPointSize);

    const std::size_t first_point = point_offsets[static_cast<std::size_t>(face)];
    float* out = out_positions.data() + first_point * kPointSize;
    const float* uv = w.coords.data();
    for (int i = 0; i < num_coords; ++i, uv += 2, out += kPointSize)
      surface.Evaluate(uv, w.patch_points.data(), kPointSize, out);

    int* facets = out_triangles.data() + triangle_offsets[static_cast<std::size_t>(face)] * kFacetSize;
    tess.GetFacets(facets);
    tess.TransformFacetCoordIndices(facets, static_cast<int>(first_point));
  }
};

BfrTessellator::BfrTessellator(const Input& mesh, FactoryCache cache) : impl_(std::make_unique<Impl>()) {
  impl_->refiner.reset(make_refiner(mesh));

  impl_->mesh_points.reserve(mesh.positions->size() * kPointSize);
  for (const auto& p : *mesh.positions)
    for (double c : p) impl_->mesh_points.push_back(static_cast<float>(c));

  if (cache == FactoryCache::ThreadSafe) {
    impl_->factory = std::make_unique<ThreadSafeFactory>(*impl_->refiner, ThreadSafeFactory::Options());
  } else {
    UncachedFactory::Options options;
    options.EnableCaching(false);
    impl_->factory = std::make_unique<UncachedFactory>(*impl_->refiner, options);
  }

  impl_->tess_options.SetFacetSize(kFacetSize);
}

BfrTessellator::~BfrTessellator() = default;

Result BfrTessellator::run(const std::vector<int>& face_rates, int threads) {
  Impl& m = *impl_;
  const int nf = m.face_count();
  if (face_rates.size() != static_cast<std::size_t>(nf))
    throw std::invalid_argument("osd_bench: face_rates has " + std::to_string(face_rates.size()) + " entries for " +
                                std::to_string(nf) + " faces");
  if (threads < 1) throw std::invalid_argument("osd_bench: threads must be at least 1");

  // Sizing (not timed): the counts a consumer knows before it allocates.
  m.point_offsets.assign(static_cast<std::size_t>(nf) + 1, 0);
  m.triangle_offsets.assign(static_cast<std::size_t>(nf) + 1, 0);
  std::size_t max_coords = 0;
  for (int f = 0; f < nf; ++f) {
    const int rate = face_rates[static_cast<std::size_t>(f)];
    if (rate < 1) throw std::invalid_argument("osd_bench: tessellation rates must be at least 1");
    std::size_t coords = 0, facets = 0;
    if (m.factory->FaceHasLimitSurface(f)) {
      Bfr::Tessellation tess(m.factory->GetFaceParameterization(f), rate, m.tess_options);
      if (!tess.IsValid()) throw std::runtime_error("osd_bench: invalid Bfr::Tessellation for face " + std::to_string(f));
      coords = static_cast<std::size_t>(tess.GetNumCoords());
      facets = static_cast<std::size_t>(tess.GetNumFacets());
    }
    if (coords > max_coords) max_coords = coords;
    m.point_offsets[static_cast<std::size_t>(f) + 1] = m.point_offsets[static_cast<std::size_t>(f)] + coords;
    m.triangle_offsets[static_cast<std::size_t>(f) + 1] = m.triangle_offsets[static_cast<std::size_t>(f)] + facets;
  }
  const std::size_t num_points = m.point_offsets.back();
  const std::size_t num_triangles = m.triangle_offsets.back();
  if (num_points > static_cast<std::size_t>(INT_MAX))
    throw std::invalid_argument("osd_bench: more points than int triangle indices can address");
  m.out_positions.assign(num_points * kPointSize, 0.0f);  // touched now, so no page faults are timed
  m.out_triangles.assign(num_triangles * kFacetSize, 0);

  if (m.workers.size() < static_cast<std::size_t>(threads)) m.workers.resize(static_cast<std::size_t>(threads));
  for (Worker& w : m.workers) {
    w.coords.reserve(max_coords * 2);
    w.patch_points.reserve(1024 * kPointSize);  // ample for Catmull-Clark patches; grows once if not
  }

  using Clock = std::chrono::steady_clock;
  Clock::time_point start, stop;
  if (threads == 1) {
    Worker& w = m.workers[0];
    start = Clock::now();
    for (int f = 0; f < nf; ++f) m.tessellate_face(f, face_rates[static_cast<std::size_t>(f)], w);
    stop = Clock::now();
  } else {
    tbb::task_arena arena(threads);
    arena.initialize();
    start = Clock::now();
    arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range<int>(0, nf, 64), [&](const tbb::blocked_range<int>& r) {
        Worker& w = m.workers[static_cast<std::size_t>(tbb::this_task_arena::current_thread_index())];
        for (int f = r.begin(); f != r.end(); ++f) m.tessellate_face(f, face_rates[static_cast<std::size_t>(f)], w);
      });
    });
    stop = Clock::now();
  }

  Result result;
  result.triangles = num_triangles;
  result.points = num_points;
  result.seconds = std::chrono::duration<double>(stop - start).count();
  return result;
}

const std::vector<float>& BfrTessellator::positions() const { return impl_->out_positions; }
const std::vector<int>& BfrTessellator::triangles() const { return impl_->out_triangles; }
const std::vector<std::size_t>& BfrTessellator::point_offsets() const { return impl_->point_offsets; }
const std::vector<std::size_t>& BfrTessellator::triangle_offsets() const { return impl_->triangle_offsets; }
std::size_t BfrTessellator::face_count() const { return static_cast<std::size_t>(impl_->face_count()); }

}  // namespace osd_bench
