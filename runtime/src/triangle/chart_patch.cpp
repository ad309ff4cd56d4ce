#include "chart_patch.hpp"

#include <array>

namespace stencil_runtime {

namespace {

std::uint32_t turn(const TriangleTopology& t, std::uint32_t h, int times) {
  for (int k = 0; k < times; ++k) h = t.turn_ccw(h);
  return h;
}

}  // namespace

namespace {

// From the origin along the edge to e_first for `straight` steps, then turned
// by `turns` (counter-clockwise from the way back: 4 is a 60-degree left turn,
// 2 a right turn) for `after` steps; nullopt if a vertex turned at is not regular.
std::optional<int> walk(const TriangleTopology& t, std::uint32_t first, long straight, int turns, long after) {
  std::uint32_t e = first;
  for (long step = 1; step < straight + after; ++step) {
    // Only a regular inner vertex is walked through (a boundary vertex in six
    // faces is not: its fan is open, turning round it would leave the mesh).
    if (t.valence(t.head(e)) != 6 || t.on_boundary(t.head(e))) return std::nullopt;
    // From the way back (+180 degrees): straight on is 3 turns.
    e = turn(t, t.twin(e), step == straight ? turns : 3);
  }
  return t.head(e);
}

}  // namespace

std::optional<int> chart_vertex(const TriangleTopology& t, std::uint32_t e_0, const ChartPoint& p) {
  const int origin = t.vertex(TriangleTopology::face_of(e_0), TriangleTopology::corner_of(e_0));
  if (p.a == 0) return origin;
  // Turning counter-clockwise round a vertex is +60 degrees in the chart.
  const int v = t.valence(origin);
  const std::uint32_t e_k = turn(t, e_0, p.sector % v);
  if (const auto x = walk(t, e_k, p.a - p.b, 4, p.b)) return x;
  // The other side of the parallelogram: b steps along e_{k+1}, then a - b after a right turn.
  if (p.b > 0) return walk(t, t.turn_ccw(e_k), p.b, 2, p.a - p.b);
  return std::nullopt;
}

namespace {

// The layout's vertices walked from e_0; false when a walk fails.
bool walk_layout(const TriangleTopology& t, std::uint32_t e_0, const std::vector<ChartPoint>& layout, std::vector<int>& points) {
  points.clear();
  points.reserve(layout.size());
  for (const ChartPoint& p : layout) {
    const auto v = chart_vertex(t, e_0, p);
    if (!v) return false;
    points.push_back(*v);
  }
  return true;
}

// Where a face without an extraordinary corner lies in the second ring of the
// extraordinary vertex x, given which corners are x's neighbours (to_x[c]: the
// half-edge from corner c to x): the band region, the face corner at its corner
// 0, and x's half-edge e_k of the sector it lies in (sector 0 of the region's
// chart). false for any other configuration.
bool band_position(const TriangleTopology& t, std::size_t f, const std::array<std::optional<std::uint32_t>, 3>& to_x,
                   TrianglePatch& patch, std::uint32_t& e_k) {
  const int adjacent = (to_x[0] ? 1 : 0) + (to_x[1] ? 1 : 0) + (to_x[2] ? 1 : 0);
  if (adjacent == 2) {
    // Region 2, corners (1,0), (2,1), (1,1): e_k, a second-ring vertex, e_{k+1}.
    const int r = to_x[0] ? (to_x[1] ? 1 : 0) : 2;  // the corner after r is the one not adjacent
    e_k = t.twin(*to_x[r]);
    patch.region = 2, patch.rotation = r;
    return t.head(t.turn_ccw(e_k)) == t.vertex(f, r + 2);
  }
  if (adjacent != 1) return false;
  const int r = to_x[0] ? 0 : to_x[1] ? 1 : 2;
  const std::uint32_t to_p = t.twin(*to_x[r]);          // x -> the corner next to it
  const std::uint32_t beyond = turn(t, t.twin(to_p), 3);  // straight on through that corner
  patch.rotation = r;
  if (t.head(beyond) == t.vertex(f, r + 1)) {
    // Region 1, corners (1,0), (2,0), (2,1): the corner is e_k.
    patch.region = 1, e_k = to_p;
    return true;
  }
  if (t.head(beyond) == t.vertex(f, r + 2)) {
    // Region 3, corners (1,1), (2,1), (2,2): the corner is e_{k+1}.
    patch.region = 3, e_k = turn(t, to_p, t.valence(t.head(t.twin(to_p))) - 1);
    return true;
  }
  return false;
}

}  // namespace

std::optional<TrianglePatch> find_triangle_patch(const TriangleTopology& t, std::size_t f, const TriangleTables& tables) {
  TrianglePatch patch;
  int ev = -1;  // the extraordinary vertex whose patch or band holds the face
  for (int c = 0; c < 3; ++c)
    if (t.valence(t.vertex(f, c)) != 6) {
      if (ev >= 0) return std::nullopt;
      ev = t.vertex(f, c);
      patch.valence = t.valence(ev);
      patch.rotation = c;
    }
  // Extraordinary neighbours of the corners whose vertex rule reaches the second ring.
  std::array<std::optional<std::uint32_t>, 3> to_x;
  int near = -1;
  for (int c = 0; c < 3; ++c) {
    const std::uint32_t first = TriangleTopology::half_edge(f, c);
    std::uint32_t h = first;
    do {
      const int x = t.head(h);
      const int valence = t.valence(x);
      if (valence != 6 && x != ev && !t.on_boundary(x) && tables.regions(valence) > 1) {
        if (ev >= 0 || (near >= 0 && near != x)) return std::nullopt;
        near = x;
        to_x[static_cast<std::size_t>(c)] = h;
      }
      h = t.turn_ccw(h);
    } while (h != first);
  }
  if (ev >= 0) {
    if (walk_layout(t, TriangleTopology::half_edge(f, patch.rotation), tables.layout(patch.valence), patch.points)) return patch;
    return std::nullopt;
  }
  if (near >= 0) {
    std::uint32_t e_k = 0;
    patch.valence = t.valence(near);
    if (band_position(t, f, to_x, patch, e_k) &&
        walk_layout(t, e_k, tables.layout(patch.valence, patch.region), patch.points))
      return patch;
    return std::nullopt;
  }
  for (int r = 0; r < 3; ++r)
    if (walk_layout(t, TriangleTopology::half_edge(f, r), tables.layout(6), patch.points)) {
      patch.rotation = r;
      return patch;
    }
  return std::nullopt;
}

}  // namespace stencil_runtime
