#include "triangle/generate_triangle.hpp"

#include <algorithm>
#include <mutex>
#include <tuple>
#include <tbb/parallel_for.h>

#include "algebra/real.hpp"
#include "base/error.hpp"
#include "base/limits.hpp"
#include "common/rate_spec.hpp"
#include "triangle/triangle_children.hpp"
#include "triangle/triangle_sectors_json.hpp"
#include "common/table_set_pipeline.hpp"

namespace sg {

TriangleTableSet generate_triangle_tables(const TriangleScheme& scheme, const std::vector<int>& valences,
                                          const std::vector<long>& rates,
                                          const std::function<void(const std::string&)>& progress) {
  if (valences.empty() || rates.empty()) throw Error("nothing to generate: no valences or no rates");
  for (int v : valences) scheme.real_neighbour_weight(v);  // range check with the scheme's own message
  check_rates(rates, limits::kMaxSurfaceRate, "the largest rate for surface schemes");
  TriangleTableSet set;
  set.rates = rates;
  set.valences = valences;
  std::vector<BivariateSolution> regular(rates.size());
  // The regular patch's derivative stencils, where its basis is not a
  // polynomial (sqrt(3)); Loop's quartic gives its derivatives directly.
  const bool derivatives = !regular_basis_is_polynomial(scheme);
  std::vector<BivariateGradient> gradient(rates.size());
  sg::prepare_real_limits();  // before threads first use Real (algebra/real.hpp)
  tbb::parallel_for(std::size_t(0), rates.size(), [&](std::size_t r) {
    if (derivatives) std::tie(regular[r], gradient[r]) = solve_regular_with_gradient(scheme, 3 * rates[r]);
    else regular[r] = solve_regular(scheme, 3 * rates[r]);
  });

  set.tables.assign(valences.size(), std::vector<TriangleTable>(rates.size()));
  const auto jobs = valence_rate_jobs(valences, rates);
  std::mutex report;
  std::vector<std::size_t> done(valences.size(), 0);
  std::vector<Real> worst(valences.size(), Real(0));
  sg::prepare_real_limits();  // before threads first use Real (algebra/real.hpp)
  tbb::parallel_for(std::size_t(0), jobs.size(), [&](std::size_t k) {
    const auto [vi, r] = jobs[k];
    const int v = valences[vi];
    const long n = rates[r];
    TriangleTable table = solve_triangle_table(scheme, v, n, regular[r], v == 6 && derivatives ? &gradient[r] : nullptr);
    if (v == 6) gradient[r] = {};  // its only reader is done
    if (!table.exact && !(table.residual < Real("1e-60")))
      throw Error("scheme '" + scheme.name + "', valence " + std::to_string(v) + ", n = " + std::to_string(n) +
                  ": the high-precision residual " + to_string(table.residual, 3) + " is too large");
    std::lock_guard lock(report);
    worst[vi] = std::max(worst[vi], table.residual);
    set.tables[vi][r] = std::move(table);
    if (progress && ++done[vi] == rates.size())
      progress(scheme.name + ": valence " + std::to_string(v) + " solved for " + std::to_string(rates.size()) +
               " rates, " +
               (set.tables[vi][r].exact ? std::string("exact")
                                                 : "high precision (" + std::to_string(kRealDigits) +
                                                       " digits), largest residual " + to_string(worst[vi], 3)));
  });
  return set;
}

std::size_t write_triangle_tables(const TriangleScheme& scheme, const TriangleTableSet& set,
                                  const std::filesystem::path& out_dir, BinaryPrecision precision,
                                  const std::function<void(const std::string&)>& progress) {
  OutputTransaction tx(out_dir / scheme.name);
  add_table_files(tx, set.tables, triangle_table_to_json);
  TriangleSectorSet sectors;
  std::string binary = triangle_tables_to_binary(scheme, set, precision, &sectors, progress);
  const std::size_t size = binary.size();
  tx.add(scheme.name + ".sgt", std::move(binary));
  if (!sectors.sectors.empty()) tx.add("sectors.json", triangle_sectors_to_json(scheme, sectors));  // the same, exact
  tx.commit();
  return size;
}

}  // namespace sg
