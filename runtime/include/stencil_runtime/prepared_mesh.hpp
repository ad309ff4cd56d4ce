#pragma once
// A control mesh after the refinement steps that isolate its extraordinary
// vertices (quad: mesh_preparation.hpp, triangle: triangle_preparation.hpp), and
// the record that maps each original face to the faces that now cover it.
#include <cstddef>
#include <string>
#include <vector>

#include "mesh.hpp"

namespace stencil_runtime {

struct PreparedMesh {
  Mesh mesh;
  int steps = 0;  // subdivision steps applied
  // Per step: the first child of each face of the mesh before that step (size faces + 1).
  std::vector<std::vector<std::size_t>> child_offsets;
  std::vector<int> original_sizes;  // corner count of each original face
};

// A parameter of a prepared face: grid indices (i/n, j/n) on the same n as the
// original face's.
struct FaceParameter {
  std::size_t face;
  long i, j;
};

// The error for a vertex whose valence the tables do not cover, with the
// stencilgen call that adds it.
inline MeshError missing_valence_error(std::size_t vertex, int valence, const std::string& scheme_name) {
  return MeshError("vertex " + std::to_string(vertex) + " has valence " + std::to_string(valence) +
                   ", which the tables do not cover; generate it with: stencilgen --scheme " + scheme_name +
                   " --valence " + std::to_string(valence) + " --n <rates> --out <dir>");
}

}  // namespace stencil_runtime
