// Fuzz target: stencilgen's --n and --valence lists (sg::parse_rate_spec,
// "24", "12-24", "1-4,8"); a result must be sorted, without duplicates, every
// entry in 1..the stated limit, as documented.
#include <algorithm>

#include "fuzz_support.hpp"
#include "base/limits.hpp"
#include "common/rate_spec.hpp"

namespace {

// Adapter: the entry point under test.
std::vector<long> parse(const std::string& text) {
  return sg::parse_rate_spec(text, sg::limits::kMaxCurveRate, "the largest rate for curve schemes");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(fuzz::as_text(data, size));
  fuzz::run_expecting_errors([&] {
    const std::vector<long> rates = parse(text);
    if (rates.empty() || rates.front() < 1 || rates.back() > sg::limits::kMaxCurveRate || std::adjacent_find(rates.begin(), rates.end(), std::greater_equal<>()) != rates.end())
      fuzz::finding("parse_rate_spec(\"" + text + "\") is not a sorted list of distinct rates >= 1");
  });
  return 0;
}
