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
  // Per step: how many times smaller its children are across (2 for the
  // 1-to-4 splits, 3 for two sqrt(3) steps, which split each face in 9).
  std::vector<int> step_scales;
  std::vector<int> original_sizes;  // corner count of each original face

  // Records one step that split every face of the mesh into `children` faces
  // `scale` times smaller across: face f became faces children*f .. of `refined`.
  void add_uniform_step(Mesh refined, std::size_t children, int scale) {
    std::vector<std::size_t> offsets(mesh.face_count() + 1);
    for (std::size_t f = 0; f < offsets.size(); ++f) offsets[f] = children * f;
    add_step(std::move(refined), std::move(offsets), scale);
  }
  void add_four_way_step(Mesh refined) { add_uniform_step(std::move(refined), 4, 2); }
  void add_step(Mesh refined, std::vector<std::size_t> offsets, int scale) {
    child_offsets.push_back(std::move(offsets));
    step_scales.push_back(scale);
    mesh = std::move(refined);
    ++steps;
  }
};

// A parameter of a prepared face: grid indices (i/n, j/n) on the same n as the
// original face's.
struct FaceParameter {
  std::size_t face;
  long i, j;
};

// Valences above 64 are refused (the tessellation's vertex polygon holds 64 corners).
inline void check_valence_limit(std::size_t vertex, int valence) {
  if (valence > 64)
    throw MeshError("vertex " + std::to_string(vertex) + " has valence " + std::to_string(valence) +
                    "; the runtime supports valences up to 64");
}

// The error for a vertex whose valence the tables do not cover, with the
// stencilgen call that adds it.
inline MeshError missing_valence_error(std::size_t vertex, int valence, const std::string& scheme_name) {
  return MeshError("vertex " + std::to_string(vertex) + " has valence " + std::to_string(valence) +
                   ", which the tables do not cover; generate it with: stencilgen --scheme " + scheme_name +
                   " --valence " + std::to_string(valence) + " --n <rates> --out <dir>");
}

}  // namespace stencil_runtime
