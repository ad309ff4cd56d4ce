#include "runtime_use.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "fuzz_support.hpp"
#include "rate_choice.hpp"
#include "stencil_runtime/limits.hpp"
#include "stencil_runtime/mesh_io.hpp"
#include "stencil_runtime/surface.hpp"
#include "stencil_runtime/surface_topology.hpp"
#include "stencil_runtime/tessellation.hpp"
#include "quad/semi_sharp_levels.hpp"
#include "tables/quad_tables.hpp"
#include "tables/triangle_tables.hpp"

namespace fuzz {

namespace rt = stencil_runtime;

namespace {

// Weights looked up per input at most: keeps one input to milliseconds.
constexpr long kWeightBudget = 4'000'000;

// Counts the weights a lookup sweep will read; false once the budget is spent.
class Budget {
 public:
  bool take(long weights) {
    if (weights > left_) return false;
    left_ -= weights;
    return true;
  }

 private:
  long left_ = kWeightBudget;
};

// Semi-sharp features cost faces: Loop's whole-mesh steps make 4 times the
// faces per unit of sharpness (a few tagged faces with a corner of sharpness 9
// become a million, legal and within the runtime's limit but seconds under the
// sanitizers: a libFuzzer timeout, 2026-12-03); the quad family's refinement
// round the features (quad/semi_sharp_levels.hpp) makes about 32 faces per
// tagged feature, times 2 per unit of sharpness. Inputs beyond the budget are
// left out, as the weight budget leaves out long sweeps.
constexpr double kCreaseStepFaceBudget = 65536;

// Those faces, roughly (an upper estimate; whole-mesh steps' are exact).
double crease_step_faces(const rt::Mesh& mesh) {
  double sharpest = 0, features = 0;
  for (const auto& c : mesh.tags.creases)
    if (c.sharpness > 0 && c.sharpness < 10) sharpest = std::max(sharpest, c.sharpness), ++features;
  for (const auto& c : mesh.tags.corners)
    if (c.sharpness > 0 && c.sharpness < 10) sharpest = std::max(sharpest, c.sharpness), ++features;
  if (!(sharpest > 0)) return 0;  // NaN included: refused before any step
  const double steps = std::ceil(sharpest);
  const double whole = static_cast<double>(mesh.face_vertices.size()) * std::pow(4.0, steps - 1);
  // Both families take whole-mesh steps within their budget (lowered to this one below), else refine round the features.
  if (whole <= kCreaseStepFaceBudget) return whole;
  return 32 * features * std::pow(2.0, steps) + 16 * static_cast<double>(mesh.face_vertices.size());
}

const rt::Mesh& bundled_mesh(const char* name) {
  static std::map<std::string, rt::Mesh> meshes;
  auto it = meshes.find(name);
  if (it == meshes.end()) {
    try {
      it = meshes.emplace(name, rt::read_obj((source_dir() / "meshes" / name).string())).first;
    } catch (const std::exception& e) {
      harness_failure(e.what());
    }
  }
  return it->second;
}

// As stenciltess does: topology from the connectivity, a plan at `rates`
// (clamped to the tables by the plan), positions, then a few exact grid
// parameters of the first faces evaluated (corners and an inner point at every
// stored rate, within the budget), then a few real ones. A valence or rule the
// tables lack is a MeshError, reported by the tools the same way.
void use_surface(const std::shared_ptr<const rt::Tables>& tables, const rt::Mesh& mesh, const std::vector<int>& rates,
                 Budget& budget) {
  try {
    // With the mesh's tags (holes, creases, corners, smooth triangles), as the tools do.
    const auto topology = rt::SurfaceTopology::create(tables, mesh);
    const rt::Surface surface(topology, mesh.positions);
    rt::tessellate(surface, rates, {1});
    // And with normals: the one-pass kernels (quad/regular_face_samples, the
    // triangle families' sparse jets and cached centre stencils) under the sanitizers too.
    rt::tessellate(surface, rates, {1}, true);
    const std::size_t faces = std::min<std::size_t>(topology->face_count(), 8);
    for (int n : tables->rates()) {
      const std::int64_t points[][2] = {{0, 0}, {n, 0}, {0, n}, {n / 3, n / 3}};
      for (std::size_t f = 0; f < faces; ++f)
        for (const auto& p : points) {
          if (!budget.take(200)) return;
          surface.evaluate(f, rt::ExactParameter{{p[0], n}, {p[1], n}});
        }
    }
    // Between the grids: the patch descent through the tables' subdivision
    // (hostile rules may have no bound: an EvaluationError that says so), and
    // rows by linearity where the descent is exact.
    for (std::size_t f = 0; f < faces; ++f)
      for (const auto& [u, v] : {std::pair{0.3, 0.2}, std::pair{1.0 / 29, 1e-7}, std::pair{1e-30, 0.5}}) {
        if (!budget.take(2000)) return;
        try {
          surface.evaluate(f, u, v, 1e-9);
          topology->stencil(f, u, v);
        } catch (const rt::EvaluationError&) {
        }
      }
    // Derivatives: the descent on to a regular patch (through the tables' phi'
    // at exact grid parameters); refusals (the vertex, a triangle scheme,
    // tables without phi') are EvaluationErrors.
    for (std::size_t f = 0; f < faces; ++f)
      for (const auto& [u, v] : {std::pair{1.0 / 3, 0.5}, std::pair{0.25, 0.0}, std::pair{0.3, 0.2}}) {
        if (!budget.take(2000)) return;
        try {
          surface.derivatives(f, u, v);
          const int n = tables->rates().back();
          surface.derivatives(f, rt::ExactParameter{{1, n}, {n - 1 > 0 ? n - 1 : 1, n}});
        } catch (const rt::EvaluationError&) {
        }
      }
    // Normals at the corners: at an extraordinary vertex from the tables'
    // tangent stencils (refused, with the reason, where they hold none).
    for (std::size_t f = 0; f < faces; ++f) {
      if (!budget.take(200)) return;
      try {
        surface.normal(f, rt::ExactParameter{{0, 1}, {0, 1}});
      } catch (const rt::EvaluationError&) {
      }
    }
  } catch (const rt::MeshError&) {
  }
}

// reflection(v) is documented as a permutation of the patch's points; the
// runtime indexes control points with it unchecked.
void check_permutation(const std::uint32_t* reflection, std::size_t points, int valence) {
  std::vector<bool> seen(points, false);
  for (std::size_t h = 0; h < points; ++h) {
    if (reflection[h] >= points || seen[reflection[h]])
      finding("valence " + std::to_string(valence) + ": the loader accepted a reflection that is not a permutation of 0.." +
              std::to_string(points - 1) + " (entry " + std::to_string(h) + " is " + std::to_string(reflection[h]) + ")");
    seen[reflection[h]] = true;
  }
}

void sweep_quad(const rt::QuadTables& tables, Budget& budget) {
  std::vector<int> valences = tables.valences();
  valences.push_back(4);
  for (const rt::SectorKey& s : tables.sectors()) valences.push_back(rt::sector_kind(s));  // expanded on this first use
  for (int v : valences) {
    std::vector<double> weights(static_cast<std::size_t>(rt::QuadTables::points(v)));
    for (int n : tables.rates()) {
      if (!budget.take(2L * (n + 1) * (n + 1) * static_cast<long>(weights.size()))) break;
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
          tables.node_stencil(v, n, i, j, weights.data());
          if (i < n && j < n) tables.centre_stencil(v, n, i, j, weights.data());
        }
      if (v == 4) continue;
      // As the tessellation reads them: whole stored stencils, applied to the
      // control points permuted by the reflection where mirrored.
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          bool mirrored = false;
          const double* w = tables.centre_weights(v, n, i, j, mirrored);
          std::copy(w, w + weights.size(), weights.begin());
        }
    }
    if (v != 4 && !rt::is_sector_kind(v)) check_permutation(tables.reflection(v), weights.size(), v);
  }
}

void sweep_triangle(const rt::TriangleTables& tables, Budget& budget) {
  for (int v : tables.valences())
    for (int region = 0; region < tables.regions(v); ++region) {
      const long points = static_cast<long>(tables.layout(v, region).size());
      for (int n : tables.rates()) {
        if (!budget.take(2L * (n + 1) * (n + 2) * points)) break;
        const rt::TriangleTables::Grid grid = tables.grid(v, n, region);
        double sum = 0;
        auto read = [&](const double* w) {
          for (long h = 0; h < points; ++h) sum += w[h];
        };
        for (int j = 0; j <= n; ++j)
          for (int i = 0; i + j <= n; ++i) {
            read(grid.weights(rt::TriangleTables::GridPoint::Node, i, j));
            if (region == 0) read(tables.node_weights(v, n, i, j));
            if (i + j <= n - 1) read(grid.weights(rt::TriangleTables::GridPoint::Up, i, j));
            if (i + j <= n - 2) read(grid.weights(rt::TriangleTables::GridPoint::Down, i, j));
          }
        if (!(sum == sum)) sum = 0;  // the sum is only read to keep the loads alive
      }
    }
}

}  // namespace

void use_tables(const std::shared_ptr<const rt::Tables>& shared) {
  Budget budget;
  const rt::Tables& tables = *shared;
  if (tables.family() == rt::SchemeFamily::Quad) {
    sweep_quad(tables.quad(), budget);
    for (const char* name : {"cube.obj", "icosahedron.obj"}) {
      const rt::Mesh& mesh = bundled_mesh(name);
      use_surface(shared, mesh, std::vector<int>(mesh.face_count(), 1), budget);
    }
  } else {
    sweep_triangle(tables.triangle(), budget);
    const rt::Mesh& mesh = bundled_mesh("icosahedron.obj");
    use_surface(shared, mesh, std::vector<int>(mesh.face_count(), 1), budget);
  }
}

// Semi-sharp features take one whole-mesh step (4x the faces) per unit of
// sharpness: a few lines of tags can ask for millions of faces, legitimately
// (the library refuses only beyond its stated limit) and for seconds under the
// sanitizers. Clamps them to what keeps the prepared mesh near 8192 faces, so
// one input stays within milliseconds; infinitely sharp ones (>= 10) and
// invalid values (which the checks must refuse) are kept, and so is every tag
// when one of them is over the library's limit however the faces are made
// (at least 3 corners each), which it refuses before any work.
rt::Mesh within_budget(const rt::Mesh& mesh) {
  constexpr std::size_t kPreparedFaces = 8192;
  double cap = 1;
  for (std::size_t faces = std::max<std::size_t>(mesh.face_count(), 1) * 16; faces <= kPreparedFaces; faces *= 4) cap += 1;
  auto refused = [&](double s) {
    if (!(s > 0 && s < 10)) return false;
    double made = 3.0 * static_cast<double>(mesh.face_count());
    for (int k = 1; k < static_cast<int>(std::ceil(s)); ++k) made *= 4;
    return made > static_cast<double>(rt::limits::kMaxCreaseStepFaces);
  };
  for (const auto& c : mesh.tags.creases)
    if (refused(c.sharpness)) return mesh;
  for (const auto& c : mesh.tags.corners)
    if (refused(c.sharpness)) return mesh;
  rt::Mesh out = mesh;
  auto clamp = [&](double& s) {
    if (s > cap && s < 10) s = cap;
  };
  for (auto& c : out.tags.creases) clamp(c.sharpness);
  for (auto& c : out.tags.corners) clamp(c.sharpness);
  return out;
}

void use_mesh(const rt::Mesh& input) {
  const rt::Mesh mesh = within_budget(input);
  auto fixture = [](const char* name) {
    try {
      return rt::Tables::load((fixtures_dir() / name).string());
    } catch (const std::exception& e) {
      harness_failure(e.what());
    }
  };
  static const std::shared_ptr<const rt::Tables> quad_tables = fixture("nonpoly.sgs");
  static const std::shared_ptr<const rt::Tables> triangle_tables = fixture("loop.sgt");
  const bool triangles = std::all_of(mesh.face_sizes.begin(), mesh.face_sizes.end(), [](int k) { return k == 3; });
  // stenciltess --tolerance / --camera take the rates from the mesh before the
  // surface checks it.
  try {
    stencil_tools::rates_for_tolerance(mesh, 1e-3);
  } catch (const rt::MeshError&) {
  }
  const std::vector<int> view_rates = stencil_tools::rates_for_view(mesh, stencil_tools::Camera{}, 8);
  // Both ways of the families within the budget: whole-mesh steps up to it, refinement round the features beyond.
  static const bool budget_set = (rt::set_whole_mesh_crease_faces(static_cast<std::size_t>(kCreaseStepFaceBudget)), true);
  (void)budget_set;
  if (crease_step_faces(mesh) > kCreaseStepFaceBudget) return;
  Budget budget;
  use_surface(triangles ? triangle_tables : quad_tables, mesh, view_rates, budget);
}

}  // namespace fuzz
