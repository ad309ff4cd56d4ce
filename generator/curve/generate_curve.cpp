#include "curve/generate_curve.hpp"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <mutex>
#include <tbb/task_arena.h>
#include <tbb/parallel_for.h>

#include "algebra/real.hpp"
#include "base/error.hpp"
#include "base/limits.hpp"
#include "common/atomic_output.hpp"
#include "common/rate_spec.hpp"
#include "curve/curve_table_binary.hpp"
#include "curve/curve_table_json.hpp"
#include "curve/curve_table_verify.hpp"
#include "curve/difference_scheme.hpp"
#include "curve/eigen_solver.hpp"
#include "curve/nonuniform_derivative.hpp"
#include "curve/residue_solver.hpp"

namespace sg {

std::vector<CurveTable> generate_curve_tables(const CurveScheme& scheme, const std::vector<long>& rates,
                                              RouteChoice routes,
                                              const std::function<void(const std::string&)>& progress,
                                              std::uint64_t max_digits) {
  check_rates(rates, limits::kMaxCurveRate, "the largest rate for curve schemes");
  std::vector<CurveTable> tables(rates.size());
  const bool uniform = scheme.is_uniform();
  const DerivativeSchemes derivatives = uniform ? derivative_schemes(scheme, kMaxDerivativeOrder) : DerivativeSchemes{};
  const NonuniformDerivative nonuniform = uniform ? NonuniformDerivative{} : nonuniform_derivative_plan(scheme);
  const std::size_t orders = uniform ? derivatives.schemes.size() : nonuniform.available ? 1 : 0;
  const std::string& stop = uniform ? derivatives.stop : nonuniform.stop;
  if (progress)
    progress(scheme.name + ": " +
             (orders == 0 ? std::string("values only")
                          : "values and derivatives of order 1" + std::string(orders > 1 ? " and 2" : "")) +
             (stop.empty() ? "" : "; " + stop));
  std::mutex report;
  std::size_t done = 0;
  std::uint64_t digits = 0;  // of the tables made so far (under `report`)
  // One scheme at one rate by the chosen route(s), both compared for exact equality.
  auto solve = [&](const CurveScheme& s, long n) {
    CurveSolution sol = routes == RouteChoice::Eigen ? solve_by_eigenvector(s, n) : solve_by_residues(s, n);
    if (routes == RouteChoice::Both && !(solve_by_eigenvector(s, n) == sol))
      throw Error("scheme '" + s.name + "', n = " + std::to_string(n) +
                  ": the residue-class route and the eigenvector route disagree (a generator bug; please report)");
    return sol;
  };
  auto make = [&](std::size_t i) {
    const long n = rates[i];
    tables[i] = make_table(scheme, solve(scheme, n));
    std::vector<CurveSolution> psi;
    for (const CurveScheme& d : derivatives.schemes) psi.push_back(solve(d, n));
    if (uniform) add_derivatives(tables[i], psi, derivatives.stop);
    else if (nonuniform.available) {
      // A rate whose relations at 0 have no unique solution keeps its values, with the reason.
      try {
        add_first_derivative(tables[i], solve_nonuniform_derivative(scheme, nonuniform, n), stop);
      } catch (const Error& e) {
        tables[i].derivatives_stop = std::string("no derivative tables at this rate: ") + e.what();
      }
    }
    else tables[i].derivatives_stop = stop;
    const auto failures = verify_curve_table(tables[i], scheme);
    if (!failures.empty())
      throw Error("scheme '" + scheme.name + "', n = " + std::to_string(n) + ": verification failed: " + failures.front());
    const std::uint64_t own = exact_digits(tables[i]);
    std::lock_guard lock(report);
    digits += own;
    if (digits > max_digits)
      throw Error("scheme '" + scheme.name + "': the tables of the rates made so far hold " + std::to_string(digits) +
                  " decimal digits of exact numbers (n = " + std::to_string(n) + " alone " + std::to_string(own) +
                  "), above the limit of " + std::to_string(max_digits) +
                  " for one run; ask for fewer rates, or rates whose expansions in base " + std::to_string(scheme.arity) +
                  " have short periods (powers of the arity, or n dividing a small power of it minus 1)");
    if (progress) {
      ++done;
      progress(scheme.name + ": n = " + std::to_string(n) + " solved and verified (" + std::to_string(done) + "/" +
               std::to_string(rates.size()) + ")");
    }
  };
  // Largest rates first, each worker taking the next one when it is free (a
  // parallel_for over the rates would hand half of them, the small half, to
  // the second worker): the largest tables come first, so a request beyond
  // the size limit stops early, and the last jobs to finish are short.
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  const int workers = std::max(1, tbb::this_task_arena::max_concurrency());
  sg::prepare_real_limits();  // before threads first use Real (algebra/real.hpp)
  tbb::parallel_for(
      0, workers,
      [&](int) {
        for (std::size_t job; !failed && (job = next++) < rates.size();) {
          try {
            make(rates.size() - 1 - job);
          } catch (...) {
            failed = true;
            throw;
          }
        }
      },
      tbb::simple_partitioner());
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
