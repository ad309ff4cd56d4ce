#pragma once
// Pieces shared by the quad and the triangle tessellations: the zipper between
// two rows of limit points along a mesh edge, and the polygons along every edge
// and round every vertex.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "family/rim_node.hpp"
#include "mesh/uniform_topology.hpp"
#include "stencil_runtime/error.hpp"
#include "stencil_runtime/limits.hpp"

namespace stencil_runtime::detail {

// The zipper between two rows along one edge, both given in the edge's
// direction: A (na points) on the left, B (nb points) on the right. Equal rows
// give na - 1 quads quad(a, b); others na + nb - 2 triangles tri(a, b, advance_a).
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
    tri(a, b, advance_a);
    if (advance_a) ++a;
    else ++b;
  }
}

// The polygons the mesh's edges and vertices contribute: the zipper of each
// edge (owned by its smaller half-edge) and the polygon of the corner points
// round each vertex (owned by its first outgoing half-edge). `row(k, t, n)` is
// the index, among a face's points, of point t (in the edge's direction) of
// the row along the face's edge k (corner k -> k+1) at rate n; row(k, 0, n) is
// the point at corner k.
//
// Rims: the faces' points are inside them (cell centres), so where a face has
// no neighbour across an edge (the mesh's boundary, or a hole: a face without
// a surface, `holes[f] != 0`) the tessellation goes on to the surface's edge
// there: rim points at the edge's grid nodes at the face's rate (the limit
// curve along that edge) and a strip of triangles from the face's row to them.
// Round a vertex, each run of consecutive faces that are not holes and ends
// at such edges gets one rim point at the vertex (its limit point; one per run,
// so that two runs touching at a vertex stay two sheets) and a fan from it to
// the run's corner points. Rim points follow the faces' points; rim_nodes()
// says where each one lies.
template <int K>
class SeamPolygons {
 public:
  using Topology = UniformTopology<K>;
  // `holes`: per face, or empty; kept by reference, like `rates`.
  SeamPolygons(const Topology& topo, const std::vector<int>& rates, const std::vector<char>& holes)
      : topo_(topo), rates_(rates), holes_(holes), nh_(K * topo.faces()), nv_(topo.vertices()),
        quad_offset_(nh_ + nv_ + 1, 0), tri_offset_(nh_ + nv_ + 1, 0), vertex_owner_(nv_, UINT32_MAX) {
    const bool rims = topo.has_boundary() || !holes_.empty();
    if (rims) {
      rim_offset_.assign(nh_ + 1, 0);
      run_offset_.assign(nv_ + 1, 0);
      rim_start_.assign(nh_, UINT32_MAX);
      rim_end_.assign(nh_, UINT32_MAX);
    }
    for (std::uint32_t h = 0; h < nh_; ++h) {
      const auto v = static_cast<std::size_t>(topo.vertex(Topology::face_of(h), Topology::corner_of(h)));
      const std::uint32_t o = topo.twin(h);
      // A boundary vertex's fan starts at its outgoing boundary half-edge.
      if (vertex_owner_[v] == UINT32_MAX || o == Topology::kNoTwin) vertex_owner_[v] = h;
      std::size_t q = 0, t = 0;
      const auto na = static_cast<std::size_t>(rates[Topology::face_of(h)]);
      if (rim(h)) {
        t = 2 * na - 1;  // the strip from the face's row to the na + 1 rim points
      } else if (o != Topology::kNoTwin && h < o && !hole(Topology::face_of(h)) && !hole(Topology::face_of(o))) {
        const auto nb = static_cast<std::size_t>(rates[Topology::face_of(o)]);
        if (na == nb) q = na - 1;
        else t = na + nb - 2;
      }
      quad_offset_[h + 1] = quad_offset_[h] + q;
      tri_offset_[h + 1] = tri_offset_[h] + t;
      if (rims) rim_offset_[h + 1] = rim_offset_[h] + (rim(h) ? na - 1 : 0);  // the edge's inner grid nodes
    }
    std::uint32_t ring[limits::kMaxValence];
    for (std::size_t v = 0; v < nv_; ++v) {
      // Without holes or boundaries the valence says it all; the ring is walked only to find them.
      bool open = false;
      const int k = !rims ? topo.valence(static_cast<int>(v)) : ring_of(v, ring, open);
      std::size_t q = 0, t = 0, runs = 0;
      if (!open && (holes_.empty() || !ring_has_hole(ring, k))) {
        q = k == 4 ? 1 : 0;
        t = k == 4 ? 0 : static_cast<std::size_t>(k - 2);
      } else {
        for_each_run(ring, k, open, [&](const std::uint32_t* run, int length) {
          // The run's rim point: where its first face's outgoing rim edge starts and its last face's incoming one ends.
          const auto point = static_cast<std::uint32_t>(run_offset_[v] + runs++);
          rim_start_[run[0]] = point;
          rim_end_[Topology::half_edge(Topology::face_of(run[length - 1]), Topology::corner_of(run[length - 1]) + K - 1)] = point;
          t += static_cast<std::size_t>(length - 1);
        });
      }
      if (rims) run_offset_[v + 1] = run_offset_[v] + runs;
      quad_offset_[nh_ + v + 1] = quad_offset_[nh_ + v] + q;
      tri_offset_[nh_ + v + 1] = tri_offset_[nh_ + v] + t;
    }
  }
  std::size_t half_edges() const { return nh_; }
  std::size_t quads() const { return quad_offset_.back(); }
  std::size_t triangles() const { return tri_offset_.back(); }
  std::size_t rim_points() const { return rim_offset_.empty() ? 0 : run_offset_.back() + rim_offset_.back(); }
  // EvaluationError where `face_points` and the rim points after them exceed
  // limits::kMaxTessellationPoints.
  void check_points(std::size_t face_points) const {
    const std::size_t total = face_points + rim_points();
    if (total > limits::kMaxTessellationPoints)
      throw EvaluationError("the tessellation would have " + std::to_string(total) + " points; the limit is " +
                            std::to_string(limits::kMaxTessellationPoints) + " (lower the rates)");
  }

  // Where each rim point lies, in order; `point_offset` as for edges().
  template <class Row>
  std::vector<RimNode> rim_nodes(const std::vector<std::size_t>& point_offset, const Row& row) const {
    std::vector<RimNode> out(rim_points());
    for (std::uint32_t h = 0; h < nh_; ++h) {
      if (!rim(h)) continue;
      const std::uint32_t f = Topology::face_of(h);
      const int k = Topology::corner_of(h), n = rates_[f];
      auto beside = [&](int t) { return static_cast<std::uint32_t>(point_offset[f] + static_cast<std::size_t>(row(k, t, n))); };
      out[rim_start_[h]] = {f, k, 0, beside(0)};  // the same point for every rim edge of its run
      for (int t = 1; t < n; ++t) out[run_offset_.back() + rim_offset_[h] + static_cast<std::size_t>(t - 1)] = {f, k, t, beside(t - 1)};
    }
    return out;
  }

  // Zippers of the edges owned by half-edges [begin, end), into the slots after `quads` and `tris`.
  template <class Row>
  void edges(std::size_t begin, std::size_t end, const std::vector<std::size_t>& point_offset, const Row& row,
             std::array<int, 4>* quads, std::array<int, 3>* tris) const {
    const int rim_base = static_cast<int>(point_offset.back());
    for (auto h = static_cast<std::uint32_t>(begin); h != end; ++h) {
      if (rim(h)) {  // the strip from the face's row (A, na points) to the rim points (R, na + 1) along the edge
        const std::size_t f = Topology::face_of(h);
        const int kf = Topology::corner_of(h), na = rates_[f];
        const int fa = static_cast<int>(point_offset[f]);
        auto A = [&](int t) { return fa + row(kf, t, na); };
        auto R = [&](int t) {
          if (t == 0) return rim_base + static_cast<int>(rim_start_[h]);
          if (t == na) return rim_base + static_cast<int>(rim_end_[h]);
          return rim_base + static_cast<int>(run_offset_.back() + rim_offset_[h]) + t - 1;
        };
        std::array<int, 3>* t = tris + tri_offset_[h];
        for (int a = 0; a < na; ++a) {
          *t++ = {R(a), R(a + 1), A(a)};
          if (a + 1 < na) *t++ = {A(a), R(a + 1), A(a + 1)};
        }
        continue;
      }
      const std::uint32_t o = topo_.twin(h);
      if (o < h || o == Topology::kNoTwin) continue;  // owned by the twin, or a boundary edge
      const std::size_t f = Topology::face_of(h), g = Topology::face_of(o);
      if (hole(f) || hole(g)) continue;  // the rim: no zipper
      const int kf = Topology::corner_of(h), kg = Topology::corner_of(o);
      const int na = rates_[f], nb = rates_[g];
      const int fa = static_cast<int>(point_offset[f]), gb = static_cast<int>(point_offset[g]);
      auto A = [&](int t) { return fa + row(kf, t, na); };
      auto B = [&](int t) { return gb + row(kg, nb - 1 - t, nb); };  // g's row, in f's direction
      std::array<int, 4>* q = quads + quad_offset_[h];
      std::array<int, 3>* t = tris + tri_offset_[h];
      zipper(
          na, nb, [&](int a, int b) { *q++ = {B(b), B(b + 1), A(a + 1), A(a)}; },
          [&](int a, int b, bool advance_a) {
            if (advance_a) *t++ = {B(b), A(a + 1), A(a)};
            else *t++ = {B(b), B(b + 1), A(a)};
          });
    }
  }

  // Polygons of vertices [begin, end): a quad at valence 4, a fan of triangles otherwise.
  template <class Row>
  void vertices(std::size_t begin, std::size_t end, const std::vector<std::size_t>& point_offset, const Row& row,
                std::array<int, 4>* quads, std::array<int, 3>* tris) const {
    std::uint32_t halfedges[limits::kMaxValence];
    for (std::size_t v = begin; v != end; ++v) {
      bool open = false;
      const int k = ring_of(v, halfedges, open);
      auto corner = [&](std::uint32_t e) {
        const std::size_t f = Topology::face_of(e);
        return static_cast<int>(point_offset[f]) + row(Topology::corner_of(e), 0, rates_[f]);
      };
      std::array<int, 3>* t = tris + tri_offset_[nh_ + v];
      if (!open && !ring_has_hole(halfedges, k)) {
        int ring[limits::kMaxValence];
        for (int i = 0; i < k; ++i) ring[i] = corner(halfedges[i]);
        if (k == 4) quads[quad_offset_[nh_ + v]] = {ring[0], ring[1], ring[2], ring[3]};
        else
          for (int i = 1; i + 1 < k; ++i) *t++ = {ring[0], ring[i], ring[i + 1]};
        continue;
      }
      const int rim_base = static_cast<int>(point_offset.back());
      for_each_run(halfedges, k, open, [&](const std::uint32_t* run, int length) {
        const int apex = rim_base + static_cast<int>(rim_start_[run[0]]);
        for (int i = 0; i + 1 < length; ++i) *t++ = {apex, corner(run[i]), corner(run[i + 1])};
      });
    }
  }

 private:
  bool hole(std::size_t f) const { return !holes_.empty() && holes_[f] != 0; }
  // A half-edge of a face with a surface and none across it: the tessellation's rim runs along it.
  bool rim(std::uint32_t h) const {
    if (hole(Topology::face_of(h))) return false;
    const std::uint32_t o = topo_.twin(h);
    return o == Topology::kNoTwin || hole(Topology::face_of(o));
  }

  // The half-edges leaving vertex v, counter-clockwise from its owner; their
  // count. `open`: v is on the boundary, and the fan ends at its last face.
  int ring_of(std::size_t v, std::uint32_t* out, bool& open) const {
    const std::uint32_t h = vertex_owner_[v];
    int k = 0;
    std::uint32_t e = h;
    do {
      out[k++] = e;
      e = topo_.turn_ccw(e);
    } while (e != h && e != Topology::kNoTwin && k < limits::kMaxValence);
    open = e == Topology::kNoTwin;
    return k;
  }
  bool ring_has_hole(const std::uint32_t* ring, int k) const {
    for (int i = 0; i < k; ++i)
      if (hole(Topology::face_of(ring[i]))) return true;
    return false;
  }
  // Each run of consecutive faces that are not holes (a closed ring holds one),
  // in counter-clockwise order: emit(first half-edge, length). An open fan is
  // not wrapped round.
  template <class Emit>
  void for_each_run(const std::uint32_t* ring, int k, bool open, const Emit& emit) const {
    std::uint32_t run[limits::kMaxValence];
    int length = 0;
    if (open) {
      for (int i = 0; i <= k; ++i) {
        if (i < k && !hole(Topology::face_of(ring[i]))) {
          run[length++] = ring[i];
          continue;
        }
        if (length >= 1) emit(run, length);
        length = 0;
      }
      return;
    }
    int start = 0;
    while (!hole(Topology::face_of(ring[start]))) ++start;  // a hole: runs begin after it
    for (int i = 1; i <= k; ++i) {
      const std::uint32_t e = ring[(start + i) % k];
      if (!hole(Topology::face_of(e))) {
        run[length++] = e;
        continue;
      }
      if (length >= 1) emit(run, length);
      length = 0;
    }
  }

  const Topology& topo_;
  const std::vector<int>& rates_;
  const std::vector<char>& holes_;  // per face, or empty
  std::size_t nh_, nv_;
  std::vector<std::size_t> quad_offset_, tri_offset_;  // per half-edge, then per vertex
  // Rims (empty without boundary or holes): rim points inside each half-edge's
  // edge (prefix sums), rim points per vertex (one per run), and the rim point
  // at the start and at the end of each rim half-edge (its run's, numbered
  // among the rim points).
  std::vector<std::size_t> rim_offset_, run_offset_;
  std::vector<std::uint32_t> rim_start_, rim_end_;
  std::vector<std::uint32_t> vertex_owner_;
};

}  // namespace stencil_runtime::detail
