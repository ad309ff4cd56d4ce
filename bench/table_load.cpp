// Benchmark: size and load time of the binary surface tables in their two
// layouts (docs/table-format.md), for the headline set (valences 3-8, rates
// 1..24) of nonpoly and Catmull-Clark. Generated: the .sgs holds the patch
// subdivision, the regular curve's values and phi', and the limit stencil, and
// the reader expands the stencils; stored: every stencil. The reference is the
// paper's 2.5 MB (seed 001) and the targets: at most 1 MB with first
// derivatives, loaded in under 50 ms. Each load is the whole of
// QuadTables::load_binary (read, checksum, parse, expansion, validation),
// median of 21, one thread. Usage: bench_table_load [SCHEME...]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "quad/generate_quad.hpp"
#include "quad/quad_scheme_loader.hpp"
#include "tables/quad_tables.hpp"

namespace {
using Clock = std::chrono::steady_clock;

double median_load_ms(const std::string& path) {
  std::vector<double> ms;
  for (int k = 0; k < 21; ++k) {
    const auto t0 = Clock::now();
    const stencil_runtime::QuadTables t = stencil_runtime::QuadTables::load_binary(path);
    ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
    if (t.rates().empty()) return -1;
  }
  std::sort(ms.begin(), ms.end());
  return ms[ms.size() / 2];
}
}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> schemes(argv + 1, argv + argc);
  if (schemes.empty()) schemes = {"nonpoly", "catmull-clark"};
  std::printf("# headline set: valences 3-8, rates 1..24; %u hardware threads (loads run on one)\n",
              std::thread::hardware_concurrency());
  std::printf("| scheme | layout | precision | .sgs bytes | load, median of 21 (ms) |\n|---|---|---|---|---|\n");
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "bench_table_load";
  std::filesystem::create_directories(dir);
  for (const std::string& name : schemes) {
    const sg::QuadScheme s = sg::load_quad_scheme(name);
    std::vector<long> rates;
    for (long n = 1; n <= 24; ++n) rates.push_back(n);
    const sg::QuadTableSet set = sg::generate_quad_tables(s, {3, 4, 5, 6, 7, 8}, rates);
    for (auto layout : {sg::BinaryLayout::Generated, sg::BinaryLayout::Stored})
      for (auto precision : {sg::BinaryPrecision::Double, sg::BinaryPrecision::Single}) {
        const std::string bytes = sg::quad_tables_to_binary(s, set, precision, layout);
        const std::filesystem::path file = dir / (name + ".sgs");
        std::ofstream(file, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        std::printf("| %s | %s | %s | %zu | %.1f |\n", name.c_str(), layout == sg::BinaryLayout::Generated ? "generated" : "stored",
                    precision == sg::BinaryPrecision::Double ? "double" : "single", bytes.size(), median_load_ms(file.string()));
      }
  }
  std::filesystem::remove_all(dir);
  return 0;
}
