// Fuzz target: stenciltess --rates files (stencil_tools::rates_from_file), for
// a mesh with as many faces as the input has lines; a result must hold one
// rate per face, each in 1..4096 as documented.
#include <algorithm>

#include "fuzz_support.hpp"
#include "rate_choice.hpp"

namespace {

// Adapter: the entry point under test.
std::vector<int> parse(const std::string& path, std::size_t faces) { return stencil_tools::rates_from_file(path, faces); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = fuzz::as_text(data, size);
  const auto faces = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
  const std::string path = fuzz::write_scratch_file("rates.txt", text);
  fuzz::run_expecting_errors([&] {
    const std::vector<int> rates = parse(path, faces);
    if (rates.size() != faces || std::any_of(rates.begin(), rates.end(), [](int r) { return r < 1 || r > 4096; }))
      fuzz::finding("rates_from_file accepted a rate list that is not one rate in 1..4096 per face");
  });
  return 0;
}
