// Fuzz target: stencileval's exact parameters (stencil_tools::parse_parameter,
// "1/3", "0", "2/4"), checked against what it promises: a reduced fraction
// with a positive denominator, in [0, 1].
#include <numeric>

#include "fuzz_support.hpp"
#include "table_location.hpp"

namespace {

// Adapter: the entry point under test.
stencil_tools::Fraction parse(const std::string& text) { return stencil_tools::parse_parameter(text); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(fuzz::as_text(data, size));
  fuzz::run_expecting_errors([&] {
    const stencil_tools::Fraction f = parse(text);
    if (f.den <= 0 || f.num < 0 || f.num > f.den || std::gcd(f.num, f.den) != 1)
      fuzz::finding("parse_parameter(\"" + text + "\") gave " + std::to_string(f.num) + "/" + std::to_string(f.den) +
                    ", not a reduced fraction in [0, 1]");
  });
  return 0;
}
