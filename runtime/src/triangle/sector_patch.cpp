#include "sector_patch.hpp"

#include <algorithm>
#include <deque>
#include <map>
#include <tuple>
#include <set>
#include <unordered_map>
#include <unordered_set>

#include "boundary_patch.hpp"

namespace stencil_runtime {

namespace {

// The coordinates of chart point w in the frame of wedge t (a turn from frame s
// to frame s-1 is the 60-degree rotation (a, b) -> (a - b, a)). On a cone
// point's closed ring of k wedges frame k is frame 0: the short way round.
std::pair<long, long> in_frame(const ChartPoint& w, int t, int k, bool closed) {
  long a = w.a, b = w.b;
  if (a == 0 && b == 0) return {0, 0};
  int turns = t - w.sector;
  if (closed) {
    turns = ((turns % k) + k) % k;
    if (2 * turns > k) turns -= k;
  }
  for (; turns < 0; ++turns) std::tie(a, b) = std::pair{a - b, a};
  for (; turns > 0; --turns) std::tie(a, b) = std::pair{b, b - a};
  return {a, b};
}

// The real chart point at (a, b) of frame s in canonical form (the generator's
// BoundaryWedge::canonical without the phantom rows): B, wedge 0..k-1 or ray
// k; on a closed ring, wedge 0..k-1.
std::optional<ChartPoint> canonical(int k, bool closed, int s, long a, long b) {
  if (a == 0 && b == 0) return ChartPoint{};
  for (int turn = 0; turn <= 6; ++turn) {
    if (closed) s = ((s % k) + k) % k;
    if (s < 0 || s > k) return std::nullopt;
    if (s == k && !closed) {
      if (a >= 1 && b == 0) return ChartPoint{s, static_cast<int>(a), 0};
      if (b >= 0) return std::nullopt;
    } else if (a >= 1 && b >= 0 && b < a) {
      return ChartPoint{s, static_cast<int>(a), static_cast<int>(b)};
    }
    if (b < 0) {
      std::tie(a, b) = std::pair{a - b, a};
      --s;
    } else {
      std::tie(a, b) = std::pair{b, b - a};
      ++s;
    }
  }
  return std::nullopt;
}

using Key = std::tuple<int, int, int>;
Key key_of(const ChartPoint& p) { return {p.sector, p.a, p.b}; }

}  // namespace

bool loop_sector_vertex(const TriangleTopology& t, int v, SectorRule rule) {
  if (rule == SectorRule::Cone) return !t.on_boundary(v);
  return t.on_boundary(v) && (rule == SectorRule::Corner || rule == SectorRule::Dart || t.valence(v) != 3);
}

std::optional<TrianglePatch> loop_sector_patch(const TriangleTopology& t, std::size_t f, int corner,
                                               const std::vector<SectorRule>& rules, const TriangleTables& tables) {
  const int b_vertex = t.vertex(f, corner);
  const int k = t.valence(b_vertex);
  // A cone point's ring is closed and every face alike: the face is position 0.
  const bool closed = rules[static_cast<std::size_t>(b_vertex)] == SectorRule::Cone;
  // e_0: clockwise round B from the face's half-edge until the boundary edge.
  std::uint32_t h = TriangleTopology::half_edge(f, corner);
  int p = 0;
  while (!closed) {
    const std::uint32_t back = t.twin(h);
    if (back == TriangleTopology::kNoTwin) break;
    h = TriangleTopology::half_edge(TriangleTopology::face_of(back), TriangleTopology::corner_of(back) + 1);
    if (++p >= k) return std::nullopt;  // not on a boundary after all
  }
  const SectorKey key{rules[static_cast<std::size_t>(b_vertex)], k, p};
  const auto code = tables.sector_code(key);
  if (!code) throw EvaluationError("the triangle tables hold no patch for a " + key.name());
  const std::vector<ChartPoint>& layout = tables.layout(*code);
  std::set<Key> wanted;
  for (const ChartPoint& q : layout) wanted.insert(key_of(q));

  // Unfold: B's fan first, then across every inner edge the lattice's
  // parallelogram rule (the vertex across edge PQ from R is P + Q - R), onto
  // the layout's points only (so that irregular vertices beyond it do not
  // matter); a vertex given two places fails.
  std::unordered_map<int, ChartPoint> place;
  std::map<Key, int> vertex_at;
  auto assign = [&](int v, const ChartPoint& q) {
    const auto [it, fresh] = place.emplace(v, q);
    if (!fresh) return key_of(it->second) == key_of(q);
    return vertex_at.emplace(key_of(q), v).second;
  };
  assign(b_vertex, ChartPoint{});
  std::unordered_set<std::size_t> seen;
  std::deque<std::size_t> queue;
  std::uint32_t e = h;
  for (int j = 0; j < k; ++j) {
    const std::size_t face = TriangleTopology::face_of(e);
    const int c = TriangleTopology::corner_of(e);
    if (!assign(t.vertex(face, c + 1), ChartPoint{j, 1, 0}) ||
        !assign(t.vertex(face, c + 2), ChartPoint{closed && j + 1 == k ? 0 : j + 1, 1, 0}))
      return std::nullopt;
    seen.insert(face);
    queue.push_back(face);
    if (j + 1 < k) {
      e = t.turn_ccw(e);
      if (e == TriangleTopology::kNoTwin) return std::nullopt;
    }
  }
  while (!queue.empty()) {
    const std::size_t face = queue.front();
    queue.pop_front();
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t across = t.twin(TriangleTopology::half_edge(face, c));
      if (across == TriangleTopology::kNoTwin) continue;
      const std::size_t g = TriangleTopology::face_of(across);
      if (seen.count(g)) continue;
      const ChartPoint& P = place.at(t.vertex(face, c));
      const ChartPoint& Q = place.at(t.vertex(face, c + 1));
      const ChartPoint& R = place.at(t.vertex(face, c + 2));
      const int frame = P.a == 0 ? Q.sector : P.sector;
      const auto [pa, pb] = in_frame(P, frame, k, closed);
      const auto [qa, qb] = in_frame(Q, frame, k, closed);
      const auto [ra, rb] = in_frame(R, frame, k, closed);
      const auto s = canonical(k, closed, frame, pa + qa - ra, pb + qb - rb);
      if (!s) return std::nullopt;  // the mesh goes on beyond the wedge: not the lattice here
      if (!wanted.count(key_of(*s))) continue;
      seen.insert(g);
      if (!assign(t.vertex(g, TriangleTopology::corner_of(across) + 2), *s)) return std::nullopt;
      queue.push_back(g);
    }
  }

  TrianglePatch patch;
  patch.valence = *code;
  patch.region = 0;
  patch.rotation = corner;
  patch.points.reserve(layout.size());
  for (std::size_t i = 0; i < layout.size(); ++i) {
    const auto it = vertex_at.find(key_of(layout[i]));
    if (it == vertex_at.end()) return std::nullopt;
    const int v = it->second;
    if (i > 0) {  // every point but B regular, on the boundary exactly where the chart's rays are
      const bool ray = !closed && layout[i].b == 0 && (layout[i].sector == 0 || layout[i].sector == k);
      if (t.on_boundary(v) != ray || !regular_loop_vertex(t, v) || rules[static_cast<std::size_t>(v)] != SectorRule::Crease)
        return std::nullopt;
    }
    patch.points.push_back(v);
  }
  return patch;
}

}  // namespace stencil_runtime
