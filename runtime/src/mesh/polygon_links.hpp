#pragma once
// The half-edges of a manifold polygon mesh, closed or (where allowed) with
// boundaries: half-edge h is corner h of the concatenated face-vertex list,
// running from its vertex to the next corner's. Shared by the uniform
// topologies and the polygon subdivision step.
#include <cstddef>
#include <vector>

#include "connectivity.hpp"
#include "stencil_runtime/error.hpp"

namespace stencil_runtime {

struct PolygonLinks {
  static constexpr std::size_t kNoTwin = static_cast<std::size_t>(-1);  // a boundary half-edge
  std::vector<std::size_t> start;    // first half-edge of each face (size faces + 1)
  std::vector<std::size_t> next;     // the next half-edge in the same face
  std::vector<std::size_t> face_of;  // the face of each half-edge
  std::vector<std::size_t> twin;     // the opposite half-edge (same edge, other face), or kNoTwin
  std::vector<int> valence;          // per vertex: its number of faces (closed: also of edges)
  std::vector<char> boundary;        // per vertex: on the boundary (one more edge than faces)
  bool has_boundary = false;
};

// Throws MeshError naming the face, edge or vertex for a face with fewer than
// three vertices, an index that names no vertex, a face that repeats a vertex,
// an edge used twice in the same direction, a boundary edge (unless
// `boundaries` allows them), a vertex in no face, or a vertex whose faces form
// more than one fan (for a boundary vertex: one open fan, from its outgoing
// boundary edge to its incoming one). Face sizes must add up to the number of
// face-vertex indices (checked).
PolygonLinks link_polygons(const Connectivity& mesh, bool boundaries = false);

}  // namespace stencil_runtime
