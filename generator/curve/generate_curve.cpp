#include "curve/generate_curve.hpp"

#include <mutex>
#include <tbb/parallel_for.h>

#include "base/error.hpp"
#include "base/limits.hpp"
#include "common/atomic_output.hpp"
#include "common/rate_spec.hpp"
#include "curve/curve_table_binary.hpp"
#include "curve/curve_table_json.hpp"
#include "curve/curve_table_verify.hpp"
#include "curve/eigen_solver.hpp"
#include "curve/residue_solver.hpp"

namespace sg {

std::vector<CurveTable> generate_curve_tables(const CurveScheme& scheme, const std::vector<long>& rates,
                                              RouteChoice routes,
                                              const std::function<void(const std::string&)>& progress) {
  check_rates(rates, limits::kMaxCurveRate, "the largest rate for curve schemes");
  std::vector<CurveTable> tables(rates.size());
  std::mutex report;
  std::size_t done = 0;
  tbb::parallel_for(std::size_t(0), rates.size(), [&](std::size_t i) {
    const long n = rates[i];
    CurveSolution sol = routes == RouteChoice::Eigen ? solve_by_eigenvector(scheme, n) : solve_by_residues(scheme, n);
    if (routes == RouteChoice::Both && !(solve_by_eigenvector(scheme, n) == sol))
      throw Error("scheme '" + scheme.name + "', n = " + std::to_string(n) +
                  ": the residue-class route and the eigenvector route disagree (a generator bug; please report)");
    tables[i] = make_table(scheme, sol);
    const auto failures = verify_curve_table(tables[i], scheme);
    if (!failures.empty())
      throw Error("scheme '" + scheme.name + "', n = " + std::to_string(n) + ": verification failed: " + failures.front());
    if (progress) {
      std::lock_guard lock(report);
      ++done;
      progress(scheme.name + ": n = " + std::to_string(n) + " solved and verified (" + std::to_string(done) + "/" +
               std::to_string(rates.size()) + ")");
    }
  });
  return tables;
}

void write_curve_tables(const CurveScheme& scheme, const std::vector<CurveTable>& tables,
                        const std::filesystem::path& out_dir) {
  OutputTransaction tx(out_dir / scheme.name);
  for (const CurveTable& t : tables) {
    const std::string stem = "n" + std::to_string(t.n);
    tx.add(stem + ".json", curve_table_to_json(t));
    tx.add(stem + ".sgc", curve_table_to_binary(t, scheme.hash));
  }
  tx.commit();
}

}  // namespace sg
