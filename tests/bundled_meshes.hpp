#pragma once
// The meshes bundled in meshes/, for the tests: their folder, the triangle
// ones, and a reader by name.
#include <filesystem>
#include <string>

#include "stencil_runtime/mesh.hpp"
#include "stencil_runtime/mesh_io.hpp"

namespace test_meshes {

inline const std::filesystem::path kMeshes = std::filesystem::path(STENCIL_SOURCE_DIR) / "meshes";

// The bundled closed triangle meshes (Loop and sqrt(3) evaluate them).
inline const char* const kTriangleMeshes[] = {"icosahedron", "tri-torus", "tri-mix"};

// meshes/<name>.obj
inline stencil_runtime::Mesh bundled(const std::string& name) {
  return stencil_runtime::read_obj((kMeshes / (name + ".obj")).string());
}

}  // namespace test_meshes
