#include "stencil_runtime/triangle_tessellation.hpp"

#include <stdexcept>

#include "tessellation_parts.hpp"

namespace stencil_runtime {

namespace {

// The row of centres along a face's edge k (corner k -> k+1) at rate n, in the
// edge's direction: U(t), t = 0..n-1, the up centres of the small triangles
// on the edge, and D(t), t = 0..n-2, the down centre between U(t) and U(t+1)
// (its corner is the edge's grid node t+1). Indices among the face's centres.
inline int row_up(int k, int t, int n) {
  switch (k) {
    case 0: return up_centre_index(t, 0, n);
    case 1: return up_centre_index(n - 1 - t, t, n);
    default: return up_centre_index(0, n - 1 - t, n);
  }
}
inline int row_down(int k, int t, int n) {
  switch (k) {
    case 0: return down_centre_index(t, 0, n);
    case 1: return down_centre_index(n - 2 - t, t, n);
    default: return down_centre_index(0, n - 2 - t, n);
  }
}

}  // namespace

PolygonSoup tessellate(const TriangleSurface& surface, const std::vector<int>& rates, const TessellationOptions& options) {
  PolygonSoup soup;
  tessellate_into(surface, rates, soup, options);
  return soup;
}

void tessellate_into(const TriangleSurface& surface, const std::vector<int>& rates, PolygonSoup& soup,
                     const TessellationOptions& options) {
  const TriangleTopology& topo = surface.topology();
  const std::size_t nf = topo.faces();
  detail::check_rates(rates, nf, surface.tables());

  // Counts and offsets (serial, O(faces)). Per face: n^2 points, two quads per
  // interior node ((n-1)(n-2)/2 of them), one triangle per boundary node
  // (3(n-1)); then the zippers and vertex polygons.
  std::vector<std::size_t> point_offset(nf + 1, 0), face_quads(nf + 1, 0), face_triangles(nf + 1, 0);
  for (std::size_t f = 0; f < nf; ++f) {
    const std::size_t n = static_cast<std::size_t>(rates[f]);
    point_offset[f + 1] = point_offset[f] + n * n;
    face_quads[f + 1] = face_quads[f] + (n - 1) * (n >= 2 ? n - 2 : 0);
    face_triangles[f + 1] = face_triangles[f] + 3 * (n - 1);
  }
  const detail::SeamPolygons<3> seams(topo, rates);
  const std::size_t inner_quads = face_quads[nf], inner_triangles = face_triangles[nf];
  soup.positions.resize(point_offset[nf]);
  soup.quads.resize(inner_quads + seams.quads());
  soup.triangles.resize(inner_triangles + seams.triangles());

  const detail::RangeRunner for_range(options.threads, point_offset[nf]);
  // Faces: the centres, the hexagons round interior nodes, the triangles round boundary nodes.
  for_range(nf, [&](std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f != end; ++f) {
      const int n = rates[f];
      surface.evaluate_centres(f, n, soup.positions.data() + point_offset[f]);
      const int base = static_cast<int>(point_offset[f]);
      auto up = [&](int i, int j) { return base + up_centre_index(i, j, n); };
      auto down = [&](int i, int j) { return base + down_centre_index(i, j, n); };
      std::array<int, 4>* q = soup.quads.data() + face_quads[f];
      for (int j = 1; j < n; ++j)
        for (int i = 1; i + j <= n - 1; ++i) {
          // Counter-clockwise round node (i, j).
          const int h[6] = {up(i, j), down(i - 1, j), up(i - 1, j), down(i - 1, j - 1), up(i, j - 1), down(i, j - 1)};
          *q++ = {h[0], h[1], h[2], h[3]};
          *q++ = {h[3], h[4], h[5], h[0]};
        }
      std::array<int, 3>* t = soup.triangles.data() + face_triangles[f];
      for (int k = 0; k < 3; ++k)
        for (int s = 0; s + 1 < n; ++s) *t++ = {base + row_up(k, s, n), base + row_up(k, s + 1, n), base + row_down(k, s, n)};
    }
  });
  // Edges: the zipper between the two faces' rows of up centres; vertices: the polygon of the corner centres.
  for_range(seams.half_edges(), [&](std::size_t begin, std::size_t end) {
    seams.edges(begin, end, point_offset, row_up, soup.quads.data() + inner_quads, soup.triangles.data() + inner_triangles);
  });
  for_range(topo.vertices(), [&](std::size_t begin, std::size_t end) {
    seams.vertices(begin, end, point_offset, row_up, soup.quads.data() + inner_quads, soup.triangles.data() + inner_triangles);
  });
}

}  // namespace stencil_runtime
