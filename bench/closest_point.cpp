// Benchmark: seed 000's study of distances to a subdivision surface,
// reproduced with the exact limit surface in it (issue "Closest points...").
// Per mesh, in one process, on the same 10,000 query points (uniform in the
// box of twice the control mesh's bounding-box volume, as in seed 000):
//   (a) ClosestPointQuery on the exact limit surface (tolerance 1e-9 of the
//       diagonal), one thread and two;
//   (b) seed 000's triangle-mesh method: our exact tessellation at uniform
//       rates 2^L (L = 1..5: the limit points of a level-L subdivision) split
//       into triangles, queried through Embree's BVH point query with an exact
//       point-triangle distance, one thread and two.
// Each row: queries per second, the build time and memory of the query
// structure, and the error of the distances against (a)'s, as fractions of
// the diagonal (max and mean). (a)'s error is its own bound (the tolerance).
// Usage: bench_closest_point TABLES.sgs [MESH.obj[@1] ...]
// (TABLES must hold the rates 2, 4, 8, 16 and 32 for the triangle meshes;
// MESH@1: the mesh after one step of the scheme's own subdivision. Default:
// the bundled chess piece (224 faces), rook (368) and rook@1 (1,472), seed
// 000's range of piece sizes.)
#include <embree3/rtcore.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "distance/affine_enclosure.hpp"  // point_triangle_distance
#include "stencil_runtime/closest_point.hpp"
#include "stencil_runtime/mesh_io.hpp"
#include "stencil_runtime/subdivide.hpp"
#include "stencil_runtime/tessellation.hpp"

using namespace stencil_runtime;

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

std::atomic<long long> embree_bytes{0};
bool count_memory(void*, ssize_t bytes, bool) {
  embree_bytes += bytes;
  return true;
}

// A triangle mesh under Embree's BVH, answering the nearest-triangle distance.
class TriangleQuery {
 public:
  TriangleQuery(RTCDevice device, const PolygonSoup& soup) {
    for (const auto& p : soup.positions) points_.push_back({p[0], p[1], p[2]});
    for (const auto& t : soup.triangles) triangles_.push_back({static_cast<unsigned>(t[0]), static_cast<unsigned>(t[1]), static_cast<unsigned>(t[2])});
    for (const auto& q : soup.quads) {
      triangles_.push_back({static_cast<unsigned>(q[0]), static_cast<unsigned>(q[1]), static_cast<unsigned>(q[2])});
      triangles_.push_back({static_cast<unsigned>(q[0]), static_cast<unsigned>(q[2]), static_cast<unsigned>(q[3])});
    }
    const long long before = embree_bytes;
    const auto t0 = Clock::now();
    scene_ = rtcNewScene(device);
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), soup.positions.size()));
    for (std::size_t i = 0; i < soup.positions.size(); ++i)
      for (int k = 0; k < 3; ++k) v[3 * i + k] = soup.positions[i][k];
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), triangles_.size()));
    for (std::size_t i = 0; i < triangles_.size(); ++i)
      for (int k = 0; k < 3; ++k) idx[3 * i + k] = triangles_[i][k];
    rtcCommitGeometry(g);
    rtcAttachGeometry(scene_, g);
    rtcReleaseGeometry(g);
    rtcCommitScene(scene_);
    build_seconds = seconds_since(t0);
    memory_bytes = static_cast<std::size_t>(embree_bytes - before) + points_.size() * sizeof(Point) + triangles_.size() * 12;
  }
  ~TriangleQuery() { rtcReleaseScene(scene_); }
  std::size_t triangle_count() const { return triangles_.size(); }

  double distance(const Point& q) const {
    State s{this, q, INFINITY};
    RTCPointQuery query;
    query.x = static_cast<float>(q[0]), query.y = static_cast<float>(q[1]), query.z = static_cast<float>(q[2]);
    query.time = 0, query.radius = INFINITY;
    RTCPointQueryContext context;
    rtcInitPointQueryContext(&context);
    rtcPointQuery(scene_, &query, &context, visit, &s);
    return s.best;
  }

  double build_seconds = 0;
  std::size_t memory_bytes = 0;

 private:
  struct State {
    const TriangleQuery* mesh;
    Point q;
    double best;
  };
  static bool visit(RTCPointQueryFunctionArguments* args) {
    auto* s = static_cast<State*>(args->userPtr);
    const auto& t = s->mesh->triangles_[args->primID];
    const auto& p = s->mesh->points_;
    const double d = point_triangle_distance(s->q, p[t[0]], p[t[1]], p[t[2]]);
    if (d >= s->best) return false;
    s->best = d;
    args->query->radius = std::nextafter(static_cast<float>(d), INFINITY);
    return true;
  }
  std::vector<Point> points_;
  std::vector<std::array<unsigned, 3>> triangles_;
  RTCScene scene_ = nullptr;
};

template <class F>
double queries_per_second(int threads, std::size_t count, F each) {
  tbb::task_arena arena(threads);
  const auto t0 = Clock::now();
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 16), [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t i = r.begin(); i < r.end(); ++i) each(i);
    });
  });
  return static_cast<double>(count) / seconds_since(t0);
}

}  // namespace

int main(int argc, char** argv) try {
  if (argc < 2) {
    std::fprintf(stderr, "usage: bench_closest_point TABLES.sgs [MESH.obj ...]\n");
    return 1;
  }
  const auto tables = Tables::load(argv[1]);
  std::vector<std::string> meshes;
  for (int i = 2; i < argc; ++i) meshes.push_back(argv[i]);
  if (meshes.empty())
    for (const char* name : {"chess-piece.obj", "rook.obj", "rook.obj@1"}) meshes.push_back(std::string(STENCIL_SOURCE_DIR) + "/meshes/" + name);
  RTCDevice device = rtcNewDevice(nullptr);
  rtcSetDeviceMemoryMonitorFunction(device, count_memory, nullptr);
  constexpr std::size_t kQueries = 10000;

  std::printf("scheme %s; %zu queries uniform in the box of twice the control mesh's bounding-box volume\n\n",
              tables->scheme().c_str(), kQueries);
  std::printf("| mesh | method | triangles | build (s) | memory (MB) | queries/s, 1 thread | 2 threads | max error / diagonal | mean error / diagonal |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  for (const std::string& argument : meshes) {
    const bool refine = argument.size() > 2 && argument.substr(argument.size() - 2) == "@1";
    const std::string path = refine ? argument.substr(0, argument.size() - 2) : argument;
    const Mesh mesh = refine ? subdivide(*tables, read_obj(path)) : read_obj(path);
    const auto topology = SurfaceTopology::create(tables, mesh.vertex_count(), mesh.face_sizes, mesh.face_vertices);
    const Surface surface(topology, mesh.positions);
    Point lo = mesh.positions[0], hi = lo;
    for (const Point& p : mesh.positions)
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
    const double diagonal = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
    std::mt19937_64 rng(2026);
    std::uniform_real_distribution<double> unit(-0.5, 0.5);
    const double widen = std::cbrt(2.0);
    std::vector<Point> queries(kQueries);
    for (Point& q : queries)
      for (int k = 0; k < 3; ++k) q[k] = 0.5 * (lo[k] + hi[k]) + widen * (hi[k] - lo[k]) * unit(rng);
    const std::string name = argument.substr(argument.find_last_of('/') + 1) + " (" + std::to_string(mesh.face_count()) + " faces)";

    // (a) exact.
    const ClosestPointQuery exact(surface);
    std::vector<double> truth(kQueries);
    const double exact1 = queries_per_second(1, kQueries, [&](std::size_t i) { truth[i] = exact.find(queries[i]).distance; });
    const double exact2 = queries_per_second(2, kQueries, [&](std::size_t i) { truth[i] = exact.find(queries[i]).distance; });
    std::printf("| %s | exact limit surface | - | %.4f | %.2f | %.0f | %.0f | <= %.0e (bound) | - |\n", name.c_str(),
                exact.build_seconds(), exact.memory_bytes() / 1e6, exact1, exact2, exact.tolerance() / diagonal);
    std::fflush(stdout);

    // (b) triangle meshes of uniform tessellations.
    for (int level = 1; level <= 5; ++level) {
      const int rate = 1 << level;
      const auto t0 = Clock::now();
      const PolygonSoup soup = tessellate(surface, std::vector<int>(mesh.face_count(), rate));
      const double tessellation_seconds = seconds_since(t0);
      const TriangleQuery triangles(device, soup);
      std::vector<double> d(kQueries);
      const double q1 = queries_per_second(1, kQueries, [&](std::size_t i) { d[i] = triangles.distance(queries[i]); });
      const double q2 = queries_per_second(2, kQueries, [&](std::size_t i) { d[i] = triangles.distance(queries[i]); });
      double worst = 0, sum = 0;
      for (std::size_t i = 0; i < kQueries; ++i) {
        const double e = std::fabs(d[i] - truth[i]);
        worst = std::max(worst, e), sum += e;
      }
      std::printf("| %s | Embree, level %d (rate %d) | %zu | %.4f + %.4f | %.2f | %.0f | %.0f | %.2e | %.2e |\n", name.c_str(), level,
                  rate, triangles.triangle_count(), tessellation_seconds, triangles.build_seconds, triangles.memory_bytes / 1e6, q1,
                  q2, worst / diagonal, sum / kQueries / diagonal);
      std::fflush(stdout);
    }
  }
  rtcReleaseDevice(device);
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "bench_closest_point: %s\n", e.what());
  return 1;
}
