#pragma once
// The half-edges of a closed manifold polygon mesh: half-edge h is corner h of
// the concatenated face-vertex list, running from its vertex to the next
// corner's. Shared by the uniform topologies and the polygon subdivision step.
#include <cstddef>
#include <vector>

#include "connectivity.hpp"
#include "stencil_runtime/error.hpp"

namespace stencil_runtime {

struct PolygonLinks {
  std::vector<std::size_t> start;    // first half-edge of each face (size faces + 1)
  std::vector<std::size_t> next;     // the next half-edge in the same face
  std::vector<std::size_t> face_of;  // the face of each half-edge
  std::vector<std::size_t> twin;     // the opposite half-edge (same edge, other face)
  std::vector<int> valence;          // per vertex: its number of edges
};

// Throws MeshError naming the face, edge or vertex for a face with fewer than
// three vertices, an index that names no vertex, a face that repeats a vertex,
// an edge used twice in the same direction, a boundary edge, a vertex in no
// face, or a vertex whose faces form more than one fan. Face sizes must add up
// to the number of face-vertex indices (checked).
PolygonLinks link_polygons(const Connectivity& mesh);

}  // namespace stencil_runtime
