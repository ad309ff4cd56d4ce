// Fuzz target: binary curve tables (.sgc, load_curve_table), checksum made
// valid (sealed_binary.hpp), then a uniform curve and its derivatives evaluated
// over the grid of eight control points as a caller would.
#include <algorithm>
#include <vector>

#include "fuzz_support.hpp"
#include "sealed_binary.hpp"
#include "stencil_runtime/curve_table.hpp"

namespace {

// Adapter: the entry point under test.
stencil_runtime::CurveTable parse(const std::string& path) { return stencil_runtime::load_curve_table(path); }

void use(const stencil_runtime::CurveTable& table) {
  if (table.functions.size() != 1) return;  // evaluate_uniform_curve is for uniform tables
  const std::vector<double> points{0, 1, 0, -1, 2, 0, 1, 3};
  const std::int64_t n = table.n, reach = std::min<std::int64_t>(8 * n, 4096);  // bounded work
  for (std::int64_t k = -std::min<std::int64_t>(n, 4096); k <= reach; ++k) {
    stencil_runtime::evaluate_uniform_curve(table, points, k);
    for (int order = 1; order <= static_cast<int>(table.derivative_orders); ++order)
      stencil_runtime::evaluate_uniform_curve_derivative(table, points, k, order);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = fuzz::write_scratch_file("input.sgc", fuzz::with_valid_checksum(fuzz::as_text(data, size)));
  fuzz::run_expecting_errors([&] { use(parse(path)); });
  return 0;
}
