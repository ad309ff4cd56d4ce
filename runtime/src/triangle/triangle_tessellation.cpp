// The triangle family's share of the watertight tessellation (tessellation.hpp):
// n^2 centres of the small triangles of each prepared face at its rate n, two
// quads (a hexagon) round every interior grid node, a triangle round every
// boundary node, and the rows of up centres along each edge for the seams;
// round holes the grid nodes of the face's edge.
#include <string>

#include "family/seam_polygons.hpp"
#include "family/stencil_sum.hpp"
#include "loop_split.hpp"
#include "triangle_family.hpp"

namespace stencil_runtime {

namespace {

// From this rate up, a polynomial regular patch's normals are evaluated row by
// row (face_derivative_rows.hpp): its per-face and per-row set-up costs about
// as much as the derivative stencils' sums at rate 5 (Loop: 720 + 120 n
// multiply-adds against 72 n^2, less the rows' 18 n^2).
constexpr long kRowNormalRate = 6;

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

void TriangleFamily::plan(TessellationLayout& layout, const detail::RangeRunner& run) const {
  const std::size_t nf = topology_.faces();
  const std::vector<int>& rates = layout.rates;
  // Counts and offsets (serial, O(faces)). Per face: n^2 points, two quads per
  // interior node ((n-1)(n-2)/2 of them), one triangle per boundary node
  // (3(n-1)); then the zippers and vertex polygons.
  std::vector<std::size_t> face_quads(nf + 1, 0), face_triangles(nf + 1, 0);
  layout.point_offsets.assign(nf + 1, 0);
  auto hole = [&](std::size_t f) { return !layout.holes.empty() && layout.holes[f] != 0; };
  for (std::size_t f = 0; f < nf; ++f) {
    const auto n = hole(f) ? 0 : static_cast<std::size_t>(rates[f]);  // a hole: no points, no polygons
    layout.point_offsets[f + 1] = layout.point_offsets[f] + n * n;
    face_quads[f + 1] = face_quads[f] + (n == 0 ? 0 : (n - 1) * (n >= 2 ? n - 2 : 0));
    face_triangles[f + 1] = face_triangles[f] + (n == 0 ? 0 : 3 * (n - 1));
  }
  const detail::SeamPolygons<3> seams(topology_, rates, layout.holes);
  seams.check_points(layout.point_offsets[nf]);
  layout.rim = seams.rim_nodes(layout.point_offsets, row_up);
  const std::size_t inner_quads = face_quads[nf], inner_triangles = face_triangles[nf];
  layout.quads.resize(inner_quads + seams.quads());
  layout.triangles.resize(inner_triangles + seams.triangles());
  // Faces: the hexagons round interior nodes, the triangles round boundary nodes.
  run(nf, [&](std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f != end; ++f) {
      if (hole(f)) continue;
      const int n = rates[f];
      const int base = static_cast<int>(layout.point_offsets[f]);
      auto up = [&](int i, int j) { return base + up_centre_index(i, j, n); };
      auto down = [&](int i, int j) { return base + down_centre_index(i, j, n); };
      std::array<int, 4>* q = layout.quads.data() + face_quads[f];
      for (int j = 1; j < n; ++j)
        for (int i = 1; i + j <= n - 1; ++i) {
          // Counter-clockwise round node (i, j).
          const int h[6] = {up(i, j), down(i - 1, j), up(i - 1, j), down(i - 1, j - 1), up(i, j - 1), down(i, j - 1)};
          *q++ = {h[0], h[1], h[2], h[3]};
          *q++ = {h[3], h[4], h[5], h[0]};
        }
      std::array<int, 3>* t = layout.triangles.data() + face_triangles[f];
      for (int k = 0; k < 3; ++k)
        for (int s = 0; s + 1 < n; ++s) *t++ = {base + row_up(k, s, n), base + row_up(k, s + 1, n), base + row_down(k, s, n)};
    }
  });
  // Edges: the zipper between the two faces' rows of up centres; vertices: the polygon of the corner centres.
  run(seams.half_edges(), [&](std::size_t begin, std::size_t end) {
    seams.edges(begin, end, layout.point_offsets, row_up, layout.quads.data() + inner_quads,
                layout.triangles.data() + inner_triangles);
  });
  run(topology_.vertices(), [&](std::size_t begin, std::size_t end) {
    seams.vertices(begin, end, layout.point_offsets, row_up, layout.quads.data() + inner_quads,
                   layout.triangles.data() + inner_triangles);
  });
}

void TriangleFamily::points(const TessellationLayout& layout, std::size_t begin, std::size_t end, const Point* pos,
                            std::array<float, 3>* out) const {
  samples<true, false>(layout, begin, end, pos, out, nullptr);
}

void TriangleFamily::normals(const TessellationLayout& layout, std::size_t begin, std::size_t end, const Point* pos,
                             std::array<float, 3>* out) const {
  samples<false, true>(layout, begin, end, pos, nullptr, out);
}

void TriangleFamily::points_and_normals(const TessellationLayout& layout, std::size_t begin, std::size_t end,
                                        const Point* pos, std::array<float, 3>* positions,
                                        std::array<float, 3>* normals) const {
  samples<true, true>(layout, begin, end, pos, positions, normals);
}

template <bool kPositions, bool kNormals>
void TriangleFamily::samples(const TessellationLayout& layout, std::size_t begin, std::size_t end, const Point* pos,
                             std::array<float, 3>* positions, std::array<float, 3>* normals) const {
  thread_local std::vector<Point> local, row_ds, row_dt;
  for (std::size_t f = begin; f != end; ++f) {
    if (!layout.holes.empty() && layout.holes[f]) continue;  // no points
    const TrianglePatch& p = patches_[f];
    const long n = layout.rates[f];
    std::array<float, 3>* position = kPositions ? positions + layout.point_offsets[f] : nullptr;
    std::array<float, 3>* normal = kNormals ? normals + layout.point_offsets[f] : nullptr;
    // Normals: the points differentiated in the patch's own coordinates; the
    // patch's rotation (and the Loop split's maps, below a refined face) keep
    // the orientation, so du x dv there points the same way as on the face.
    auto put_normal = [&](const Point& du, const Point& dv) {
      const Point u = unit_cross(du, dv);
      *normal++ = {static_cast<float>(u[0]), static_cast<float>(u[1]), static_cast<float>(u[2])};
    };
    // The face's n^2 centres in their order (up_centre_index, down_centre_index):
    // row(a0, b, count) for the samples (a0 + 3i, b), i < count, in thirds of 1/n.
    auto each_row = [&](auto&& row) {
      for (long j = 0; j < n; ++j) row(1L, 3 * j + 1, n - j);
      for (long j = 0; j + 1 < n; ++j) row(2L, 3 * j + 2, n - 1 - j);
    };
    if (refined(f)) {
      // Refined round semi-sharp features: point by point from the leaves,
      // where each centre is a centre of rate n again (a Loop split doubles it).
      // The leaves' kinds' centre derivatives, looked up (under the cache's lock) only when the kind changes.
      std::shared_ptr<const std::vector<double>> kind_derivatives;
      int kind_valence = 0, kind_region = -1;
      each_row([&](long a0, long b, long count) {
        for (long i = 0, a = a0; i < count; ++i, a += 3) {
          long la = a, lb = b, pa = 0, pb = 0;
          const TrianglePatch& leaf = patches_[leaf_of(f, la, lb, 3 * n)];
          leaf.to_patch(la, lb, 3 * n, pa, pb);
          const TriangleTables::Grid g = tables_.grid(leaf.valence, static_cast<int>(n), leaf.region);
          const std::size_t m = leaf.points.size();
          if (kPositions) {
            const Point q = stencil_sum(g.weights(static_cast<TriangleTables::GridPoint>(pa % 3), pa / 3, pb / 3),
                                        leaf.points.data(), m, pos);
            *position++ = {static_cast<float>(q[0]), static_cast<float>(q[1]), static_cast<float>(q[2])};
          }
          if (kNormals) {
            const int ci = static_cast<int>(pa / 3), cj = static_cast<int>(pb / 3), rate = static_cast<int>(n);
            const int centre = pa % 3 == 1 ? up_centre_index(ci, cj, rate) : down_centre_index(ci, cj, rate);
            if (leaf.valence != kind_valence || leaf.region != kind_region) {
              kind_derivatives = centre_derivatives(leaf.valence, leaf.region, rate, m);
              kind_valence = leaf.valence, kind_region = leaf.region;
            }
            const double* d = kind_derivatives->data() + static_cast<std::size_t>(centre) * 2 * m;
            put_normal(stencil_sum(d, leaf.points.data(), m, pos), stencil_sum(d + m, leaf.points.data(), m, pos));
          }
        }
      });
      continue;
    }
    gather_points(p.points, pos, local);  // once per face: the sums below read them n^2 times
    const std::size_t m = local.size();
    const TriangleTables::Grid grid = tables_.grid(p.valence, static_cast<int>(n), p.region);
    auto put_position = [&](const double* w) {
      double x = 0, y = 0, z = 0;
      for (std::size_t h = 0; h < m; ++h) x += w[h] * local[h][0], y += w[h] * local[h][1], z += w[h] * local[h][2];
      *position++ = {static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)};
    };
    auto position_weights = [&](long a, long b) {
      long pa = 0, pb = 0;
      p.to_patch(a, b, 3 * n, pa, pb);
      return grid.weights(static_cast<TriangleTables::GridPoint>(pa % 3), pa / 3, pb / 3);
    };
    if (kNormals && derivative_rows_ && p.valence == 6 && p.region == 0 && n >= kRowNormalRate) {
      // A polynomial regular patch (Loop): normals row by row (face_derivative_rows.hpp).
      FaceDerivativeRows::Face face(*derivative_rows_, p.rotation, local.data());
      const double scale = 1.0 / (3.0 * static_cast<double>(n));
      each_row([&](long a0, long b, long count) {
        if (kPositions)
          for (long i = 0, a = a0; i < count; ++i, a += 3) put_position(position_weights(a, b));
        // The derivatives of the whole row, then their normals: short loops whose
        // samples are independent, so that the processor overlaps their chains
        // of dependent operations (Horner steps, the square root).
        face.start_row(static_cast<double>(b) * scale);
        row_ds.resize(static_cast<std::size_t>(count)), row_dt.resize(static_cast<std::size_t>(count));
        for (long i = 0, a = a0; i < count; ++i, a += 3)
          face.at(static_cast<double>(a) * scale, row_ds[static_cast<std::size_t>(i)], row_dt[static_cast<std::size_t>(i)]);
        for (std::size_t i = 0; i < static_cast<std::size_t>(count); ++i) put_normal(row_ds[i], row_dt[i]);
      });
      continue;
    }
    if (kNormals && grid.has_sparse_jets()) {
      // The other regular faces (sqrt(3); Loop below kRowNormalRate): the
      // tables' value and derivative stencils at each point, their nonzero
      // entries only (sqrt(3): about two thirds), in one pass over the points;
      // a row's derivatives first, then their normals, as above.
      each_row([&](long a0, long b, long count) {
        row_ds.resize(static_cast<std::size_t>(count)), row_dt.resize(static_cast<std::size_t>(count));
        for (long i = 0, a = a0; i < count; ++i, a += 3) {
          long pa = 0, pb = 0;
          p.to_patch(a, b, 3 * n, pa, pb);
          TriangleTables::Grid::SparseJet jet;
          grid.sparse_jet(static_cast<TriangleTables::GridPoint>(pa % 3), pa / 3, pb / 3, jet);
          double x = 0, y = 0, z = 0, ux = 0, uy = 0, uz = 0, vx = 0, vy = 0, vz = 0;
          for (std::size_t k = 0; k < jet.count; ++k) {
            const Point& q = local[jet.column[k]];
            const double* c = jet.wuv + 3 * k;
            if (kPositions) x += c[0] * q[0], y += c[0] * q[1], z += c[0] * q[2];
            ux += c[1] * q[0], uy += c[1] * q[1], uz += c[1] * q[2];
            vx += c[2] * q[0], vy += c[2] * q[1], vz += c[2] * q[2];
          }
          if (kPositions) *position++ = {static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)};
          row_ds[static_cast<std::size_t>(i)] = {ux, uy, uz}, row_dt[static_cast<std::size_t>(i)] = {vx, vy, vz};
        }
        for (std::size_t i = 0; i < static_cast<std::size_t>(count); ++i) put_normal(row_ds[i], row_dt[i]);
      });
      continue;
    }
    // The other patches: positions from the tables' stencils; normals from
    // the kind's derivative stencils at the centres (centre_derivatives).
    const std::shared_ptr<const std::vector<double>> derivatives =
        kNormals ? centre_derivatives(p.valence, p.region, static_cast<int>(n), m) : nullptr;
    auto put = [&](long a, long b) {
      long pa = 0, pb = 0;
      p.to_patch(a, b, 3 * n, pa, pb);
      const double* w = kPositions ? grid.weights(static_cast<TriangleTables::GridPoint>(pa % 3), pa / 3, pb / 3) : nullptr;
      if (!kNormals) {
        put_position(w);
        return;
      }
      // Position and derivatives in one pass over the points: nine
      // independent sums keep the processor's pipelines full where the
      // position's three alone wait on their own additions.
      const int i = static_cast<int>(pa / 3), j = static_cast<int>(pb / 3), rate = static_cast<int>(n);
      const int centre = pa % 3 == 1 ? up_centre_index(i, j, rate) : down_centre_index(i, j, rate);
      const double* d = derivatives->data() + static_cast<std::size_t>(centre) * 2 * m;
      double x = 0, y = 0, z = 0, ux = 0, uy = 0, uz = 0, vx = 0, vy = 0, vz = 0;
      for (std::size_t h = 0; h < m; ++h) {
        const Point& q = local[h];
        if (kPositions) x += w[h] * q[0], y += w[h] * q[1], z += w[h] * q[2];
        ux += d[h] * q[0], uy += d[h] * q[1], uz += d[h] * q[2];
        vx += d[m + h] * q[0], vy += d[m + h] * q[1], vz += d[m + h] * q[2];
      }
      if (kPositions) *position++ = {static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)};
      put_normal({ux, uy, uz}, {vx, vy, vz});
    };
    each_row([&](long a0, long b, long count) {
      for (long i = 0, a = a0; i < count; ++i, a += 3) put(a, b);
    });
  }
}

std::shared_ptr<const std::vector<double>> TriangleFamily::centre_derivatives(int valence, int region, int n,
                                                                             std::size_t m) const {
  const std::tuple<int, int, int> key{valence, region, n};
  {
    std::lock_guard lock(centre_derivatives_mutex_);
    const auto it = centre_derivatives_.find(key);
    if (it != centre_derivatives_.end()) return it->second;
  }
  // The derivatives are linear in the points (derivative_weights_by_linearity).
  const TrianglePatchDescent& descent = checked_descent();
  const auto rate = static_cast<std::size_t>(n);
  auto weights = std::make_shared<std::vector<double>>(rate * rate * 2 * m);
  auto fill = [&](int centre, long pa, long pb) {
    derivative_weights_by_linearity(
        m,
        [&](std::vector<Point>& unit) {
          return descent.derivatives(valence, region, unit, ExactDual{Fraction::make(pa, 3L * n), 1, 0},
                                     ExactDual{Fraction::make(pb, 3L * n), 0, 1});
        },
        weights->data() + static_cast<std::size_t>(centre) * 2 * m);
  };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i + j <= n - 1; ++i) fill(up_centre_index(i, j, n), 3L * i + 1, 3L * j + 1);
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + j <= n - 2; ++i) fill(down_centre_index(i, j, n), 3L * i + 2, 3L * j + 2);
  std::lock_guard lock(centre_derivatives_mutex_);
  return centre_derivatives_.emplace(key, std::move(weights)).first->second;
}

namespace {

// Grid node t (0..n, in the edge's direction) of the face's edge k, in thirds: the face's node (i/(3n), j/(3n)).
inline void edge_grid_node(int k, long t, long n, long& i, long& j) {
  switch (k) {
    case 0: i = 3 * t, j = 0; break;
    case 1: i = 3 * (n - t), j = 3 * t; break;
    default: i = 0, j = 3 * (n - t); break;
  }
}

}  // namespace

std::size_t TriangleFamily::leaf_of(std::size_t node, long& a, long& b, long d) const {
  while (refined(node)) node = tree_.child(node, loop_child_on_grid(a, b, d));
  return node;
}

Point TriangleFamily::edge_node(std::size_t face, int corner, int t, int n, const Point* prepared) const {
  long i = 0, j = 0, pi = 0, pj = 0;
  edge_grid_node(corner, t, n, i, j);
  const TrianglePatch& p = patches_[leaf_of(face, i, j, 3L * n)];  // a node of rate n below a refined face too
  p.to_patch(i, j, 3L * n, pi, pj);
  const TriangleTables::Grid grid = tables_.grid(p.valence, n, p.region);
  const double* w = grid.weights(TriangleTables::GridPoint::Node, pi / 3, pj / 3);
  return stencil_sum(w, p.points.data(), p.points.size(), prepared);
}

std::array<double, 2> TriangleFamily::edge_node_parameter(std::size_t face, int corner, int t, int n) const {
  long i = 0, j = 0, pi = 0, pj = 0;
  edge_grid_node(corner, t, n, i, j);
  patches_[face].to_patch(i, j, 3L * n, pi, pj);
  return {static_cast<double>(pi) / (3.0 * n), static_cast<double>(pj) / (3.0 * n)};
}

}  // namespace stencil_runtime
