// Fuzz target: binary quad surface tables (.sgs, SurfaceTables::load), checksum
// made valid (sealed_binary.hpp), and the tables used as the tools use them.
#include "fuzz_support.hpp"
#include "runtime_use.hpp"
#include "sealed_binary.hpp"
#include "stencil_runtime/surface_table.hpp"

namespace {

// Adapter: the entry point under test.
stencil_runtime::SurfaceTables parse(const std::string& path) { return stencil_runtime::SurfaceTables::load(path); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = fuzz::write_scratch_file("input.sgs", fuzz::with_valid_checksum(fuzz::as_text(data, size)));
  fuzz::run_expecting_errors([&] { fuzz::use_quad_tables(parse(path)); });
  return 0;
}
