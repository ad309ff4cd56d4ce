// Fuzz target: points files of stencildist and stencilfit
// (stencil_tools::read_points): the first byte picks the form (.xyz, .ply,
// .off), the rest is the file. A result must be non-empty, with every
// coordinate finite and at most 1e37 in magnitude, as documented.
#include <cmath>

#include "fuzz_support.hpp"
#include "points_file.hpp"

namespace {

// Adapter: the entry point under test.
std::vector<stencil_runtime::Point> parse(const std::string& path) { return stencil_tools::read_points(path); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static const char* const kNames[] = {"points.xyz", "points.ply", "points.off"};
  const std::string path = fuzz::write_scratch_file(kNames[data[0] % 3], fuzz::as_text(data + 1, size - 1));
  fuzz::run_expecting_errors([&] {
    const auto points = parse(path);
    if (points.empty()) fuzz::finding("read_points returned no points without an error");
    for (const auto& p : points)
      for (const double x : p)
        if (!std::isfinite(x) || std::abs(x) > 1e37) fuzz::finding("read_points accepted a coordinate out of its limits");
  });
  return 0;
}
