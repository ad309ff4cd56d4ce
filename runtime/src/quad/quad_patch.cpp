#include "quad_patch.hpp"

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

QuadPatch gather_quad_patch(const QuadTopology& topo, std::size_t face) {
  QuadPatch p;
  int ev = -1;
  for (int c = 0; c < 4; ++c)
    if (topo.valence(topo.vertex(face, c)) != 4) {
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
  p.valence = v;
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

}  // namespace stencil_runtime
