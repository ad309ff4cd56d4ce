#pragma once
// The patch of one face of a prepared triangle mesh: which valence's table
// evaluates it (6: regular), the face corner that sits at the patch's EV
// corner, and the mesh vertices that are its control points, one per point of
// the table's layout (triangle_table.hpp).
#include <optional>
#include <string>
#include <vector>

#include "triangle_table.hpp"
#include "triangle_topology.hpp"

namespace stencil_runtime {

struct TrianglePatch {
  int valence = 6;
  int rotation = 0;  // face corner at patch (0,0); patch u runs to corner rotation+1, v to rotation+2
  std::vector<int> points;

  // Barycentric grid indices: face point (i/g, j/g) (u along corner 0 -> 1,
  // v along corner 0 -> 2) -> the patch's (pi/g, pj/g).
  void to_patch(long i, long j, long g, long& pi, long& pj) const {
    switch (rotation) {
      case 0: pi = i, pj = j; break;
      case 1: pi = j, pj = g - i - j; break;
      default: pi = g - i - j, pj = i; break;
    }
  }
};

// The vertex at chart point p around corner `corner` of face f, the chart's
// sector 0 being that face (e_0 = corner + 1, e_1 = corner + 2): from the
// corner along the edge to e_{p.sector}, a - b steps straight on, then b steps
// after a 60-degree left turn; where that path turns at a vertex of valence
// other than 6, the other side of the parallelogram (b steps towards
// e_{p.sector+1}, then a - b after a right turn). nullopt when both do (the
// lattice frame does not reach that far).
std::optional<int> chart_vertex(const TriangleTopology& topology, std::size_t f, int corner, const ChartPoint& p);

// Requires at most one corner of valence other than 6 on the face; throws
// MeshError naming the face when the layout cannot be walked (another
// extraordinary vertex too close: the mesh needs isolating, see prepare_triangle_mesh).
TrianglePatch gather_triangle_patch(const TriangleTopology& topology, std::size_t face, const TriangleTables& tables);

}  // namespace stencil_runtime
