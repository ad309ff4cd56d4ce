// Benchmark: exact surface tables. Prints (1) the headline job, as
// `stencilgen --scheme nonpoly --valence 3-8 --n 24` does it in memory (solve,
// check, JSON and binary serialisation; all threads), with the binary size in
// double and single precision and the exact JSON size; (2) the growth of time
// and binary size with the valence and the largest rate, up to valence 16 and
// rate 64. Usage: bench_surface_generation [SCHEME=nonpoly]
#include <chrono>
#include <cstdio>
#include <string>
#include <tbb/parallel_for.h>
#include <thread>
#include <vector>

#include "quad/generate_quad.hpp"
#include "quad/quad_scheme_loader.hpp"
#include "quad/quad_table_json.hpp"

namespace {
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

struct Measured {
  double seconds = 0;
  std::size_t binary_double = 0, binary_single = 0, json = 0;
};

Measured run(const sg::QuadScheme& s, const std::vector<int>& valences, long n_max) {
  std::vector<long> rates;
  for (long n = 1; n <= n_max; ++n) rates.push_back(n);
  const auto t0 = Clock::now();
  const sg::QuadTableSet set = sg::generate_quad_tables(s, valences, rates);
  std::vector<const sg::QuadTable*> all;
  for (const auto& by_rate : set.tables)
    for (const auto& t : by_rate) all.push_back(&t);
  std::vector<std::size_t> json_sizes(all.size());
  tbb::parallel_for(std::size_t(0), all.size(), [&](std::size_t k) { json_sizes[k] = sg::quad_table_to_json(*all[k]).size(); });
  Measured m;
  m.binary_double = sg::quad_tables_to_binary(s, set, sg::BinaryPrecision::Double).size();
  m.seconds = seconds_since(t0);
  m.binary_single = sg::quad_tables_to_binary(s, set, sg::BinaryPrecision::Single).size();
  for (std::size_t b : json_sizes) m.json += b;
  return m;
}
}  // namespace

int main(int argc, char** argv) {
  const sg::QuadScheme s = sg::load_quad_scheme(argc > 1 ? argv[1] : "nonpoly");
  std::printf("# scheme %s, %u hardware threads\n", s.name.c_str(), std::thread::hardware_concurrency());
  std::printf("headline: valences 3-8, rates 1..24 (solve + check + JSON + binary in memory)\n");
  for (int r = 0; r < 3; ++r) {
    const Measured m = run(s, {3, 4, 5, 6, 7, 8}, 24);
    std::printf("  run %d: %.3f s; binary %.2f MB (double), %.2f MB (single); exact JSON %.1f MB\n", r + 1, m.seconds,
                m.binary_double / 1e6, m.binary_single / 1e6, m.json / 1e6);
  }
  std::printf("\n| valence | rates | time (s) | binary, double (MB) | binary, single (MB) | exact JSON (MB) |\n");
  std::printf("|---|---|---|---|---|---|\n");
  for (int v : {3, 8, 12, 16})
    for (long n : {24L, 32L, 48L, 64L}) {
      const Measured m = run(s, {v}, n);
      std::printf("| %d | 1..%ld | %.2f | %.2f | %.2f | %.1f |\n", v, n, m.seconds, m.binary_double / 1e6,
                  m.binary_single / 1e6, m.json / 1e6);
    }
  const Measured all = run(s, {3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16}, 64);
  std::printf("| 3..16 | 1..64 | %.2f | %.2f | %.2f | %.1f |\n", all.seconds, all.binary_double / 1e6,
              all.binary_single / 1e6, all.json / 1e6);
  return 0;
}
