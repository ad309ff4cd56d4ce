// Benchmark: the cost of semi-sharp creases (issue 17's target: tessellation
// throughput on a mesh with creases within 1.25x of a closed smooth mesh of
// the same size). The chess piece refined by Catmull-Clark steps to >= 40k
// faces, smooth and with every 10th edge creased (sharpness 1, then 2:
// one and two whole-mesh steps with the sharp rules in the preparation; then
// 10, infinitely sharp: darts, creases and corners, the patches of the mesh
// cut along them);
// uniform rates 8 and 16 and a random mix 1..24, 1 and 2 threads: the
// preparation time, then a whole static tessellation (plan and points, as
// bench_tessellation), in triangles per second. OpenSubdiv 3.5's Bfr
// tessellates the same meshes with the same creases in the same run.
// Then the refinement round the features (quad/semi_sharp_levels.hpp, which
// the runtime takes where whole-mesh steps would pass 2^21 faces), forced:
// every 10th edge at sharpness 2 again, and every 100th at sharpness 2 (after
// the same by whole-mesh steps) and 4
// (a few creases, the usual case; sharpness 4 is beyond whole-mesh steps here).
// With Loop tables too, the same for the triangle torus refined by Loop steps
// to 49k faces (TriangleFamily's tree, the same levels).
// Usage: bench_creases [CATMULL-CLARK.sgs|- [LOOP.sgt]] ("-": Loop alone)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <random>
#include <string>
#include <vector>

#include "bench_timing.hpp"
#include "osd_tessellation.hpp"
#include "family/semi_sharp_levels.hpp"
#include "stencil_runtime/mesh_io.hpp"
#include "stencil_runtime/subdivide.hpp"
#include "stencil_runtime/tessellation.hpp"

using namespace stencil_runtime;

namespace {

using Clock = std::chrono::steady_clock;

// Every `every`-th edge (in the order the faces first name them), with sharpness s.
MeshFeatures creases(const Mesh& mesh, double s, std::size_t every = 10) {
  MeshFeatures out;
  std::size_t corner = 0, count = 0;
  for (int k : mesh.face_sizes) {
    for (int c = 0; c < k; ++c) {
      const int a = mesh.face_vertices[corner + static_cast<std::size_t>(c)];
      const int b = mesh.face_vertices[corner + static_cast<std::size_t>((c + 1) % k)];
      if (a < b && count++ % every == 0) out.edges.push_back({a, b, s});
    }
    corner += static_cast<std::size_t>(k);
  }
  return out;
}

}  // namespace

namespace {

void bench(const std::shared_ptr<const Tables>& tables, const std::string& name, bool loop) {
  Mesh mesh = read_obj(std::string(STENCIL_SOURCE_DIR) + "/meshes/" + name + ".obj");
  while (mesh.face_count() < 40000) mesh = subdivide(*tables, mesh);
  std::printf("# %s: %s refined to %zu faces; creases on every 10th or 100th edge\n\n", tables->scheme().c_str(),
              name.c_str(), mesh.face_count());
  // What the runtime picks by itself (quad/semi_sharp_levels.hpp's automatic choice) for the creased meshes below.
  for (std::size_t every : {std::size_t{10}, std::size_t{100}}) {
    set_crease_refinement_choice(CreaseRefinementChoice::Automatic);
    const auto t = SurfaceTopology::create(tables, mesh.vertex_count(), mesh.face_sizes, mesh.face_vertices, {}, creases(mesh, 2, every));
    std::printf("# automatic choice, every %zuth edge at sharpness 2: %s\n", every, t->preparation().c_str());
  }
  std::printf("\n");
  std::printf("| sharpness | creased edges | refinement | prepared faces | preparation (s) | rate | threads | triangles | ours (M tri/s) | ours / smooth | Bfr (M tri/s) | Bfr / smooth |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::vector<std::vector<double>> smooth_rates;  // [rate][threads] of the smooth mesh: ours, Bfr
  struct Case {
    double sharpness;
    std::size_t every;
    bool round_features;
  };
  for (const Case& c : {Case{0, 10, false}, Case{1, 10, false}, Case{2, 10, false}, Case{10, 10, false}, Case{2, 10, true},
                        Case{2, 100, false}, Case{2, 100, true}, Case{4, 100, true}}) {
    const double sharpness = c.sharpness;
    const MeshFeatures features = creases(mesh, sharpness, c.every);
    set_crease_refinement_choice(c.round_features ? CreaseRefinementChoice::RoundFeatures : CreaseRefinementChoice::WholeMesh);
    const auto t0 = Clock::now();
    const auto topology = SurfaceTopology::create(tables, mesh.vertex_count(), mesh.face_sizes, mesh.face_vertices, {},
                                                  sharpness > 0 ? features : MeshFeatures{});
    const double prepare_s = std::chrono::duration<double>(Clock::now() - t0).count();
    const Surface surface(topology, mesh.positions);
    std::vector<int> pairs;
    std::vector<float> weights;
    for (const auto& e : features.edges) {
      pairs.insert(pairs.end(), {e.a, e.b});
      weights.push_back(static_cast<float>(e.sharpness));
    }
    osd_bench::Input input{&mesh.positions, &mesh.face_sizes, &mesh.face_vertices, loop};
    if (sharpness > 0) input.crease_pairs = &pairs, input.crease_sharpness = &weights;
    osd_bench::BfrTessellator osd(input);
    std::size_t row = 0;
    for (int rate : {8, 16, 0}) {
      std::mt19937 rng(7);
      std::vector<int> rates(mesh.face_count(), rate);
      if (rate == 0)
        for (int& r : rates) r = std::uniform_int_distribution<int>(1, 24)(rng);
      for (int threads : {1, 2}) {
        std::size_t triangles = 0, osd_triangles = 0;
        const double ours = bench_timing::median3([&] { return bench_timing::tessellation_seconds(surface, rates, threads, triangles); });
        const double theirs = bench_timing::median3([&] {
          const osd_bench::Result r = osd.run(rates, threads);
          osd_triangles = r.triangles;
          return r.seconds;
        });
        const double ours_rate = triangles / ours / 1e6, osd_rate = osd_triangles / theirs / 1e6;
        if (sharpness == 0) smooth_rates.push_back({ours_rate, osd_rate});
        const auto& base = smooth_rates[row++ % smooth_rates.size()];
        std::printf("| %g | 1 in %zu | %s | %zu | %.2f | %s | %d | %zu | %.1f | %.2f | %.1f | %.2f |\n", sharpness, c.every,
                    c.round_features ? "round the features" : "whole mesh", topology->prepared_face_count(), prepare_s, rate ? std::to_string(rate).c_str() : "mix 1..24", threads,
                    triangles, ours_rate, ours_rate / base[0], osd_rate, osd_rate / base[1]);
        std::fflush(stdout);
      }
    }
  }
  std::printf("\n");
}

}  // namespace

int run(int argc, char** argv) {
  const std::string cc_path = argc > 1 ? argv[1] : "tables/catmull-clark/catmull-clark.sgs";
  if (cc_path != "-") bench(Tables::load(cc_path), "chess-piece", false);
  if (argc > 2) bench(Tables::load(argv[2]), "tri-torus", true);
  return 0;
}

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_creases: error: %s\n", e.what());
    return 1;
  }
}
