// Fuzz target: OFF control meshes (stencil_runtime::read_off), and the mesh
// they give through stenciltess's path (runtime_use.hpp).
#include "fuzz_support.hpp"
#include "runtime_use.hpp"
#include "stencil_runtime/mesh_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = fuzz::write_scratch_file("input.off", fuzz::as_text(data, size));
  fuzz::run_expecting_errors([&] { fuzz::use_mesh(stencil_runtime::read_off(path)); });
  return 0;
}
