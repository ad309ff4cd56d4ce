// Benchmark: every shipped curve scheme at every rate n = 1..N_MAX, both exact
// solvers. Prints (1) the headline: total wall time with all threads, solving
// each (scheme, n) by both routes; (2) per-scheme single-thread times per route;
// (3) growth with n for a few rates. Usage: bench_curve_generation [N_MAX=64]
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstdio>
#include <string>
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <thread>
#include <vector>

#include "curve/curve_scheme_loader.hpp"
#include "curve/eigen_solver.hpp"
#include "curve/residue_solver.hpp"

namespace {
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
}  // namespace

int main(int argc, char** argv) {
  const long n_max = argc > 1 ? std::stol(argv[1]) : 64;
  std::vector<sg::CurveScheme> schemes;
  for (const auto& name : sg::available_schemes(sg::default_schemes_dir(), sg::SchemeFamily::Curve)) schemes.push_back(sg::load_curve_scheme(name));
  struct Job { std::size_t scheme; long n; };
  std::vector<Job> jobs;
  for (std::size_t s = 0; s < schemes.size(); ++s)
    for (long n = 1; n <= n_max; ++n) jobs.push_back({s, n});
  // Large rates first so the two threads finish together.
  std::sort(jobs.begin(), jobs.end(), [](const Job& a, const Job& b) { return a.n > b.n; });

  const int threads = static_cast<int>(std::thread::hardware_concurrency());
  std::printf("# %zu curve schemes, n = 1..%ld, both routes, %d threads\n", schemes.size(), n_max, threads);
  for (int run = 0; run < 3; ++run) {
    const auto t0 = Clock::now();
    tbb::parallel_for(std::size_t(0), jobs.size(), [&](std::size_t i) {
      const auto& j = jobs[i];
      const auto a = sg::solve_by_residues(schemes[j.scheme], j.n);
      const auto b = sg::solve_by_eigenvector(schemes[j.scheme], j.n);
      if (!(a == b)) std::abort();
    }, tbb::simple_partitioner());
    std::printf("total wall, run %d: %.3f s\n", run + 1, seconds_since(t0));
  }

  tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  std::printf("\n| scheme | residue route, n=1..%ld (s) | eigen route, n=1..%ld (s) |\n|---|---|---|\n", n_max, n_max);
  for (const auto& s : schemes) {
    double t_res = 0, t_eig = 0;
    for (long n = 1; n <= n_max; ++n) {
      auto t = Clock::now();
      sg::solve_by_residues(s, n);
      t_res += seconds_since(t);
      t = Clock::now();
      sg::solve_by_eigenvector(s, n);
      t_eig += seconds_since(t);
    }
    std::printf("| %s | %.4f | %.4f |\n", s.name.c_str(), t_res, t_eig);
  }
  std::printf("\nGrowth with n (single thread, ms per rate):\n| scheme | route |");
  const std::vector<long> sample{8, 16, 24, 32, 48, 61, 63, 64};
  for (long n : sample) std::printf(" n=%ld |", n);
  std::printf("\n|---|---|");
  for (std::size_t i = 0; i < sample.size(); ++i) std::printf("---|");
  std::printf("\n");
  for (const auto& s : schemes) {
    if (s.name != "fourpoint" && s.name != "dd6" && s.name != "nubspline3" && s.name != "ternary-dd4") continue;
    for (int route = 0; route < 2; ++route) {
      std::printf("| %s | %s |", s.name.c_str(), route ? "eigen" : "residue");
      for (long n : sample) {
        const auto t = Clock::now();
        route ? (void)sg::solve_by_eigenvector(s, n) : (void)sg::solve_by_residues(s, n);
        std::printf(" %.2f |", 1000 * seconds_since(t));
      }
      std::printf("\n");
    }
  }
  return 0;
}
