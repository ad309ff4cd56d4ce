// The quad family's share of the watertight tessellation (tessellation.hpp):
// n^2 cell centres per prepared face at its rate n, (n-1)^2 quads between
// them, and the rows of centres along each edge for the shared seams; where
// the surface ends (boundary, holes) the grid nodes of the face's edge.
#include <string>

#include "family/seam_polygons.hpp"
#include "family/stencil_sum.hpp"
#include "quad_family.hpp"

namespace stencil_runtime {

namespace {

// Grid index of the centre at position t (0..n-1, in the half-edge's direction)
// of the row of face cells along the face's edge k (corner k -> k+1).
inline int row_cell(int k, int t, int n) {
  switch (k & 3) {
    case 0: return t;                            // j = 0, i = t
    case 1: return t * n + (n - 1);              // i = n-1, j = t
    case 2: return (n - 1) * n + (n - 1 - t);    // j = n-1, i = n-1-t
    default: return (n - 1 - t) * n;             // i = 0, j = n-1-t
  }
}

}  // namespace

void QuadFamily::plan(TessellationLayout& layout, const detail::RangeRunner& run) const {
  const std::size_t nf = topology_.faces();
  const std::vector<int>& rates = layout.rates;
  // Counts and offsets (serial, O(faces)): points and interior quads per face,
  // then the zippers and vertex polygons.
  std::vector<std::size_t> interior_offset(nf + 1, 0);
  layout.point_offsets.assign(nf + 1, 0);
  auto hole = [&](std::size_t f) { return !layout.holes.empty() && layout.holes[f] != 0; };
  for (std::size_t f = 0; f < nf; ++f) {
    const auto n = hole(f) ? 0 : static_cast<std::size_t>(rates[f]);
    layout.point_offsets[f + 1] = layout.point_offsets[f] + n * n;
    interior_offset[f + 1] = interior_offset[f] + (n == 0 ? 0 : (n - 1) * (n - 1));
  }
  const detail::SeamPolygons<4> seams(topology_, rates, layout.holes);
  seams.check_points(layout.point_offsets[nf]);
  layout.rim = seams.rim_nodes(layout.point_offsets, row_cell);
  const std::size_t interior_quads = interior_offset[nf];
  layout.quads.resize(interior_quads + seams.quads());
  layout.triangles.resize(seams.triangles());
  run(nf, [&](std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f != end; ++f) {
      if (hole(f)) continue;
      const int n = rates[f];
      const int base = static_cast<int>(layout.point_offsets[f]);
      std::array<int, 4>* q = layout.quads.data() + interior_offset[f];
      for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i)
          *q++ = {base + j * n + i, base + j * n + i + 1, base + (j + 1) * n + i + 1, base + (j + 1) * n + i};
    }
  });
  // Edges: the zipper between the two faces' rows of centres; vertices: the polygon of the corner centres.
  run(seams.half_edges(), [&](std::size_t begin, std::size_t end) {
    seams.edges(begin, end, layout.point_offsets, row_cell, layout.quads.data() + interior_quads, layout.triangles.data());
  });
  run(topology_.vertices(), [&](std::size_t begin, std::size_t end) {
    seams.vertices(begin, end, layout.point_offsets, row_cell, layout.quads.data() + interior_quads, layout.triangles.data());
  });
}

namespace {

// Grid node t (0..n, in the edge's direction) of the face's edge k, as (i, j): the face's node (i/n, j/n).
inline void edge_grid_node(int k, int t, int n, long& i, long& j) {
  switch (k & 3) {
    case 0: i = t, j = 0; break;
    case 1: i = n, j = t; break;
    case 2: i = n - t, j = n; break;
    default: i = 0, j = n - t; break;
  }
}

}  // namespace

Point QuadFamily::edge_node(std::size_t face, int corner, int t, int n, const Point* prepared) const {
  const QuadPatch& p = patches_[face];
  long i = 0, j = 0, pi = 0, pj = 0;
  edge_grid_node(corner, t, n, i, j);
  if (refined(face)) return refined_point(face, 2 * i, 2 * j, n, prepared);
  p.to_patch(i, j, n, pi, pj);
  std::array<double, limits::kMaxPatchPoints> w{};
  tables_.node_stencil(p.valence, n, static_cast<int>(pi), static_cast<int>(pj), w.data());
  return stencil_sum(w.data(), p.points.data(), p.points.size(), prepared);
}

std::array<double, 2> QuadFamily::edge_node_parameter(std::size_t face, int corner, int t, int n) const {
  long i = 0, j = 0, pi = 0, pj = 0;
  edge_grid_node(corner, t, n, i, j);
  patches_[face].to_patch(i, j, n, pi, pj);
  return {static_cast<double>(pi) / n, static_cast<double>(pj) / n};
}

}  // namespace stencil_runtime
