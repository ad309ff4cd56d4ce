#include "quad/generate_quad.hpp"

#include <algorithm>
#include <mutex>
#include <tbb/parallel_for.h>

#include "algebra/real.hpp"
#include "base/error.hpp"
#include "base/limits.hpp"
#include "common/atomic_output.hpp"
#include "common/rate_spec.hpp"
#include "common/table_set_pipeline.hpp"
#include "curve/curve_table.hpp"
#include "curve/curve_table_json.hpp"
#include "curve/difference_scheme.hpp"
#include "curve/residue_solver.hpp"
#include "quad/boundary_sector.hpp"
#include "quad/ev_patch_solver.hpp"
#include "quad/quad_descent.hpp"
#include "quad/quad_descent_json.hpp"
#include "quad/quad_table_json.hpp"
#include "stencil_runtime/binary_format.hpp"

namespace sg {

namespace {

// The boundary sectors of vertices in up to as many faces as the largest
// valence asked for, as far as the runtime can expand their stencils at the
// largest rate (binary_format.hpp); `progress` is told of any left out.
std::vector<BoundarySector> sectors_for(const std::vector<int>& valences, const std::vector<long>& rates,
                                        const std::function<void(const std::string&)>& progress) {
  namespace fmt = stencil_runtime::format;
  const int largest = *std::max_element(valences.begin(), valences.end());
  const long rate = *std::max_element(rates.begin(), rates.end());
  int faces = largest;
  while (faces >= 1 &&
         fmt::expansion_grid_entries(static_cast<std::uint64_t>(rate),
                                     SectorLayout({SectorKind::Crease, faces, faces > 1 ? 1 : 0}).size()) > fmt::kMaxExpansionGridEntries)
    --faces;
  if (faces < largest && progress)
    progress("note: boundary vertices in more than " + std::to_string(faces) + " faces get no patches at rate " +
             std::to_string(rate) + " (their stencils would exceed the runtime's expansion limit)");
  return boundary_sectors(faces, true);  // corners too: for sharp corners and crease ends of three or more sharp edges
}

}  // namespace

QuadTableSet generate_quad_tables(const QuadScheme& scheme, const std::vector<int>& valences,
                                        const std::vector<long>& rates,
                                        const std::function<void(const std::string&)>& progress) {
  if (valences.empty() || rates.empty()) throw Error("nothing to generate: no valences or no rates");
  for (int v : valences) scheme.vertex_rule(v);  // range check with the scheme's own message
  check_rates(rates, limits::kMaxSurfaceRate, "the largest rate for surface schemes");
  QuadTableSet set;
  set.descent = std::make_shared<const QuadDescent>(quad_descent(scheme, valences, sectors_for(valences, rates, progress), progress));
  set.rates = rates;
  set.valences = valences;
  set.regular.resize(rates.size());
  set.regular_tables.resize(rates.size());
  // phi' of the regular curve where it is C1: the regular patch's derivatives (docs/table-format.md).
  const DerivativeSchemes derivative = derivative_schemes(scheme.curve, 1);
  sg::prepare_real_limits();  // before threads first use Real (algebra/real.hpp)
  tbb::parallel_for(std::size_t(0), rates.size(), [&](std::size_t r) {
    set.regular[r] = solve_by_residues(scheme.curve, 2 * rates[r]);
    set.regular_tables[r] = table_with_derivatives(scheme.curve, set.regular[r], derivative);
  });

  set.tables.assign(valences.size(), std::vector<QuadTable>(rates.size()));
  const auto jobs = valence_rate_jobs(valences, rates);
  std::mutex report;
  std::vector<std::size_t> done(valences.size(), 0);
  sg::prepare_real_limits();  // before threads first use Real (algebra/real.hpp)
  tbb::parallel_for(std::size_t(0), jobs.size(), [&](std::size_t k) {
    const auto [v, r] = jobs[k];
    const PatchGrid patch = solve_ev_patch(scheme, valences[v], 2 * rates[r], set.regular[r]);
    QuadTable table = make_quad_table(scheme, patch);
    const auto failures = check_quad_table(table);
    if (!failures.empty())
      throw Error("scheme '" + scheme.name + "', valence " + std::to_string(valences[v]) + ", n = " +
                  std::to_string(rates[r]) + ": check failed: " + failures.front());
    set.tables[v][r] = std::move(table);
    if (progress) {
      std::lock_guard lock(report);
      if (++done[v] == rates.size())
        progress(scheme.name + ": valence " + std::to_string(valences[v]) + " solved and checked for " +
                 std::to_string(rates.size()) + " rates");
    }
  });
  return set;
}

std::size_t write_quad_tables(const QuadScheme& scheme, const QuadTableSet& set,
                                 const std::filesystem::path& out_dir, BinaryPrecision precision, BinaryLayout layout) {
  OutputTransaction tx(out_dir / scheme.name);
  for (std::size_t r = 0; r < set.rates.size(); ++r)
    tx.add("regular/n" + std::to_string(2 * set.rates[r]) + ".json",
           curve_table_to_json(set.regular_tables[r]));
  add_table_files(tx, set.tables, quad_table_to_json);
  tx.add("descent.json", quad_descent_to_json(scheme, *set.descent));
  std::string binary = quad_tables_to_binary(scheme, set, precision, layout);
  const std::size_t size = binary.size();
  tx.add(scheme.name + ".sgs", std::move(binary));
  tx.commit();
  return size;
}

}  // namespace sg
