#include "boundary_patch.hpp"

#include <algorithm>

namespace stencil_runtime {

namespace {

using Lattice = std::array<int, 2>;  // x D_0 + y D_1, D_0 along corner 0 -> 1, D_1 along corner 0 -> 2

// The six unit directions, counter-clockwise from D_0.
constexpr std::array<Lattice, 6> kDirections{{{1, 0}, {0, 1}, {-1, 1}, {-1, 0}, {0, -1}, {1, -1}}};

Lattice plus(const Lattice& a, const Lattice& b) { return {a[0] + b[0], a[1] + b[1]}; }
Lattice minus(const Lattice& a, const Lattice& b) { return {a[0] - b[0], a[1] - b[1]}; }

// Chart point (s, a, b) of the regular layout as a lattice point: (a - b) D_s + b D_{s+1}.
Lattice lattice_of(const ChartPoint& p) {
  const Lattice& ds = kDirections[static_cast<std::size_t>(((p.sector % 6) + 6) % 6)];
  const Lattice& dn = kDirections[static_cast<std::size_t>(((p.sector + 1) % 6 + 6) % 6)];
  return {(p.a - p.b) * ds[0] + p.b * dn[0], (p.a - p.b) * ds[1] + p.b * dn[1]};
}

// The corners' fans unfolded onto the lattice: each vertex of a face at a
// corner of `face`, at its lattice point. A vertex may stand at two points
// (next to an inside vertex of valence 3 the fans of two corners reach the
// same vertex from two sides): the patch's rules see only adjacency, so it is
// then a control point twice. Two vertices at one point are no plane fan.
class Unfolding {
 public:
  bool place(int v, const Lattice& at) {
    for (const auto& [w, p] : points_)
      if (p == at) return w == v;
    points_.emplace_back(v, at);
    return true;
  }
  std::optional<Lattice> where(int v) const {
    for (const auto& [w, p] : points_)
      if (w == v) return p;
    return std::nullopt;
  }
  std::optional<int> at(const Lattice& q) const {
    for (const auto& [w, p] : points_)
      if (p == q) return w;
    return std::nullopt;
  }

 private:
  std::vector<std::pair<int, Lattice>> points_;
};

// Places the faces round vertex `v` (already placed with one neighbour along
// half-edge `from`), turning both ways until the boundary or back to `from`.
bool unfold_fan(const TriangleTopology& t, std::uint32_t from, Unfolding& u) {
  const int v = t.vertex(TriangleTopology::face_of(from), TriangleTopology::corner_of(from));
  const Lattice centre = *u.where(v);
  const Lattice first = minus(*u.where(t.head(from)), centre);
  const std::size_t k = static_cast<std::size_t>(std::find(kDirections.begin(), kDirections.end(), first) - kDirections.begin());
  if (k == kDirections.size()) return false;
  // Counter-clockwise: each outgoing half-edge is the next direction.
  std::uint32_t h = from;
  for (std::size_t step = 0; step < 6; ++step) {
    if (!u.place(t.head(h), plus(centre, kDirections[(k + step) % 6]))) return false;
    // The face of h also holds the vertex before v (its third corner).
    const std::size_t f = TriangleTopology::face_of(h);
    if (!u.place(t.vertex(f, TriangleTopology::corner_of(h) + 2), plus(centre, kDirections[(k + step + 1) % 6]))) return false;
    h = t.turn_ccw(h);
    if (h == TriangleTopology::kNoTwin || h == from) break;
  }
  // Clockwise from `from`, for a boundary vertex whose fan began before it.
  h = from;
  for (std::size_t step = 1; step < 6; ++step) {
    // The half-edge before h round v: after h's twin (head(h) -> v) in the face before.
    const std::uint32_t back = t.twin(h);
    if (back == TriangleTopology::kNoTwin) break;
    h = TriangleTopology::half_edge(TriangleTopology::face_of(back), TriangleTopology::corner_of(back) + 1);
    if (h == from) break;
    if (!u.place(t.head(h), plus(centre, kDirections[(k + 6 - step) % 6]))) return false;
  }
  return true;
}

}  // namespace

int PhantomPoints::add(int b1, int b2, int r) {
  if (b2 < b1) std::swap(b1, b2);
  const auto [it, inserted] = index.emplace(std::array<int, 3>{b1, b2, r}, static_cast<int>(first + rows.size()));
  if (inserted) rows.push_back({{b1, 1.0}, {b2, 1.0}, {r, -1.0}});
  return it->second;
}

bool regular_loop_vertex(const TriangleTopology& t, int v) { return t.valence(v) == (t.on_boundary(v) ? 3 : 6); }

std::optional<TrianglePatch> regular_boundary_patch(const TriangleTopology& t, std::size_t face, const TriangleTables& tables,
                                                    PhantomPoints& phantoms) {
  for (int c = 0; c < 3; ++c)
    if (!regular_loop_vertex(t, t.vertex(face, c))) return std::nullopt;
  Unfolding u;
  u.place(t.vertex(face, 0), {0, 0});
  u.place(t.vertex(face, 1), {1, 0});
  u.place(t.vertex(face, 2), {0, 1});
  for (int c = 0; c < 3; ++c)
    if (!unfold_fan(t, TriangleTopology::half_edge(face, c), u)) return std::nullopt;
  TrianglePatch patch;
  patch.valence = 6;
  patch.region = 0;
  patch.rotation = 0;
  for (const ChartPoint& p : tables.layout(6)) {
    const Lattice q = lattice_of(p);
    if (const auto v = u.at(q)) {
      patch.points.push_back(*v);
      continue;
    }
    // Beyond the boundary: across the boundary edge (b1, b2) from the real triangle (b1, b2, r).
    std::optional<int> phantom;
    for (std::size_t k = 0; k < 6 && !phantom; ++k) {
      const Lattice p1 = plus(q, kDirections[k]), p2 = plus(q, kDirections[(k + 1) % 6]);
      const auto b1 = u.at(p1), b2 = u.at(p2), r = u.at(minus(plus(p1, p2), q));
      if (b1 && b2 && r && t.on_boundary(*b1) && t.on_boundary(*b2)) phantom = phantoms.add(*b1, *b2, *r);
    }
    if (!phantom) return std::nullopt;
    patch.points.push_back(*phantom);
  }
  return patch;
}

}  // namespace stencil_runtime
