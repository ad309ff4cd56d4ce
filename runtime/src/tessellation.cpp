#include "stencil_runtime/tessellation.hpp"

#include <algorithm>
#include <stdexcept>

#include "tessellation_parts.hpp"

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

int table_rate_at_least(const std::vector<int>& table_rates, int wanted) {
  for (int n : table_rates)
    if (n >= wanted) return n;
  return table_rates.back();
}

std::vector<int> prepared_rates(const PreparedMesh& prepared, const std::vector<int>& original) {
  if (original.size() != prepared.original_sizes.size())
    throw std::invalid_argument("need one rate per face: got " + std::to_string(original.size()) + " for " +
                                std::to_string(prepared.original_sizes.size()) + " faces");
  for (std::size_t f = 0; f < original.size(); ++f)
    if (original[f] < 1) throw std::invalid_argument("face " + std::to_string(f) + ": rate must be at least 1");
  // A step whose children are s times smaller across gives them ceil(rate / s).
  std::vector<int> rates = original;
  for (std::size_t s = 0; s < prepared.child_offsets.size(); ++s) {
    const auto& offsets = prepared.child_offsets[s];
    const int scale = prepared.step_scales[s];
    std::vector<int> next(offsets.back());
    for (std::size_t f = 0; f + 1 < offsets.size(); ++f)
      for (std::size_t c = offsets[f]; c < offsets[f + 1]; ++c) next[c] = std::max(1, (rates[f] + scale - 1) / scale);
    rates = std::move(next);
  }
  return rates;
}

PolygonSoup tessellate(const LimitSurface& surface, const std::vector<int>& rates, const TessellationOptions& options) {
  PolygonSoup soup;
  tessellate_into(surface, rates, soup, options);
  return soup;
}

void tessellate_into(const LimitSurface& surface, const std::vector<int>& rates, PolygonSoup& soup,
                     const TessellationOptions& options) {
  const QuadTopology& topo = surface.topology();
  const std::size_t nf = topo.faces();
  detail::check_rates(rates, nf, surface.tables());

  // Counts and offsets (serial, O(faces)): points and interior quads per face,
  // then the zippers and vertex polygons.
  std::vector<std::size_t> point_offset(nf + 1, 0), interior_offset(nf + 1, 0);
  for (std::size_t f = 0; f < nf; ++f) {
    const std::size_t n = static_cast<std::size_t>(rates[f]);
    point_offset[f + 1] = point_offset[f] + n * n;
    interior_offset[f + 1] = interior_offset[f] + (n - 1) * (n - 1);
  }
  const detail::SeamPolygons<4> seams(topo, rates);
  const std::size_t interior_quads = interior_offset[nf];
  soup.positions.resize(point_offset[nf]);
  soup.quads.resize(interior_quads + seams.quads());
  soup.triangles.resize(seams.triangles());

  const detail::RangeRunner for_range(options.threads, point_offset[nf]);
  // Faces: limit points at the cell centres and the quads between them.
  for_range(nf, [&](std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f != end; ++f) {
      const int n = rates[f];
      surface.evaluate_centres(f, n, soup.positions.data() + point_offset[f]);
      const int base = static_cast<int>(point_offset[f]);
      std::array<int, 4>* q = soup.quads.data() + interior_offset[f];
      for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i)
          *q++ = {base + j * n + i, base + j * n + i + 1, base + (j + 1) * n + i + 1, base + (j + 1) * n + i};
    }
  });
  // Edges: the zipper between the two faces' rows of centres; vertices: the polygon of the corner centres.
  for_range(seams.half_edges(), [&](std::size_t begin, std::size_t end) {
    seams.edges(begin, end, point_offset, row_cell, soup.quads.data() + interior_quads, soup.triangles.data());
  });
  for_range(topo.vertices(), [&](std::size_t begin, std::size_t end) {
    seams.vertices(begin, end, point_offset, row_cell, soup.quads.data() + interior_quads, soup.triangles.data());
  });
}

}  // namespace stencil_runtime
