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

inline int corner_cell(int c, int n) { return row_cell(c, 0, n); }

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
  // Each step halves the faces: children get ceil(rate / 2).
  std::vector<int> rates = original;
  for (const auto& offsets : prepared.child_offsets) {
    std::vector<int> next(offsets.back());
    for (std::size_t f = 0; f + 1 < offsets.size(); ++f)
      for (std::size_t c = offsets[f]; c < offsets[f + 1]; ++c) next[c] = std::max(1, (rates[f] + 1) / 2);
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
  const std::size_t nf = topo.faces(), nh = 4 * nf, nv = topo.vertices();
  if (rates.size() != nf) throw std::invalid_argument("need one rate per prepared face");
  const SurfaceTables& tables = surface.tables();
  for (std::size_t f = 0; f < nf; ++f)
    if (!tables.has_rate(rates[f]))
      throw std::out_of_range("face " + std::to_string(f) + ": rate " + std::to_string(rates[f]) + " is not in the tables");

  // Counts and offsets (serial, O(faces)): points and interior quads per face;
  // the zipper of each edge (owned by its smaller half-edge) and the polygon of
  // each vertex (owned by its first outgoing half-edge in face order).
  std::vector<std::size_t> point_offset(nf + 1, 0), quad_offset(nh + nv + 1, 0), tri_offset(nh + nv + 1, 0);
  std::vector<std::uint32_t> vertex_owner(nv, UINT32_MAX);
  for (std::uint32_t h = 0; h < nh; ++h) {
    const int v = topo.vertex(QuadTopology::face_of(h), QuadTopology::corner_of(h));
    if (vertex_owner[static_cast<std::size_t>(v)] == UINT32_MAX) vertex_owner[static_cast<std::size_t>(v)] = h;
  }
  // Slots: [0, nf) interior quads per face (in quad_offset), then per half-edge, then per vertex.
  std::vector<std::size_t> interior_offset(nf + 1, 0);
  for (std::size_t f = 0; f < nf; ++f) {
    const std::size_t n = static_cast<std::size_t>(rates[f]);
    point_offset[f + 1] = point_offset[f] + n * n;
    interior_offset[f + 1] = interior_offset[f] + (n - 1) * (n - 1);
  }
  for (std::uint32_t h = 0; h < nh; ++h) {
    std::size_t q = 0, t = 0;
    const std::uint32_t o = topo.twin(h);
    if (h < o) {
      const std::size_t na = static_cast<std::size_t>(rates[QuadTopology::face_of(h)]);
      const std::size_t nb = static_cast<std::size_t>(rates[QuadTopology::face_of(o)]);
      if (na == nb) q = na - 1;
      else t = na + nb - 2;
    }
    quad_offset[h + 1] = quad_offset[h] + q;
    tri_offset[h + 1] = tri_offset[h] + t;
  }
  for (std::size_t v = 0; v < nv; ++v) {
    const int k = topo.valence(static_cast<int>(v));
    quad_offset[nh + v + 1] = quad_offset[nh + v] + (k == 4 ? 1 : 0);
    tri_offset[nh + v + 1] = tri_offset[nh + v] + (k == 4 ? 0 : static_cast<std::size_t>(k - 2));
  }
  const std::size_t interior_quads = interior_offset[nf];
  soup.positions.resize(point_offset[nf]);
  soup.quads.resize(interior_quads + quad_offset[nh + nv]);
  soup.triangles.resize(tri_offset[nh + nv]);

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
  // Edges: the zipper between the two faces' rows of centres.
  for_range(nh, [&](std::size_t begin, std::size_t end) {
    for (std::uint32_t h = static_cast<std::uint32_t>(begin); h != end; ++h) {
      const std::uint32_t o = topo.twin(h);
      if (o < h) continue;
      const std::size_t f = QuadTopology::face_of(h), g = QuadTopology::face_of(o);
      const int kf = QuadTopology::corner_of(h), kg = QuadTopology::corner_of(o);
      const int na = rates[f], nb = rates[g];
      const int fa = static_cast<int>(point_offset[f]), gb = static_cast<int>(point_offset[g]);
      auto A = [&](int t) { return fa + row_cell(kf, t, na); };
      auto B = [&](int t) { return gb + row_cell(kg, nb - 1 - t, nb); };  // g's row, in f's direction
      std::array<int, 4>* q = soup.quads.data() + interior_quads + quad_offset[h];
      std::array<int, 3>* t = soup.triangles.data() + tri_offset[h];
      detail::zipper(
          na, nb, [&](int a, int b) { *q++ = {B(b), B(b + 1), A(a + 1), A(a)}; },
          [&](int a, int b, bool advance_a) {
            if (advance_a) *t++ = {B(b), A(a + 1), A(a)};
            else *t++ = {B(b), B(b + 1), A(a)};
          });
    }
  });
  // Vertices: the polygon of the corner centres around each mesh vertex.
  for_range(nv, [&](std::size_t begin, std::size_t end) {
    int ring[64];
    for (std::size_t v = begin; v != end; ++v) {
      const std::uint32_t h = vertex_owner[v];
      int k = 0;
      std::uint32_t e = h;
      do {
        const std::size_t f = QuadTopology::face_of(e);
        const int c = QuadTopology::corner_of(e);
        ring[k++] = static_cast<int>(point_offset[f]) + corner_cell(c, rates[f]);
        e = topo.twin(QuadTopology::half_edge(f, c + 3));
      } while (e != h && k < 64);
      if (k == 4) {
        soup.quads[interior_quads + quad_offset[nh + v]] = {ring[0], ring[1], ring[2], ring[3]};
      } else {
        std::array<int, 3>* t = soup.triangles.data() + tri_offset[nh + v];
        for (int i = 1; i + 1 < k; ++i) *t++ = {ring[0], ring[i], ring[i + 1]};
      }
    }
  });
}

}  // namespace stencil_runtime
