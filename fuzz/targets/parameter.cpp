// Fuzz target: stencileval's parameters (stencil_tools::parse_parameter: exact
// rationals "1/3", "0", "2/4", or decimals "0.3"), checked against what it
// promises: an exact parameter is a reduced fraction with a positive
// denominator, a decimal is finite. (The range [0, 1] is the face domain's to
// check, not the parser's.)
#include <cmath>
#include <cstdint>
#include <numeric>

#include "fuzz_support.hpp"
#include "tool_support.hpp"

namespace {

// Adapter: the entry point under test.
stencil_tools::ParameterText parse(const std::string& text) { return stencil_tools::parse_parameter(text); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(fuzz::as_text(data, size));
  fuzz::run_expecting_errors([&] {
    const stencil_tools::ParameterText p = parse(text);
    if (!std::isfinite(p.value)) fuzz::finding("parse_parameter(\"" + text + "\") gave a value that is not finite");
    if (!p.exact) return;
    const stencil_runtime::Fraction& f = p.fraction;
    // The numerator may be -2^63, whose negation std::gcd would need: compare magnitudes as unsigned.
    const std::uint64_t magnitude = f.num < 0 ? 0 - static_cast<std::uint64_t>(f.num) : static_cast<std::uint64_t>(f.num);
    if (f.den <= 0 || std::gcd(magnitude, static_cast<std::uint64_t>(f.den)) != 1)
      fuzz::finding("parse_parameter(\"" + text + "\") gave " + std::to_string(f.num) + "/" + std::to_string(f.den) +
                    ", not a reduced fraction with a positive denominator");
  });
  return 0;
}
