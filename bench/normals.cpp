// Benchmark: the cost of tessellation normals (issue 14's "position +
// derivatives costs at most 2x position alone"). The chess piece refined by
// the scheme's own rules to >= 100k control faces, uniform rates 4, 8, 16, 24,
// 1 and 2 threads: a plan made once, then the median of three evaluations of
// positions alone (TessellationPlan::evaluate) and of positions plus unit
// normals (evaluate with both outputs, one pass), for nonpoly and Catmull-Clark. For
// Catmull-Clark, OpenSubdiv's Bfr evaluates the same points with and without
// first derivatives in the same run (cached surfaces, per face
// PreparePatchPoints, then Evaluate at every point), as the reference ratio.
// Triangle tables given after them (Loop, sqrt(3)) run on the tri-mix mesh,
// refined the same way: Loop differentiates its quartic, sqrt(3) takes its
// regular faces' stored derivative stencils and descends on the others.
// Usage: bench_normals [NONPOLY.sgs] [CATMULL-CLARK.sgs] [TRIANGLE.sgt ...] (- skips a quad set)
#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "stencil_runtime/mesh_io.hpp"
#include "stencil_runtime/subdivide.hpp"
#include "stencil_runtime/tessellation.hpp"

using namespace stencil_runtime;
namespace osd = OpenSubdiv;

namespace {

using Clock = std::chrono::steady_clock;

template <class F>
double median3(F f) {
  double t[3];
  for (double& x : t) {
    const auto t0 = Clock::now();
    f();
    x = std::chrono::duration<double>(Clock::now() - t0).count();
  }
  std::sort(t, t + 3);
  return t[1];
}

// Bfr at the same n x n cell centres of every face, with or without du, dv.
struct BfrMesh {
  std::unique_ptr<osd::Far::TopologyRefiner> refiner;
  std::vector<osd::Bfr::Surface<float>> surfaces;
  std::vector<float> flat;

  explicit BfrMesh(const Mesh& m) {
    osd::Far::TopologyDescriptor desc;
    desc.numVertices = static_cast<int>(m.vertex_count());
    desc.numFaces = static_cast<int>(m.face_count());
    desc.numVertsPerFace = m.face_sizes.data();
    desc.vertIndicesPerFace = m.face_vertices.data();
    using Factory = osd::Far::TopologyRefinerFactory<osd::Far::TopologyDescriptor>;
    refiner.reset(Factory::Create(desc, Factory::Options(osd::Sdc::SCHEME_CATMARK, osd::Sdc::Options())));
    const osd::Bfr::RefinerSurfaceFactory<> factory(*refiner);
    surfaces.resize(m.face_count());
    for (std::size_t f = 0; f < m.face_count(); ++f) factory.InitVertexSurface(static_cast<int>(f), &surfaces[f]);
    for (const Point& p : m.positions)
      for (double x : p) flat.push_back(static_cast<float>(x));
  }
  void run(int n, bool derivatives, std::vector<float>& out) const {
    std::vector<float> patch;
    float du[3], dv[3];
    std::size_t k = 0;
    out.resize(surfaces.size() * static_cast<std::size_t>(n * n) * 3);
    for (const auto& s : surfaces) {
      patch.resize(static_cast<std::size_t>(s.GetNumPatchPoints()) * 3);
      s.PreparePatchPoints(flat.data(), 3, patch.data(), 3);
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i, k += 3) {
          const float uv[2] = {(2.0f * i + 1) / (2.0f * n), (2.0f * j + 1) / (2.0f * n)};
          if (derivatives) s.Evaluate(uv, patch.data(), 3, &out[k], du, dv);
          else s.Evaluate(uv, patch.data(), 3, &out[k]);
        }
    }
  }
};

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> paths = {argc > 1 ? argv[1] : "tables/nonpoly/nonpoly.sgs",
                                    argc > 2 ? argv[2] : "tables/catmull-clark/catmull-clark.sgs"};
  for (int k = 3; k < argc; ++k) paths.push_back(argv[k]);
  const std::string meshes = std::string(STENCIL_SOURCE_DIR) + "/meshes/";
  std::printf("| scheme | control faces | rate | threads | points | positions (ms) | positions + normals (ms) | ratio | "
              "Bfr points (ms) | Bfr points + du, dv (ms) | Bfr ratio |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (std::size_t s = 0; s < paths.size(); ++s) {
    if (paths[s] == "-") continue;  // skipped
    const auto tables = Tables::load(paths[s]);
    Mesh mesh = read_obj(meshes + (tables->family() == SchemeFamily::Triangle ? "tri-mix.obj" : "chess-piece.obj"));
    while (mesh.face_count() < 100000) mesh = subdivide(*tables, mesh);
    const auto topology = SurfaceTopology::create(tables, mesh.vertex_count(), mesh.face_sizes, mesh.face_vertices);
    const Surface surface(topology, mesh.positions);
    std::unique_ptr<BfrMesh> bfr;
    if (tables->scheme() == "catmull-clark") bfr = std::make_unique<BfrMesh>(mesh);
    for (int rate : {4, 8, 16, 24})
      for (int threads : {1, 2}) {
        // Rates are per original face; the refined mesh needs no isolation step here.
        const TessellationPlan plan(topology, std::vector<int>(mesh.face_count(), rate), {threads});
        PolygonSoup soup = plan.make_soup();
        soup.normals.resize(soup.positions.size());
        const double alone = median3([&] { plan.evaluate(surface, soup.positions.data()); });
        const double both = median3([&] {
          plan.evaluate(surface, soup.positions.data(), soup.normals.data());
        });
        std::printf("| %s | %zu | %d | %d | %zu | %.2f | %.2f | %.2f |", tables->scheme().c_str(), mesh.face_count(), rate,
                    threads, soup.positions.size(), alone * 1e3, both * 1e3, both / alone);
        if (bfr && threads == 1) {
          const int n = plan.prepared_rates().front();
          std::vector<float> out;
          const double p = median3([&] { bfr->run(n, false, out); });
          const double d = median3([&] { bfr->run(n, true, out); });
          std::printf(" %.2f | %.2f | %.2f |\n", p * 1e3, d * 1e3, d / p);
        } else {
          std::printf("  |  |  |\n");
        }
      }
  }
  return 0;
}
