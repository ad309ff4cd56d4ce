// Fuzz target: exact curve tables as `stencilgen verify` reads them
// (sg::parse_table_document, then sg::curve_table_from_json).
#include "fuzz_support.hpp"
#include "common/table_document.hpp"
#include "curve/curve_table_json.hpp"

namespace {

// Adapter: the entry points under test.
void parse(const std::string& text) {
  sg::parse_table_document(text, "fuzzed.json");
  sg::curve_table_from_json(text, "fuzzed.json");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(fuzz::as_text(data, size));
  fuzz::run_expecting_errors([&] { parse(text); });
  return 0;
}
