#include "quad_patch.hpp"

#include <map>
#include <optional>
#include <string>

namespace stencil_runtime {

namespace {

// A quad of the mesh seen as the unit cell of a local grid: corner k of the
// face is the cell's lower-left, k+1 lower-right, k+2 upper-right, k+3 upper-left.
// Valid while the crossed edges' endpoints are regular (valence 4).
struct Cell {
  const QuadTopology* topo;
  std::size_t face;
  int k;
  int ll() const { return topo->vertex(face, k); }
  int lr() const { return topo->vertex(face, k + 1); }
  int ur() const { return topo->vertex(face, k + 2); }
  int ul() const { return topo->vertex(face, k + 3); }
  Cell across(int from, int offset) const {  // the cell across the edge from corner k+from to k+from+1
    const std::uint32_t t = topo->twin(QuadTopology::half_edge(face, k + from));
    return {topo, QuadTopology::face_of(t), QuadTopology::corner_of(t) + offset};
  }
  Cell right() const { return across(1, 1); }
  Cell up() const { return across(2, 0); }
  Cell left() const { return across(3, -1 + 4); }
  Cell down() const { return across(0, -2 + 4); }
};

}  // namespace

bool regular_inside(const QuadTopology& topo, int vertex, const std::vector<SectorRule>& rule) {
  return topo.valence(vertex) == 4 && rule[static_cast<std::size_t>(vertex)] != SectorRule::Cone;
}

QuadPatch gather_quad_patch(const QuadTopology& topo, std::size_t face, const std::vector<SectorRule>& rule) {
  QuadPatch p;
  int ev = -1;
  for (int c = 0; c < 4; ++c)
    if (!regular_inside(topo, topo.vertex(face, c), rule)) {
      if (ev >= 0) throw MeshError("face " + std::to_string(face) + " has two extraordinary vertices");
      ev = c;
    }
  if (ev < 0) {  // regular: the 16 points (i, j), i, j in {-1..2}, row by row
    p.valence = 4;
    p.rotation = 0;
    p.points.assign(16, -1);
    const Cell c0{&topo, face, 0};
    const Cell rows[3] = {c0.down(), c0, c0.up()};
    for (int r = 0; r < 3; ++r) {
      const Cell cells[3] = {rows[r].left(), rows[r], rows[r].right()};
      for (int s = 0; s < 3; ++s) {  // cell with lower-left (s-1, r-1)
        const int i = s - 1, j = r - 1;
        p.points[static_cast<std::size_t>((j + 1) * 4 + (i + 1))] = cells[s].ll();
        p.points[static_cast<std::size_t>((j + 1) * 4 + (i + 2))] = cells[s].lr();
        p.points[static_cast<std::size_t>((j + 2) * 4 + (i + 2))] = cells[s].ur();
        p.points[static_cast<std::size_t>((j + 2) * 4 + (i + 1))] = cells[s].ul();
      }
    }
    return p;
  }
  const int v = topo.valence(topo.vertex(face, ev));
  // A cone point's patch has the interior layout (at valence 4 too) and its own kind.
  p.valence = rule[static_cast<std::size_t>(topo.vertex(face, ev))] == SectorRule::Cone ? sector_kind({SectorRule::Cone, v, 0}) : v;
  p.rotation = ev;
  p.points.assign(static_cast<std::size_t>(2 * v + 8), -1);
  p.points[0] = topo.vertex(face, ev);
  // Sectors counter-clockwise: sector s is the quad (EV, e_s, f_s, e_{s+1}).
  Cell sector{&topo, face, ev};
  for (int s = 0; s < v; ++s) {
    p.points[static_cast<std::size_t>(1 + 2 * s)] = sector.lr();
    p.points[static_cast<std::size_t>(2 + 2 * s)] = sector.ur();
    const std::uint32_t t = topo.twin(QuadTopology::half_edge(sector.face, sector.k + 3));
    sector = {&topo, QuadTopology::face_of(t), QuadTopology::corner_of(t)};
  }
  const Cell c0{&topo, face, ev};
  const Cell r = c0.right(), ru = r.up(), rd = r.down(), u = c0.up(), ul = u.left();
  const std::size_t o = static_cast<std::size_t>(2 * v + 1);
  p.points[o + 0] = rd.lr();  // (2,-1)
  p.points[o + 1] = r.lr();   // (2,0)
  p.points[o + 2] = r.ur();   // (2,1)
  p.points[o + 3] = ru.ur();  // (2,2)
  p.points[o + 4] = ru.ul();  // (1,2)
  p.points[o + 5] = u.ul();   // (0,2)
  p.points[o + 6] = ul.ul();  // (-1,2)
  return p;
}

namespace {

// The cell across edge `from` (k+from -> k+from+1) of a cell, if the edge is not on the boundary.
std::optional<Cell> across(const std::optional<Cell>& c, int from, int offset) {
  if (!c) return std::nullopt;
  if (c->topo->twin(QuadTopology::half_edge(c->face, c->k + from)) == QuadTopology::kNoTwin) return std::nullopt;
  return c->across(from, offset);
}

}  // namespace

bool boundary_patch_ready(const QuadTopology& topo, std::size_t face, const std::vector<SectorRule>& rule) {
  int boundary_edges = 0;
  for (int c = 0; c < 4; ++c) boundary_edges += topo.twin(QuadTopology::half_edge(face, c)) == QuadTopology::kNoTwin;
  if (boundary_edges == 0 || boundary_edges > 2) return false;
  // Two boundary edges must meet at a corner in one face: edges c-1 and c, corner c.
  int corner_at = -1;
  if (boundary_edges == 2) {
    int c = -1;
    for (int k = 0; k < 4; ++k)
      if (topo.twin(QuadTopology::half_edge(face, k)) == QuadTopology::kNoTwin &&
          topo.twin(QuadTopology::half_edge(face, k + 3)) == QuadTopology::kNoTwin)
        c = k;
    if (c < 0 || rule[static_cast<std::size_t>(topo.vertex(face, c))] != SectorRule::Corner || topo.valence(topo.vertex(face, c)) != 1)
      return false;
    corner_at = c;
  }
  for (int c = 0; c < 4; ++c) {
    const int v = topo.vertex(face, c);
    if (c == corner_at) continue;
    if (topo.on_boundary(v)) {
      if (topo.valence(v) != 2 || rule[static_cast<std::size_t>(v)] != SectorRule::Crease) return false;
      // A boundary corner must lie on one of the face's boundary edges.
      const bool on_edge = topo.twin(QuadTopology::half_edge(face, c)) == QuadTopology::kNoTwin ||
                           topo.twin(QuadTopology::half_edge(face, c + 3)) == QuadTopology::kNoTwin;
      if (!on_edge) return false;
    } else if (!regular_inside(topo, v, rule)) {
      return false;
    }
  }
  return true;
}

QuadPatch gather_boundary_patch(const QuadTopology& topo, std::size_t face, std::size_t first_phantom,
                                std::vector<std::vector<std::pair<int, double>>>& phantoms) {
  QuadPatch p;
  p.valence = 4;
  p.rotation = 0;
  p.points.assign(16, -1);
  const std::optional<Cell> c0 = Cell{&topo, face, 0};
  const std::optional<Cell> rows[3] = {across(c0, 0, 2), c0, across(c0, 2, 0)};
  auto at = [&](int i, int j) -> int& { return p.points[static_cast<std::size_t>((j + 1) * 4 + (i + 1))]; };
  for (int r = 0; r < 3; ++r) {
    const std::optional<Cell> cells[3] = {across(rows[r], 3, 3), rows[r], across(rows[r], 1, 1)};
    for (int s = 0; s < 3; ++s) {
      if (!cells[s]) continue;
      const int i = s - 1, j = r - 1;
      at(i, j) = cells[s]->ll(), at(i + 1, j) = cells[s]->lr(), at(i + 1, j + 1) = cells[s]->ur(), at(i, j + 1) = cells[s]->ul();
    }
  }
  // Missing points as rows over mesh vertices: first the missing rows (j = -1
  // or 2) by reflection through the boundary row, then the missing columns
  // (which may reflect phantoms: the corner's point 4 p00 - 2 p10 - 2 p01 + p11).
  std::map<int, std::map<int, double>> rows_of;  // (j+1)*4+(i+1) -> entries
  auto entries = [&](int i, int j) {
    const int h = (j + 1) * 4 + (i + 1);
    if (rows_of.count(h)) return rows_of[h];
    return std::map<int, double>{{at(i, j), 1.0}};
  };
  auto reflect = [&](int i, int j, int si, int sj, int ti, int tj) {  // (i,j) = 2 (si,sj) - (ti,tj)
    std::map<int, double> e;
    for (const auto& [v, w] : entries(si, sj)) e[v] += 2 * w;
    for (const auto& [v, w] : entries(ti, tj)) e[v] -= w;
    rows_of[(j + 1) * 4 + (i + 1)] = e;
  };
  const bool row_low = at(0, -1) < 0, row_high = at(0, 2) < 0, col_low = at(-1, 0) < 0, col_high = at(2, 0) < 0;
  for (int i = -1; i <= 2; ++i) {
    if (row_low && at(i, 0) >= 0 && at(i, 1) >= 0) reflect(i, -1, i, 0, i, 1);
    if (row_high && at(i, 1) >= 0 && at(i, 0) >= 0) reflect(i, 2, i, 1, i, 0);
  }
  for (int j = -1; j <= 2; ++j) {
    if (col_low && at(-1, j) < 0) reflect(-1, j, 0, j, 1, j);
    if (col_high && at(2, j) < 0) reflect(2, j, 1, j, 0, j);
  }
  for (int h = 0; h < 16; ++h) {
    if (p.points[static_cast<std::size_t>(h)] >= 0) continue;
    const auto it = rows_of.find(h);
    if (it == rows_of.end()) throw MeshError("internal: face " + std::to_string(face) + " has no point " + std::to_string(h) + " of its boundary patch");
    p.points[static_cast<std::size_t>(h)] = static_cast<int>(first_phantom + phantoms.size());
    phantoms.emplace_back(it->second.begin(), it->second.end());
  }
  return p;
}

bool sector_vertex(const QuadTopology& topo, int v, const std::vector<SectorRule>& rule) {
  if (!topo.on_boundary(v)) return false;
  const int k = topo.valence(v);
  const SectorRule r = rule[static_cast<std::size_t>(v)];
  return !(k == 2 && r == SectorRule::Crease) && !(k == 1 && r == SectorRule::Corner);
}

bool sector_patch_ready(const QuadTopology& topo, std::size_t face, int at, const std::vector<SectorRule>& rule) {
  const int corner = at;
  auto boundary_edge = [&](int c) { return topo.twin(QuadTopology::half_edge(face, c)) == QuadTopology::kNoTwin; };
  for (int d = 1; d <= 3; ++d) {
    const int v = topo.vertex(face, corner + d);
    if (!topo.on_boundary(v)) {
      if (!regular_inside(topo, v, rule)) return false;
    } else {
      // e_p (d = 1) on the edge corner -> corner+1, e_{p+1} (d = 3) on corner+3 -> corner; f_p never.
      const bool on_edge = (d == 1 && boundary_edge(corner)) || (d == 3 && boundary_edge(corner + 3));
      if (!on_edge || topo.valence(v) != 2 || rule[static_cast<std::size_t>(v)] != SectorRule::Crease) return false;
    }
  }
  return true;
}

QuadPatch gather_sector_patch(const QuadTopology& topo, std::size_t face, int corner, const std::vector<SectorRule>& rule) {
  const int b = topo.vertex(face, corner);
  // Clockwise to the sector's first face (the one on the boundary edge B-e_0): its position is p.
  Cell first{&topo, face, corner};
  int p = 0;
  for (;;) {
    const std::uint32_t t = topo.twin(QuadTopology::half_edge(first.face, first.k));
    if (t == QuadTopology::kNoTwin) break;
    first = {&topo, QuadTopology::face_of(t), QuadTopology::corner_of(t) + 1};
    if (++p > topo.valence(b)) throw MeshError("internal: vertex " + std::to_string(b) + " has no boundary edge");
  }
  const int k = topo.valence(b);
  const SectorKey key{rule[static_cast<std::size_t>(b)], k, p};
  QuadPatch out;
  out.valence = sector_kind(key);
  out.rotation = corner;
  out.points.assign(static_cast<std::size_t>(key.points()), -1);
  out.points[0] = b;
  // Counter-clockwise: face s is (B, e_s, f_s, e_{s+1}).
  Cell sector = first;
  for (int s = 0; s < k; ++s) {
    out.points[static_cast<std::size_t>(1 + s)] = sector.lr();
    out.points[static_cast<std::size_t>(k + 2 + s)] = sector.ur();
    if (s + 1 == k) {
      out.points[static_cast<std::size_t>(1 + k)] = sector.ul();
      break;
    }
    const std::uint32_t t = topo.twin(QuadTopology::half_edge(sector.face, sector.k + 3));
    if (t == QuadTopology::kNoTwin) throw MeshError("internal: vertex " + std::to_string(b) + " has fewer faces than its valence");
    sector = {&topo, QuadTopology::face_of(t), QuadTopology::corner_of(t)};
  }
  // The outer points of the face's chart that exist (boundary_sector.hpp's order).
  const Cell c0{&topo, face, corner};
  const Cell r = c0.right(), ru = r.up(), u = c0.up();
  std::size_t o = static_cast<std::size_t>(2 * k + 2);
  if (p > 0) out.points[o++] = r.down().lr();  // (2,-1)
  out.points[o++] = r.lr();                    // (2,0)
  out.points[o++] = r.ur();                    // (2,1)
  out.points[o++] = ru.ur();                   // (2,2)
  out.points[o++] = ru.ul();                   // (1,2)
  out.points[o++] = u.ul();                    // (0,2)
  if (p + 1 < k) out.points[o++] = u.left().ul();  // (-1,2)
  if (o != out.points.size()) throw MeshError("internal: boundary sector patch of face " + std::to_string(face) + " is incomplete");
  return out;
}

}  // namespace stencil_runtime
