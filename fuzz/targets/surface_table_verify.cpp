// Fuzz target: exact quad surface tables as `stencilgen verify` checks them
// (sg::verify_quad_table against the bundled nonpoly scheme). verify
// re-solves the patch at the table's own valence and rate, which takes as
// long as generating it; inputs whose "valence" exceeds 6 or whose "n"
// exceeds 3 are skipped, so that the fuzzer spends its time on the reader
// rather than on legitimately long solves.
#include <nlohmann/json.hpp>

#include "fuzz_support.hpp"
#include "common/table_document.hpp"
#include "quad/quad_scheme_loader.hpp"
#include "quad/quad_table_verify.hpp"

namespace {

// Adapter: the entry point under test.
void verify(const std::string& text, const sg::QuadScheme& scheme) {
  sg::verify_quad_table(sg::parse_table_document(text, "fuzzed.json"), scheme);
}

bool cheap_to_verify(const std::string& text) {
  const nlohmann::ordered_json doc = nlohmann::ordered_json::parse(text, nullptr, false);  // as verify parses it
  if (!doc.is_object()) return true;  // refused before any solving
  auto within = [&](const char* key, long limit) {
    const auto it = doc.find(key);
    return it == doc.end() || !it->is_number() || it->get<double>() <= static_cast<double>(limit);
  };
  return within("valence", 6) && within("n", 3);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const sg::QuadScheme scheme = [] {
    try {
      return sg::load_quad_scheme("nonpoly", {}, fuzz::source_dir() / "schemes");
    } catch (const std::exception& e) {
      fuzz::harness_failure(e.what());
    }
  }();
  const std::string text(fuzz::as_text(data, size));
  if (!cheap_to_verify(text)) return 0;
  fuzz::run_expecting_errors([&] { verify(text, scheme); });
  return 0;
}
