// Fuzz targets quad_json_table and quad_json_regular: one file of an otherwise
// valid directory of exact quad JSON tables (see json_directory.hpp; the input
// may name and add other files), loaded by Tables::load
// and used as the tools use the tables. The two targets differ in the file an
// input replaces by default (FUZZ_DEFAULT_FILE, set in fuzz/CMakeLists.txt):
// the extraordinary patch table read first (v3/n1.json: the scheme hash and
// rules come from it, and valence 3's reflection) or the regular patch's
// curve table (regular/n4.json), so that each has its own corpus.
#include "fuzz_support.hpp"
#include "json_directory.hpp"
#include "runtime_use.hpp"
#include "stencil_runtime/tables.hpp"

namespace {

// Adapter: the entry point under test.
std::shared_ptr<const stencil_runtime::Tables> parse(const std::string& dir) {
  return stencil_runtime::Tables::load(dir);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string dir = fuzz::json_table_directory(fuzz::as_text(data, size), FUZZ_DEFAULT_FILE);
  fuzz::run_expecting_errors([&] { fuzz::use_tables(parse(dir)); });
  return 0;
}
