// Fuzz target: Wavefront OBJ control meshes (stencil_runtime::read_obj), and
// the mesh they give through stenciltess's path (runtime_use.hpp).
#include "fuzz_support.hpp"
#include "runtime_use.hpp"
#include "stencil_runtime/mesh_io.hpp"

namespace {

// Adapter: the entry point under test.
stencil_runtime::Mesh parse(const std::string& path) { return stencil_runtime::read_obj(path); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = fuzz::write_scratch_file("input.obj", fuzz::as_text(data, size));
  fuzz::run_expecting_errors([&] { fuzz::use_mesh(parse(path)); });
  return 0;
}
