// Fuzz targets expression and expression_real: the scheme files' formula
// language (sg::evaluate_expression, exact; sg::evaluate_expression_real, high
// precision, with FUZZ_REAL_EXPRESSION set in fuzz/CMakeLists.txt), with the
// bindings a scheme file's formulas see: a valence v and a parameter w.
#include "algebra/expression.hpp"
#include "fuzz_support.hpp"

namespace {

// Adapter: the entry point under test.
void evaluate(std::string_view text, const sg::Bindings& bindings) {
#ifdef FUZZ_REAL_EXPRESSION
  sg::evaluate_expression_real(text, bindings);
#else
  sg::evaluate_expression(text, bindings);
#endif
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const sg::Bindings bindings{{"v", sg::Rational(5)}, {"w", sg::Rational(1, 16)}};
  fuzz::run_expecting_errors([&] { evaluate(fuzz::as_text(data, size), bindings); });
  return 0;
}
