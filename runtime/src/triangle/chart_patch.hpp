#pragma once
// The patch of one face of a prepared triangle mesh: which valence's table and
// region evaluate it (valence 6: regular; region 0: the EV's own patch, 1..3:
// sqrt(3)'s band in the EV's second ring), the face corner that sits at the
// region's corner 0, and the mesh vertices that are its control points, one per
// point of the region's layout (tables/triangle_tables.hpp).
#include <optional>
#include <string>
#include <vector>

#include "mesh/uniform_topology.hpp"
#include "stencil_runtime/exact_parameter.hpp"
#include "tables/triangle_tables.hpp"

namespace stencil_runtime {

struct TrianglePatch {
  int valence = 6;
  int region = 0;
  int rotation = 0;  // face corner at the region's corner 0; its u runs to corner rotation+1, v to rotation+2
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
  // The same for an exact parameter.
  ExactParameter to_patch(const ExactParameter& p) const {
    const Fraction w = subtract(subtract(Fraction{1, 1}, p.u), p.v);
    switch (rotation) {
      case 0: return p;
      case 1: return {p.v, w};
      default: return {w, p.u};
    }
  }
};

// The vertex at chart point p of the chart whose origin is the start of
// half-edge e_0 and whose edge e_0 is that half-edge (sector 0 is the face of
// e_0): from the origin along the edge to e_{p.sector}, a - b steps straight
// on, then b steps after a 60-degree left turn; where that path passes a vertex
// of valence other than 6, the other side of the parallelogram (b steps towards
// e_{p.sector+1}, then a - b after a right turn). nullopt when both do (the
// lattice frame does not reach that far).
std::optional<int> chart_vertex(const TriangleTopology& topology, std::uint32_t e_0, const ChartPoint& p);
// The same with the chart's origin at corner `corner` of face f (e_0 = corner + 1, e_1 = corner + 2).
inline std::optional<int> chart_vertex(const TriangleTopology& topology, std::size_t f, int corner, const ChartPoint& p) {
  return chart_vertex(topology, TriangleTopology::half_edge(f, corner), p);
}

// The face's patch, or nullopt when the mesh is not isolated enough there: two
// corners of valence other than 6; with band regions (sqrt(3)), more than one
// extraordinary vertex on or next to the face's corners; or a layout point the
// walks cannot reach (another extraordinary vertex in the way).
//   A face with an extraordinary corner takes its valence's region 0 (rotation:
//   that corner). A face next to an extraordinary vertex X whose valence has
//   band regions takes the band region its corners form round X. Any other face
//   is regular: the first rotation whose layout walks all succeed.
std::optional<TrianglePatch> find_triangle_patch(const TriangleTopology& topology, std::size_t face, const TriangleTables& tables);

}  // namespace stencil_runtime
