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
  std::vector<char> non_manifold;    // Fans::Any only, per half-edge: its edge is in three faces or more, or used
                                     // twice in one direction (it has no twin, and is not a boundary)
  bool has_boundary = false;
};

// Whether every vertex must be in exactly one fan of faces (what the families
// subdivide), or may be in none or several (a mesh as a modeller saved it,
// before mesh/manifold_input.hpp splits it).
enum class Fans { One, Any };

// Throws MeshError naming the face, edge or vertex for a face with fewer than
// three vertices, an index that names no vertex, a face that repeats a vertex,
// a valence over limits::kMaxValence, a boundary edge (unless `boundaries`
// allows them), and with Fans::One an edge used twice in the same direction
// (or in more than two faces), a vertex in no face or a vertex whose faces form
// more than one fan (for a boundary vertex: one open fan, from its outgoing
// boundary edge to its incoming one). Face sizes must add up to the number of
// face-vertex indices (checked). With Fans::Any, `boundary` marks the vertices
// with a boundary edge out, and `non_manifold` the half-edges of non-manifold
// edges.
PolygonLinks link_polygons(const Connectivity& mesh, bool boundaries = false, Fans fans = Fans::One);

}  // namespace stencil_runtime
