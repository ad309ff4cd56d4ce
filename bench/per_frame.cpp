// Benchmark: a deforming mesh, per frame. New control positions in,
// tessellated positions out, with the topology and the tessellation plan made
// once (runtime v2), against OpenSubdiv 3.5's fastest CPU paths for the same
// samples (osd_per_frame.hpp: Far/Osd EvalStencils + EvalPatches, and cached
// Bfr surfaces), thread for thread; and against our own static tessellation
// (plan and points made anew, as tessellate() does). Mesh: the chess piece
// refined by the scheme's own rules to >= 100k control faces. Rates 4, 8, 16,
// 24; 1 and 2 threads; the median of 5 frames.
// Usage: bench_per_frame [NONPOLY.sgs] [CATMULL-CLARK.sgs] [RATES e.g. 4,8]
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "osd_per_frame.hpp"
#include "stencil_runtime/mesh_io.hpp"
#include "stencil_runtime/subdivide.hpp"
#include "stencil_runtime/tessellation.hpp"

using namespace stencil_runtime;
using Clock = std::chrono::steady_clock;

namespace {

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

double median(std::vector<double> t) {
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

// Frame k: every vertex pushed along a travelling wave.
std::vector<Point> pose(const Mesh& rest, int k) {
  std::vector<Point> p = rest.positions;
  for (auto& x : p) {
    const double phase = 0.7 * k + 3 * x[2];
    x[0] *= 1 + 0.05 * std::sin(phase);
    x[1] *= 1 + 0.05 * std::cos(phase);
  }
  return p;
}

// The plan's sample parameters per face: cell centres ((2i+1)/(2n), (2j+1)/(2n)), row by row.
osd_bench::FaceSamples samples_of(const std::vector<int>& rates) {
  osd_bench::FaceSamples s;
  s.uv.resize(rates.size());
  for (std::size_t f = 0; f < rates.size(); ++f) {
    const int n = rates[f];
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        s.uv[f].push_back(static_cast<float>((2 * i + 1) / (2.0 * n)));
        s.uv[f].push_back(static_cast<float>((2 * j + 1) / (2.0 * n)));
      }
  }
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string paths[2] = {argc > 1 ? argv[1] : "tables/nonpoly/nonpoly.sgs",
                                argc > 2 ? argv[2] : "tables/catmull-clark/catmull-clark.sgs"};
  std::vector<int> rate_list{4, 8, 16, 24};
  if (argc > 3) {
    rate_list.clear();
    std::stringstream in(argv[3]);
    for (std::string item; std::getline(in, item, ',');) rate_list.push_back(std::stoi(item));
  }
  const std::string mesh_path = std::string(STENCIL_SOURCE_DIR) + "/meshes/chess-piece.obj";
  std::printf("| scheme | control faces | rate | threads | points | ours per frame (ms) | ours static (ms) | "
              "OSD EvalPatches (ms) | OSD Bfr (ms) | ratio to best OSD | per frame / static | max diff / size |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (int s = 0; s < 2; ++s) {
    if (paths[s] == "-") continue;  // "-" skips that scheme (e.g. to re-measure Catmull-Clark alone)
    const auto tables = Tables::load(paths[s]);
    Mesh mesh = read_obj(mesh_path);
    while (mesh.face_count() < 100000) mesh = subdivide(*tables, mesh);
    const auto topology = SurfaceTopology::create(tables, mesh.vertex_count(), mesh.face_sizes, mesh.face_vertices);
    if (topology->refinement_steps() != 0) throw std::runtime_error("expected an isolated mesh");
    std::vector<std::vector<Point>> frames;
    for (int k = 0; k < 5; ++k) frames.push_back(pose(mesh, k));
    double size = 0;
    {
      Point lo = mesh.positions[0], hi = lo;
      for (const auto& p : mesh.positions)
        for (int c = 0; c < 3; ++c) lo[c] = std::min(lo[c], p[c]), hi[c] = std::max(hi[c], p[c]);
      size = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) + (hi[2] - lo[2]) * (hi[2] - lo[2]));
    }
    for (int rate : rate_list) {
      const std::vector<int> rates(mesh.face_count(), rate);
      const bool cc = tables->scheme() == "catmull-clark";
      std::unique_ptr<osd_bench::PerFrame> osd;
      if (cc) osd = std::make_unique<osd_bench::PerFrame>(mesh.positions, mesh.face_sizes, mesh.face_vertices, samples_of(rates));
      for (int threads : {1, 2}) {
        tbb::task_arena arena(threads);
        double per_frame = 0, statics = 0, patches = 0, bfr = 0, diff = 0;
        std::size_t points = 0;
        arena.execute([&] {
          const TessellationPlan plan(topology, rates, {threads});
          Surface surface(topology);
          std::vector<std::array<float, 3>> out(plan.point_count());
          points = out.size();
          std::vector<double> t;
          for (std::size_t k = 0; k < frames.size(); ++k) {
            const auto start = Clock::now();
            surface.set_positions(frames[k]);
            plan.evaluate(surface, out.data());
            if (k > 0) t.push_back(since(start));  // the first frame warms the caches
          }
          per_frame = median(t);
          t.clear();
          for (int k = 0; k < 3; ++k) {
            const auto start = Clock::now();
            const TessellationPlan fresh(topology, rates, {threads});
            PolygonSoup soup = fresh.make_soup();
            fresh.evaluate(surface, soup.positions.data());
            t.push_back(since(start));
          }
          statics = median(t);
          if (osd) {
            std::vector<double> tp, tb;
            for (std::size_t k = 0; k < frames.size(); ++k) {
              const double a = osd->eval_patches(frames[k], threads);
              const double b = osd->bfr(frames[k], threads);
              if (k > 0) tp.push_back(a), tb.push_back(b);
            }
            patches = median(tp);
            bfr = median(tb);
            // Same samples, same surface: the last frame's points agree.
            const auto& theirs = osd->output();
            for (std::size_t p = 0; p < out.size(); ++p)
              for (int c = 0; c < 3; ++c) diff = std::max(diff, std::fabs(static_cast<double>(out[p][c]) - theirs[3 * p + c]));
          }
        });
        const double best = osd ? std::min(patches, bfr) : 0;
        std::printf("| %s | %zu | %d | %d | %zu | %.2f | %.2f | %s | %s | %s | %.2f | %s |\n", tables->scheme().c_str(),
                    mesh.face_count(), rate, threads, points, per_frame * 1e3, statics * 1e3,
                    osd ? std::to_string(patches * 1e3).substr(0, 7).c_str() : "", osd ? std::to_string(bfr * 1e3).substr(0, 7).c_str() : "",
                    osd ? std::to_string(best / per_frame).substr(0, 5).c_str() : "", per_frame / statics,
                    osd ? std::to_string(diff / size).substr(0, 9).c_str() : "");
        std::fflush(stdout);
      }
    }
  }
  return 0;
}
