#pragma once
// A mesh's connectivity without positions: what topology is built from.
#include <cstddef>
#include <vector>

namespace stencil_runtime {

struct Connectivity {
  std::size_t vertex_count = 0;
  std::vector<int> face_sizes;
  std::vector<int> face_vertices;  // concatenated, counter-clockwise seen from outside
  std::size_t face_count() const { return face_sizes.size(); }
};

}  // namespace stencil_runtime
