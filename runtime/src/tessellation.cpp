#include "stencil_runtime/tessellation.hpp"

#include <algorithm>
#include <stdexcept>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

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

struct Counts {
  std::size_t quads = 0, triangles = 0;
};

// The zipper between two rows along one edge, both given in the edge's
// direction: A on the left (face f), B on the right (face g).
template <class EmitQuad, class EmitTri>
void zipper(int na, int nb, const EmitQuad& quad, const EmitTri& tri) {
  if (na == nb) {
    for (int t = 0; t + 1 < na; ++t) quad(t, t);
    return;
  }
  int a = 0, b = 0;
  while (a + 1 < na || b + 1 < nb) {
    // Advance the row whose next point comes first along the edge:
    // compare (a + 1.5)/na with (b + 1.5)/nb exactly.
    const bool advance_a = b + 1 >= nb || (a + 1 < na && (2 * a + 3) * nb <= (2 * b + 3) * na);
    if (advance_a) {
      tri(a, b, true);
      ++a;
    } else {
      tri(a, b, false);
      ++b;
    }
  }
}

}  // namespace

int table_rate_at_least(const SurfaceTables& tables, int wanted) {
  int best = tables.rates().back();
  for (int n : tables.rates())
    if (n >= wanted) return n;
  return best;
}

std::vector<int> prepared_rates(const LimitSurface& surface, const std::vector<int>& original) {
  if (original.size() != surface.original_faces())
    throw std::invalid_argument("need one rate per face: got " + std::to_string(original.size()) + " for " +
                                std::to_string(surface.original_faces()) + " faces");
  const int steps = surface.prepared().steps;
  const std::size_t per = std::size_t(1) << (2 * steps);
  std::vector<int> out(original.size() * per);
  for (std::size_t f = 0; f < original.size(); ++f) {
    if (original[f] < 1) throw std::invalid_argument("face " + std::to_string(f) + ": rate must be at least 1");
    const int r = std::max(1, (original[f] + (1 << steps) - 1) >> steps);
    for (std::size_t c = 0; c < per; ++c) out[f * per + c] = r;
  }
  return out;
}

PolygonSoup tessellate(const LimitSurface& surface, const std::vector<int>& rates, const TessellationOptions& options) {
  const Mesh& mesh = surface.prepared().mesh;
  const QuadTopology topo(mesh);
  const std::size_t nf = topo.faces();
  if (rates.size() != nf) throw std::invalid_argument("need one rate per prepared face");
  const SurfaceTables& tables = surface.tables();
  for (std::size_t f = 0; f < nf; ++f)
    if (!tables.has_rate(rates[f]))
      throw std::out_of_range("face " + std::to_string(f) + ": rate " + std::to_string(rates[f]) + " is not in the tables");

  // Offsets: points and interior quads per face; strip polygons per edge
  // (owned by the half-edge with the smaller index); polygons per vertex.
  std::vector<std::size_t> point_offset(nf + 1, 0), quad_offset(nf + 1, 0);
  for (std::size_t f = 0; f < nf; ++f) {
    const std::size_t n = static_cast<std::size_t>(rates[f]);
    point_offset[f + 1] = point_offset[f] + n * n;
    quad_offset[f + 1] = quad_offset[f] + (n - 1) * (n - 1);
  }
  PolygonSoup soup;
  soup.positions.resize(point_offset[nf]);
  std::vector<std::array<int, 4>> interior(quad_offset[nf]);

  tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                            options.threads > 0 ? static_cast<std::size_t>(options.threads)
                                                : tbb::this_task_arena::max_concurrency());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nf), [&](const tbb::blocked_range<std::size_t>& range) {
    std::vector<double> w(2 * 64 + 8);
    for (std::size_t f = range.begin(); f != range.end(); ++f) {
      const int n = rates[f];
      std::array<float, 3>* out = soup.positions.data() + point_offset[f];
      surface.evaluate_centres(f, n, out, w.data());
      const int base = static_cast<int>(point_offset[f]);
      std::array<int, 4>* q = interior.data() + quad_offset[f];
      for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i)
          *q++ = {base + j * n + i, base + j * n + i + 1, base + (j + 1) * n + i + 1, base + (j + 1) * n + i};
    }
  });

  // Edge zippers and vertex polygons (cheap; serial).
  soup.quads = std::move(interior);
  for (std::uint32_t h = 0; h < 4 * nf; ++h) {
    const std::uint32_t o = topo.twin(h);
    if (o < h) continue;
    const std::size_t f = QuadTopology::face_of(h), g = QuadTopology::face_of(o);
    const int kf = QuadTopology::corner_of(h), kg = QuadTopology::corner_of(o);
    const int na = rates[f], nb = rates[g];
    const int fa = static_cast<int>(point_offset[f]), gb = static_cast<int>(point_offset[g]);
    auto A = [&](int t) { return fa + row_cell(kf, t, na); };
    auto B = [&](int t) { return gb + row_cell(kg, nb - 1 - t, nb); };  // g's row reversed into f's direction
    zipper(
        na, nb, [&](int a, int b) { soup.quads.push_back({B(b), B(b + 1), A(a + 1), A(a)}); },
        [&](int a, int b, bool advance_a) {
          if (advance_a) soup.triangles.push_back({B(b), A(a + 1), A(a)});
          else soup.triangles.push_back({B(b), B(b + 1), A(a)});
        });
  }
  std::vector<char> done(topo.vertices(), 0);
  std::vector<int> ring;
  for (std::uint32_t h = 0; h < 4 * nf; ++h) {
    const std::size_t f0 = QuadTopology::face_of(h);
    const int v = topo.vertex(f0, QuadTopology::corner_of(h));
    if (done[static_cast<std::size_t>(v)]) continue;
    done[static_cast<std::size_t>(v)] = 1;
    ring.clear();
    std::uint32_t e = h;
    do {
      const std::size_t f = QuadTopology::face_of(e);
      const int c = QuadTopology::corner_of(e);
      ring.push_back(static_cast<int>(point_offset[f]) + corner_cell(c, rates[f]));
      e = topo.twin(QuadTopology::half_edge(f, c + 3));
    } while (e != h);
    if (ring.size() == 4) soup.quads.push_back({ring[0], ring[1], ring[2], ring[3]});
    else
      for (std::size_t k = 1; k + 1 < ring.size(); ++k) soup.triangles.push_back({ring[0], ring[k], ring[k + 1]});
  }
  return soup;
}

}  // namespace stencil_runtime
