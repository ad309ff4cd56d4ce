// Benchmark: watertight tessellation throughput (triangles per second; a quad
// counts as two) on the bundled meshes and on a large one (the chess piece
// refined by the scheme's own rules to >= 100k control faces), uniform rates
// 4, 8, 16, 24 and a random adaptive mix 1..24, with 1 and 2 threads. For
// Catmull-Clark, OpenSubdiv 3.5's Bfr tessellates the same meshes at the same
// rates in the same run (positions only, float, preallocated arrays), and the
// ratio is printed; every row also with unit normals on (positions and
// normals, the time ratio to positions alone, of the whole tessellation and of
// the evaluation alone on a plan and soup made beforehand). Also: table load time and memory. Triangle meshes: Loop
// from its .sgt tables on the bundled triangle meshes and the triangulated torus
// refined by Loop steps to >= 100k faces, against Bfr's Loop tessellation
// likewise; sqrt(3) on the same meshes (the torus refined by double sqrt(3)
// steps), alone: OpenSubdiv has no sqrt(3).
// Usage: bench_tessellation [NONPOLY.sgs] [CATMULL-CLARK.sgs] [MESH-NAME-FILTER] [LOOP.sgt] [SQRT3.sgt]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>
#include <unistd.h>
#include <vector>

#include "bench_timing.hpp"
#include "osd_tessellation.hpp"
#include "stencil_runtime/mesh_io.hpp"
#include "stencil_runtime/subdivide.hpp"
#include "stencil_runtime/tessellation.hpp"

using namespace stencil_runtime;

namespace {

using Clock = std::chrono::steady_clock;

double resident_mb() {
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return resident * static_cast<double>(sysconf(_SC_PAGESIZE)) / 1e6;
}

struct NamedMesh {
  std::string name;
  Mesh mesh;
};

// The scheme's own refinement (quad steps; Loop steps, or double sqrt(3) steps, 1-to-9).
Mesh refined(Mesh mesh, const Tables& rules, std::size_t min_faces) {
  while (mesh.face_count() < min_faces) mesh = subdivide(rules, mesh);
  return mesh;
}

std::vector<int> rate_set(std::size_t faces, int rate, std::mt19937& rng) {
  std::vector<int> r(faces, rate);
  if (rate == 0)
    for (int& x : r) x = std::uniform_int_distribution<int>(1, 24)(rng);
  return r;
}

// Median of three runs of `f`, which returns seconds.
void run_rows(const char* scheme, const NamedMesh& m, const std::shared_ptr<const Tables>& tables, bool with_osd) {
  const Surface surface(SurfaceTopology::create(tables, m.mesh.vertex_count(), m.mesh.face_sizes, m.mesh.face_vertices),
                        m.mesh.positions);
  const bool loop = std::string(scheme) == "loop";
  std::unique_ptr<osd_bench::BfrTessellator> osd;
  if (with_osd) osd = std::make_unique<osd_bench::BfrTessellator>(
      osd_bench::Input{&m.mesh.positions, &m.mesh.face_sizes, &m.mesh.face_vertices, loop});
  for (int rate : {4, 8, 16, 24, 0}) {
    std::mt19937 rng(7);
    const std::vector<int> rates = rate_set(m.mesh.face_count(), rate, rng);
    for (int threads : {1, 2}) {
      std::size_t triangles = 0;
      // A whole static tessellation: the plan (rates, connectivity) and the points.
      const double ours = bench_timing::median3([&] {
        const auto s = Clock::now();
        const TessellationPlan plan(surface.shared_topology(), rates, {threads});
        PolygonSoup soup = plan.make_soup();
        plan.evaluate(surface, soup.positions.data());
        const double secs = std::chrono::duration<double>(Clock::now() - s).count();
        triangles = soup.triangle_count();
        return secs;
      });
      // The same with unit normals on (issue 14's "position + derivatives at most 2x position alone").
      const double with_normals = bench_timing::median3([&] {
        const auto s = Clock::now();
        const TessellationPlan plan(surface.shared_topology(), rates, {threads});
        PolygonSoup soup = plan.make_soup();
        soup.normals.resize(soup.positions.size());
        plan.evaluate(surface, soup.positions.data(), soup.normals.data());
        return std::chrono::duration<double>(Clock::now() - s).count();
      });
      // The evaluation alone, with and without normals, on one plan and one
      // soup made beforehand: what the whole tessellation's ratio holds without
      // the first touch of hundreds of MB of fresh pages, whose cost on this
      // virtual machine varies by a factor of up to 8 from run to run.
      double evaluation_ratio = 0;
      {
        const TessellationPlan plan(surface.shared_topology(), rates, {threads});
        PolygonSoup soup = plan.make_soup();
        soup.normals.resize(soup.positions.size());
        auto seconds_of = [](auto&& f) {
          const auto s = Clock::now();
          f();
          return std::chrono::duration<double>(Clock::now() - s).count();
        };
        const double alone = bench_timing::median3([&] { return seconds_of([&] { plan.evaluate(surface, soup.positions.data()); }); });
        const double both = bench_timing::median3(
            [&] { return seconds_of([&] { plan.evaluate(surface, soup.positions.data(), soup.normals.data()); }); });
        evaluation_ratio = both / alone;
      }
      char normals_columns[96];
      std::snprintf(normals_columns, sizeof normals_columns, " %.1f | %.2f | %.2f |", triangles / with_normals / 1e6,
                    with_normals / ours, evaluation_ratio);
      const double ours_rate = triangles / ours / 1e6;
      if (with_osd) {
        std::size_t osd_triangles = 0;
        const double theirs = bench_timing::median3([&] {
          const osd_bench::Result r = osd->run(rates, threads);
          osd_triangles = r.triangles;
          return r.seconds;
        });
        const double osd_rate = osd_triangles / theirs / 1e6;
        std::printf("| %s | %s | %zu | %s | %d | %zu | %.1f | %.1f | %.2f |%s\n", scheme, m.name.c_str(),
                    m.mesh.face_count(), rate ? std::to_string(rate).c_str() : "mix 1..24", threads, triangles,
                    ours_rate, osd_rate, ours_rate / osd_rate, normals_columns);
      } else {
        std::printf("| %s | %s | %zu | %s | %d | %zu | %.1f | | |%s\n", scheme, m.name.c_str(), m.mesh.face_count(),
                    rate ? std::to_string(rate).c_str() : "mix 1..24", threads, triangles, ours_rate, normals_columns);
      }
      std::fflush(stdout);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  const std::string nonpoly_path = argc > 1 ? argv[1] : "tables/nonpoly/nonpoly.sgs";
  const std::string cc_path = argc > 2 ? argv[2] : "tables/catmull-clark/catmull-clark.sgs";
  const std::string mesh_dir = std::string(STENCIL_SOURCE_DIR) + "/meshes/";
  const std::string only = argc > 3 ? argv[3] : "";  // optional: only meshes whose name contains this

  const double before = resident_mb();
  const auto t0 = Clock::now();
  const auto nonpoly = Tables::load(nonpoly_path);
  const double load_s = std::chrono::duration<double>(Clock::now() - t0).count();
  std::printf("# table load: %s, %.1f ms, resident memory +%.1f MB\n", nonpoly_path.c_str(), load_s * 1e3,
              resident_mb() - before);
  const auto cc = Tables::load(cc_path);

  std::printf("\n| scheme | mesh | control faces | rate | threads | triangles | ours (M tri/s) | OpenSubdiv Bfr (M tri/s) | ratio | "
              "ours with normals (M tri/s) | time with normals / without | evaluation with normals / without |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const auto* scheme : {"nonpoly", "catmull-clark"}) {
    const auto& tables = std::string(scheme) == "nonpoly" ? nonpoly : cc;
    std::vector<NamedMesh> meshes;
    for (const char* name : {"cube", "torus-3-5", "chess-piece", "bumpy-sphere"})
      meshes.push_back({name, read_obj(mesh_dir + name + ".obj")});
    meshes.push_back({"chess-piece, refined", refined(read_obj(mesh_dir + "chess-piece.obj"), *tables, 100000)});
    for (const NamedMesh& m : meshes) {
      if (m.name.find(only) == std::string::npos) continue;
      run_rows(scheme, m, tables, std::string(scheme) == "catmull-clark");
    }
  }
  // Triangle schemes: Loop against Bfr's Loop; sqrt(3), which OpenSubdiv lacks, alone.
  const std::string triangle_paths[2] = {argc > 4 ? argv[4] : "tables/loop/loop.sgt",
                                         argc > 5 ? argv[5] : "tables/sqrt3/sqrt3.sgt"};
  for (const char* scheme : {"loop", "sqrt3"}) {
    const bool loop = std::string(scheme) == "loop";
    const std::string& path = triangle_paths[loop ? 0 : 1];
    if (!std::ifstream(path)) {
      std::printf("\n# %s not found: no %s rows (stencilgen --scheme %s --valence 3-8 --n 24 --out tables)\n", path.c_str(),
                  scheme, scheme);
      continue;
    }
    const auto tables = Tables::load(path);
    std::vector<NamedMesh> meshes;
    for (const char* name : {"icosahedron", "tri-torus", "tri-mix"}) meshes.push_back({name, read_obj(mesh_dir + name + ".obj")});
    meshes.push_back({"tri-torus, refined", refined(read_obj(mesh_dir + "tri-torus.obj"), *tables, 100000)});
    for (const NamedMesh& m : meshes) {
      if (m.name.find(only) == std::string::npos) continue;
      run_rows(scheme, m, tables, loop);
    }
  }
  return 0;
}
