// Fuzz target: PLY control meshes (stencil_runtime::read_ply_mesh, whose
// reader the PLY points files share), and the mesh they give through
// stenciltess's path (runtime_use.hpp).
#include "fuzz_support.hpp"
#include "runtime_use.hpp"
#include "stencil_runtime/mesh_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = fuzz::write_scratch_file("input.ply", fuzz::as_text(data, size));
  fuzz::run_expecting_errors([&] { fuzz::use_mesh(stencil_runtime::read_ply_mesh(path)); });
  return 0;
}
