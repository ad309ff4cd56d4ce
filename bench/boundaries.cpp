// Benchmark: the cost of boundaries (issue 17's target: tessellation
// throughput on a mesh with boundaries within 1.25x of a closed mesh of the
// same size). Two pairs of meshes: an open tube
// against the closed torus of the same grid (256 x 224 quads, all regular,
// equal face counts),
// the cube refined to 49,152 faces against the cube without its top face
// refined alike (40,960 faces, a boundary loop with extraordinary vertices
// next to it; throughput, not time, is compared), and the cube without two
// adjacent faces (boundary vertices in one and in three faces: boundary
// sectors) against the cube. Uniform rates 8
// and 16 and a random mix 1..24, 1 and 2 threads: a whole static
// tessellation (plan and points, as bench_tessellation) in triangles per
// second, and the per-frame update of the prepared points (set_positions).
// OpenSubdiv 3.5's Bfr tessellates the same meshes in the same run.
// With Loop tables (second argument; - skips the Catmull-Clark pairs): a
// triangulated torus against the tube of the same grid (every rim vertex in
// three faces: regular boundary patches with phantom points), and against the
// same torus with every 8th ring of edges infinitely sharp (the patches of the
// mesh cut along them: regular boundary patches on both sides of each ring),
// against a flat sheet of the same grid open on all four sides (its
// corners in one and two faces: boundary sectors, .sgt version 7), and
// against the same torus with 448 dashes of two sharp edges (896 darts of
// valence 6: dart sectors).
// Usage: bench_boundaries [CATMULL-CLARK.sgs|-] [LOOP.sgt] [PAIR]  (PAIR: run
// only the pairs whose name contains it)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "bench_timing.hpp"
#include "osd_tessellation.hpp"
#include "stencil_runtime/mesh_io.hpp"
#include "stencil_runtime/subdivide.hpp"
#include "stencil_runtime/tessellation.hpp"

using namespace stencil_runtime;

namespace {

using Clock = std::chrono::steady_clock;

// A grid of around x rows quads on a torus (closed) or a tube (open at both ends).
Mesh ring_grid(int around, int rows, bool closed) {
  Mesh m;
  const int rings = closed ? rows : rows + 1;
  for (int j = 0; j < rings; ++j)
    for (int i = 0; i < around; ++i) {
      const double a = 2 * M_PI * i / around, b = 2 * M_PI * j / rows;
      m.positions.push_back(closed ? Point{(3 + std::cos(b)) * std::cos(a), (3 + std::cos(b)) * std::sin(a), std::sin(b)}
                                   : Point{std::cos(a), std::sin(a), 4.0 * j / rows});
    }
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < around; ++i) {
      auto at = [&](int x, int y) { return (y % rings) * around + (x % around); };
      m.face_sizes.push_back(4);
      m.face_vertices.insert(m.face_vertices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return m;
}

// A flat grid of w x h quads, gently waved, open on all four sides.
Mesh open_sheet(int w, int h) {
  Mesh m;
  for (int j = 0; j <= h; ++j)
    for (int i = 0; i <= w; ++i)
      m.positions.push_back({8.0 * i / w, 8.0 * j / w, 0.2 * std::sin(0.3 * i) * std::cos(0.2 * j)});
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      auto at = [&](int x, int y) { return y * (w + 1) + x; };
      m.face_sizes.push_back(4);
      m.face_vertices.insert(m.face_vertices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return m;
}

// The same grid with each quad split into two triangles along one diagonal.
Mesh triangulated(const Mesh& quads) {
  Mesh m;
  m.positions = quads.positions;
  for (std::size_t f = 0; f < quads.face_count(); ++f) {
    const int* q = &quads.face_vertices[4 * f];
    m.face_sizes.insert(m.face_sizes.end(), {3, 3});
    m.face_vertices.insert(m.face_vertices.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
  }
  return m;
}

struct Row {
  double ours = 0, osd = 0;
};

// On every `rows_apart`-th ring of an around x rows torus grid, a dash of two
// infinitely sharp edges every `apart` vertices: a dart at each end.
MeshFeatures sharp_dashes(int around, int rows, int rows_apart, int apart) {
  MeshFeatures out;
  for (int j = 0; j < rows; j += rows_apart)
    for (int i = 0; i + 2 < around; i += apart)
      for (int e = 0; e < 2; ++e) out.edges.push_back({j * around + i + e, j * around + i + e + 1, 10.0});
  return out;
}

}  // namespace

struct Pair {
  std::string name;
  Mesh closed, open;  // "open": with boundaries, or with the features below
  std::shared_ptr<const Tables> tables;
  MeshFeatures open_features;  // infinitely sharp edges of the second mesh (none: the smooth surface)
};

// Every `every`-th ring of edges (i, j) - (i + 1, j) of an around x rows torus grid, infinitely sharp.
MeshFeatures sharp_rings(int around, int rows, int every) {
  MeshFeatures out;
  for (int j = 0; j < rows; j += every)
    for (int i = 0; i < around; ++i) out.edges.push_back({j * around + i, j * around + (i + 1) % around, 10.0});
  return out;
}

int run(int argc, char** argv) {
  const std::string cc_path = argc > 1 ? argv[1] : "tables/catmull-clark/catmull-clark.sgs";
  std::vector<Pair> pairs;
  if (cc_path != "-") {
    const auto tables = Tables::load(cc_path);
    Mesh cube = read_obj(std::string(STENCIL_SOURCE_DIR) + "/meshes/cube.obj");
    Mesh open_box = cube;
    open_box.face_sizes.erase(open_box.face_sizes.begin());
    open_box.face_vertices.erase(open_box.face_vertices.begin(), open_box.face_vertices.begin() + 4);
    // Without two adjacent faces: the two vertices of their common edge are in one face each, and four more
    // rim vertices in three (boundary sectors: patches of their own, not regular ones with phantom points).
    Mesh notched = open_box;
    notched.face_sizes.erase(notched.face_sizes.begin());
    notched.face_vertices.erase(notched.face_vertices.begin(), notched.face_vertices.begin() + 4);
    while (cube.face_count() < 40000) cube = subdivide(*tables, cube);
    while (open_box.face_count() < 40000) open_box = subdivide(*tables, open_box);
    Mesh notched_closed = read_obj(std::string(STENCIL_SOURCE_DIR) + "/meshes/cube.obj");
    // The notched box refined by one step first, so that its sector vertices are not all that is there: then alike.
    notched = subdivide(*tables, notched);
    while (notched.face_count() < 30000) notched = subdivide(*tables, notched);
    while (notched_closed.face_count() < 30000) notched_closed = subdivide(*tables, notched_closed);
    pairs.push_back({"torus / tube 256x224", ring_grid(256, 224, true), ring_grid(256, 224, false), tables, {}});
    pairs.push_back({"cube / open box", cube, open_box, tables, {}});
    pairs.push_back({"cube / box without two faces", notched_closed, notched, tables, {}});
  }
  if (argc > 2) {
    const auto loop = Tables::load(argv[2]);
    pairs.push_back({"Loop: torus / tube 256x112, triangulated", triangulated(ring_grid(256, 112, true)),
                     triangulated(ring_grid(256, 112, false)), loop, {}});
    pairs.push_back({"Loop: torus / torus with 14 sharp rings, 256x112", triangulated(ring_grid(256, 112, true)),
                     triangulated(ring_grid(256, 112, true)), loop, sharp_rings(256, 112, 8)});
    pairs.push_back({"Loop: torus / open sheet 256x112, triangulated", triangulated(ring_grid(256, 112, true)),
                     triangulated(open_sheet(256, 112)), loop, {}});
    pairs.push_back({"Loop: torus / torus with 448 sharp dashes (896 darts), 256x112", triangulated(ring_grid(256, 112, true)),
                     triangulated(ring_grid(256, 112, true)), loop, sharp_dashes(256, 112, 8, 8)});
  }
  std::printf("| meshes | mesh | faces | rate | threads | triangles | ours (M tri/s) | ours / closed | Bfr (M tri/s) | Bfr / closed | positions update (ms) |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
  const std::string only = argc > 3 ? argv[3] : "";
  for (const Pair& pair : pairs) {
    if (pair.name.find(only) == std::string::npos) continue;
    std::vector<Row> closed_rows;
    for (int open = 0; open < 2; ++open) {
      const Mesh& mesh = open ? pair.open : pair.closed;
      const MeshFeatures features = open ? pair.open_features : MeshFeatures{};
      const auto topology = SurfaceTopology::create(pair.tables, mesh.vertex_count(), mesh.face_sizes, mesh.face_vertices, {}, features);
      Surface surface(topology, mesh.positions);
      const double update_ms = 1e3 * bench_timing::median3([&] {
        const auto s = Clock::now();
        surface.set_positions(mesh.positions);
        return std::chrono::duration<double>(Clock::now() - s).count();
      });
      std::vector<int> crease_pairs;
      std::vector<float> crease_sharpness;
      for (const auto& e : features.edges) {
        crease_pairs.insert(crease_pairs.end(), {e.a, e.b});
        crease_sharpness.push_back(static_cast<float>(e.sharpness));
      }
      osd_bench::Input input{&mesh.positions, &mesh.face_sizes, &mesh.face_vertices, pair.tables->family() == SchemeFamily::Triangle,
                             &crease_pairs, &crease_sharpness};
      osd_bench::BfrTessellator osd(input);
      std::size_t row = 0;
      for (int rate : {8, 16, 0}) {
        std::mt19937 rng(7);
        std::vector<int> rates(mesh.face_count(), rate);
        if (rate == 0)
          for (int& r : rates) r = std::uniform_int_distribution<int>(1, 24)(rng);
        for (int threads : {1, 2}) {
          std::size_t triangles = 0, osd_triangles = 0;
          const double ours =
              bench_timing::median3([&] { return bench_timing::tessellation_seconds(surface, rates, threads, triangles); });
          const double theirs = bench_timing::median3([&] {
            const osd_bench::Result r = osd.run(rates, threads);
            osd_triangles = r.triangles;
            return r.seconds;
          });
          const Row now{triangles / ours / 1e6, osd_triangles / theirs / 1e6};
          if (!open) closed_rows.push_back(now);
          const Row& base = closed_rows[row++];
          std::printf("| %s | %s | %zu | %s | %d | %zu | %.1f | %.2f | %.1f | %.2f | %.2f |\n", pair.name.c_str(),
                      pair.open_features.edges.empty() ? (open ? "open" : "closed") : (open ? "creased" : "smooth"), mesh.face_count(), rate ? std::to_string(rate).c_str() : "mix 1..24",
                      threads, triangles, now.ours, now.ours / base.ours, now.osd, now.osd / base.osd, update_ms);
          std::fflush(stdout);
        }
      }
    }
  }
  return 0;
}

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_boundaries: error: %s\n", e.what());
    return 1;
  }
}
