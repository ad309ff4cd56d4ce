// Fuzz target: binary quad surface tables (.sgs, Tables::load), checksum
// made valid (sealed_binary.hpp), and the tables used as the tools use them.
#include "fuzz_support.hpp"
#include "runtime_use.hpp"
#include "sealed_binary.hpp"
#include "stencil_runtime/tables.hpp"

namespace {

// Adapter: the entry point under test.
std::shared_ptr<const stencil_runtime::Tables> parse(const std::string& path) { return stencil_runtime::Tables::load(path); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = fuzz::write_scratch_file("input.sgs", fuzz::with_valid_checksum(fuzz::as_text(data, size)));
  fuzz::run_expecting_errors([&] { fuzz::use_tables(parse(path)); });
  return 0;
}
