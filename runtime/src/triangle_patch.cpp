#include "stencil_runtime/triangle_patch.hpp"

namespace stencil_runtime {

namespace {

std::uint32_t turn(const TriangleTopology& t, std::uint32_t h, int times) {
  for (int k = 0; k < times; ++k) h = t.turn_ccw(h);
  return h;
}

int head(const TriangleTopology& t, std::uint32_t h) {
  return t.vertex(TriangleTopology::face_of(h), TriangleTopology::corner_of(h) + 1);
}

}  // namespace

namespace {

// From the origin along the edge to e_first for `straight` steps, then turned
// by `turns` (counter-clockwise from the way back: 4 is a 60-degree left turn,
// 2 a right turn) for `after` steps; nullopt if a vertex turned at is not regular.
std::optional<int> walk(const TriangleTopology& t, std::uint32_t first, long straight, int turns, long after) {
  std::uint32_t e = first;
  for (long step = 1; step < straight + after; ++step) {
    if (t.valence(head(t, e)) != 6) return std::nullopt;
    // From the way back (+180 degrees): straight on is 3 turns.
    e = turn(t, t.twin(e), step == straight ? turns : 3);
  }
  return head(t, e);
}

}  // namespace

std::optional<int> chart_vertex(const TriangleTopology& t, std::size_t f, int corner, const ChartPoint& p) {
  const int origin = t.vertex(f, corner);
  if (p.a == 0) return origin;
  // Turning counter-clockwise round a vertex is +60 degrees in the chart.
  const int v = t.valence(origin);
  const std::uint32_t e_k = turn(t, TriangleTopology::half_edge(f, corner), p.sector % v);
  if (const auto x = walk(t, e_k, p.a - p.b, 4, p.b)) return x;
  // The other side of the parallelogram: b steps along e_{k+1}, then a - b after a right turn.
  if (p.b > 0) return walk(t, t.turn_ccw(e_k), p.b, 2, p.a - p.b);
  return std::nullopt;
}

TrianglePatch gather_triangle_patch(const TriangleTopology& t, std::size_t face, const TriangleTables& tables) {
  TrianglePatch patch;
  patch.rotation = 0;
  for (int c = 0; c < 3; ++c)
    if (t.valence(t.vertex(face, c)) != 6) {
      if (patch.valence != 6)
        throw MeshError("face " + std::to_string(face) + " has two extraordinary vertices");
      patch.valence = t.valence(t.vertex(face, c));
      patch.rotation = c;
    }
  const auto& layout = tables.layout(patch.valence);
  patch.points.reserve(layout.size());
  for (const ChartPoint& p : layout) {
    const auto v = chart_vertex(t, face, patch.rotation, p);
    if (!v)
      throw MeshError("face " + std::to_string(face) + ": another extraordinary vertex lies within its patch's reach "
                      "(the mesh was not isolated enough)");
    patch.points.push_back(*v);
  }
  return patch;
}

}  // namespace stencil_runtime
