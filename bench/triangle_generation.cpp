// Benchmark: triangle-scheme tables (Loop, sqrt(3)). Prints (1) the headline
// job, as `stencilgen --scheme S --valence 3-8 --n 24` does it in memory
// (valence 6 added; solve, check, JSON and binary serialisation; all threads),
// with the binary size in double and single precision and the JSON size; (2)
// the growth of time and sizes with the largest rate.
// Usage: bench_triangle_generation [SCHEME=sqrt3]
#include <chrono>
#include <cstdio>
#include <string>
#include <tbb/parallel_for.h>
#include <thread>
#include <vector>

#include "triangle/generate_triangle.hpp"
#include "triangle/triangle_scheme_loader.hpp"

namespace {
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

struct Measured {
  double seconds = 0;
  std::size_t binary_double = 0, binary_single = 0, json = 0;
};

Measured run(const sg::TriangleScheme& s, const std::vector<int>& valences, long n_max) {
  std::vector<long> rates;
  for (long n = 1; n <= n_max; ++n) rates.push_back(n);
  const auto t0 = Clock::now();
  const sg::TriangleTableSet set = sg::generate_triangle_tables(s, valences, rates);
  std::vector<const sg::TriangleTable*> all;
  for (const auto& by_rate : set.tables)
    for (const auto& t : by_rate) all.push_back(&t);
  std::vector<std::size_t> json_sizes(all.size());
  tbb::parallel_for(std::size_t(0), all.size(), [&](std::size_t k) { json_sizes[k] = sg::triangle_table_to_json(*all[k]).size(); });
  Measured m;
  m.binary_double = sg::triangle_tables_to_binary(s, set, sg::BinaryPrecision::Double).size();
  m.seconds = seconds_since(t0);
  m.binary_single = sg::triangle_tables_to_binary(s, set, sg::BinaryPrecision::Single).size();
  for (std::size_t b : json_sizes) m.json += b;
  return m;
}
}  // namespace

int main(int argc, char** argv) {
  const sg::TriangleScheme s = sg::load_triangle_scheme(argc > 1 ? argv[1] : "sqrt3");
  std::printf("# scheme %s, %u hardware threads\n", s.name.c_str(), std::thread::hardware_concurrency());
  std::printf("headline: valences 3-8, rates 1..24 (solve + check + JSON + binary in memory)\n");
  for (int r = 0; r < 2; ++r) {
    const Measured m = run(s, {3, 4, 5, 6, 7, 8}, 24);
    std::printf("  run %d: %.3f s; binary %.2f MB (double), %.2f MB (single); JSON %.1f MB\n", r + 1, m.seconds,
                m.binary_double / 1e6, m.binary_single / 1e6, m.json / 1e6);
  }
  std::printf("\n| valences | rates | time (s) | binary, double (MB) | binary, single (MB) | JSON (MB) |\n");
  std::printf("|---|---|---|---|---|---|\n");
  for (long n : {6L, 12L, 18L}) {
    const Measured m = run(s, {3, 4, 5, 6, 7, 8}, n);
    std::printf("| 3..8 | 1..%ld | %.2f | %.2f | %.2f | %.1f |\n", n, m.seconds, m.binary_double / 1e6,
                m.binary_single / 1e6, m.json / 1e6);
  }
  for (int v : {3, 5, 12}) {
    const Measured m = run(s, {v}, 24);
    std::printf("| %d | 1..24 | %.2f | %.2f | %.2f | %.1f |\n", v, m.seconds, m.binary_double / 1e6,
                m.binary_single / 1e6, m.json / 1e6);
  }
  return 0;
}
