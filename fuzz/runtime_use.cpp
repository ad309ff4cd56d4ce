#include "runtime_use.hpp"

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "fuzz_support.hpp"
#include "rate_choice.hpp"
#include "stencil_runtime/limit_surface.hpp"
#include "stencil_runtime/tessellation.hpp"
#include "stencil_runtime/triangle_surface.hpp"
#include "stencil_runtime/triangle_tessellation.hpp"

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

// Rate 1 for every original face, as stenciltess --rate 1 asks for it.
template <class Surface>
void tessellate_at_rate_one(const Surface& surface, const std::vector<int>& table_rates) {
  std::vector<int> rates = rt::prepared_rates(surface, std::vector<int>(surface.original_faces(), 1));
  stencil_tools::snap_to_tables(rates, table_rates);
  rt::tessellate(surface, rates, {1});
}

// Corners and an inner point of the first original faces with `corners`
// corners (the faces evaluate() takes), at every rate (quads: (i, j) in
// [0, n]^2; triangles: i + j <= n).
template <class Surface>
void evaluate_some(const Surface& surface, const rt::Mesh& mesh, int corners, const std::vector<int>& table_rates,
                   Budget& budget) {
  std::vector<std::size_t> faces;
  for (std::size_t f = 0; f < mesh.face_count() && faces.size() < 8; ++f)
    if (mesh.face_sizes[f] == corners) faces.push_back(f);
  for (int n : table_rates) {
    const long far = corners == 4 ? n : 0;
    const long points[][2] = {{0, 0}, {n, 0}, {0, n}, {far, far}, {n / 3, n / 3}};
    for (std::size_t f : faces)
      for (const auto& p : points) {
        if (!budget.take(200)) return;
        surface.evaluate(f, p[0], p[1], n);
      }
  }
}

void use_quad_surface(const rt::SurfaceTables& tables, const rt::Mesh& mesh, Budget& budget) {
  try {
    const rt::LimitSurface surface(tables, mesh, "fuzz");
    tessellate_at_rate_one(surface, tables.rates());
    evaluate_some(surface, mesh, 4, tables.rates(), budget);
  } catch (const rt::MeshError&) {
    // A valence or rule the tables lack: the tools report it the same way.
  }
}

void use_triangle_surface(const rt::TriangleTables& tables, const rt::Mesh& mesh, Budget& budget) {
  try {
    const rt::TriangleSurface surface(tables, mesh, "fuzz");
    tessellate_at_rate_one(surface, tables.rates());
    evaluate_some(surface, mesh, 3, tables.rates(), budget);
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

}  // namespace

void use_quad_tables(const rt::SurfaceTables& tables) {
  Budget budget;
  std::vector<int> valences = tables.valences();
  valences.push_back(4);
  for (int v : valences) {
    std::vector<double> weights(static_cast<std::size_t>(rt::SurfaceTables::points(v)));
    for (int n : tables.rates()) {
      if (!budget.take(2L * (n + 1) * (n + 1) * static_cast<long>(weights.size()))) break;
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
          tables.node_stencil(v, n, i, j, weights.data());
          if (i < n && j < n) tables.centre_stencil(v, n, i, j, weights.data());
        }
      if (v == 4) continue;
      // As LimitSurface::evaluate_centres reads them: whole stored stencils,
      // applied to the control points permuted by the reflection where mirrored.
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          bool mirrored = false;
          const double* w = tables.centre_weights(v, n, i, j, mirrored);
          std::copy(w, w + weights.size(), weights.begin());
        }
    }
    if (v != 4) check_permutation(tables.reflection(v), weights.size(), v);
  }
  use_quad_surface(tables, bundled_mesh("cube.obj"), budget);
  use_quad_surface(tables, bundled_mesh("icosahedron.obj"), budget);
}

void use_triangle_tables(const rt::TriangleTables& tables) {
  Budget budget;
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
  use_triangle_surface(tables, bundled_mesh("icosahedron.obj"), budget);
}

void use_mesh(const rt::Mesh& mesh) {
  static const rt::SurfaceTables quad_tables = [] {
    try {
      return rt::SurfaceTables::load((fixtures_dir() / "nonpoly.sgs").string());
    } catch (const std::exception& e) {
      harness_failure(e.what());
    }
  }();
  static const rt::TriangleTables triangle_tables = [] {
    try {
      return rt::TriangleTables::load((fixtures_dir() / "loop.sgt").string());
    } catch (const std::exception& e) {
      harness_failure(e.what());
    }
  }();
  const bool triangles = std::all_of(mesh.face_sizes.begin(), mesh.face_sizes.end(), [](int k) { return k == 3; });
  // stenciltess --tolerance / --camera take the rates from the mesh before the
  // surface checks it (corners: 3 with triangle tables, 4 with quad tables).
  try {
    stencil_tools::rates_for_tolerance(mesh, 1e-3, triangles ? 3 : 4);
  } catch (const rt::MeshError&) {
  }
  const std::vector<int> view_rates = stencil_tools::rates_for_view(mesh, stencil_tools::Camera{}, 8);
  Budget budget;
  auto use = [&](const auto& surface, const std::vector<int>& table_rates) {
    std::vector<int> rates = rt::prepared_rates(surface, view_rates);
    stencil_tools::snap_to_tables(rates, table_rates);
    rt::tessellate(surface, rates, {1});
    evaluate_some(surface, mesh, triangles ? 3 : 4, table_rates, budget);
  };
  if (triangles) use(rt::TriangleSurface(triangle_tables, mesh, "loop"), triangle_tables.rates());
  else use(rt::LimitSurface(quad_tables, mesh, "nonpoly"), quad_tables.rates());
}

}  // namespace fuzz
