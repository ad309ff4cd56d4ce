#include "triangle_steps.hpp"

#include <stdexcept>
#include <string>
#include <unordered_map>

namespace stencil_runtime {

namespace {

// The vertex rule at every vertex, as rows [0, nv): (1 - valence w) p + w (sum
// of the neighbours); on a boundary, `boundary`'s rules.
void relax_vertices(const TriangleTopology& topo, const TriangleTables& t, RefinementStep& step,
                    const BoundaryRules* boundary = nullptr) {
  const std::size_t nv = topo.vertices();
  // One outgoing half-edge per vertex; on the boundary, the boundary one (its fan's first).
  std::vector<std::uint32_t> first_out(nv, UINT32_MAX);
  for (std::uint32_t h = 0; h < 3 * topo.faces(); ++h) {
    const auto v = static_cast<std::size_t>(topo.vertex(TriangleTopology::face_of(h), TriangleTopology::corner_of(h)));
    if (first_out[v] == UINT32_MAX || topo.twin(h) == TriangleTopology::kNoTwin) first_out[v] = h;
  }
  SparseEntries row;
  for (std::size_t v = 0; v < nv; ++v) {
    const int valence = topo.valence(static_cast<int>(v));
    if (topo.on_boundary(static_cast<int>(v))) {
      if (!boundary) throw MeshError("internal: a Loop step on a mesh with boundaries was given no boundary rules");
      std::uint32_t e = first_out[v], last = e;
      for (; e != TriangleTopology::kNoTwin; e = topo.turn_ccw(e)) last = e;
      boundary_row(row, static_cast<std::uint32_t>(v), static_cast<std::uint32_t>(topo.head(first_out[v])),
                   static_cast<std::uint32_t>(topo.vertex(TriangleTopology::face_of(last), TriangleTopology::corner_of(last) + 2)),
                   valence, *boundary);
      step.add_row(row);
      continue;
    }
    double w = 0;
    if (!t.neighbour_weight(valence, w))
      throw MeshError("vertex " + std::to_string(v) + " has valence " + std::to_string(valence) +
                      ", for which the tables have no rule");
    row.assign(1, {static_cast<std::uint32_t>(v), 1 - valence * w});
    std::uint32_t e = first_out[v];
    do {
      row.emplace_back(static_cast<std::uint32_t>(topo.head(e)), w);
      e = topo.turn_ccw(e);
    } while (e != first_out[v]);
    step.add_row(row);
  }
}

// One sqrt(3) step: vertices [0, nv) relaxed, then the centre of face f at
// nv + f; face h (a half-edge of the input) is (start of h, centre of the face
// across h, centre of h's face): the flipped edges.
TriangleStep sqrt3_step(const TriangleTopology& topo, const TriangleTables& t) {
  const std::size_t nf = topo.faces(), nv = topo.vertices();
  TriangleStep out;
  RefinementStep step;
  step.input_vertices = nv;
  relax_vertices(topo, t, step);
  SparseEntries row;
  for (std::size_t f = 0; f < nf; ++f) {
    row.clear();
    for (int k = 0; k < 3; ++k) row.emplace_back(static_cast<std::uint32_t>(topo.vertex(f, k)), 1.0 / 3);
    step.add_row(row);
  }
  out.mesh.vertex_count = step.rows();
  out.mesh.face_sizes.assign(3 * nf, 3);
  out.mesh.face_vertices.reserve(9 * nf);
  for (std::uint32_t h = 0; h < 3 * nf; ++h) {
    const std::size_t f = TriangleTopology::face_of(h);
    out.mesh.face_vertices.insert(out.mesh.face_vertices.end(),
                                  {topo.vertex(f, TriangleTopology::corner_of(h)),
                                   static_cast<int>(nv + TriangleTopology::face_of(topo.twin(h))), static_cast<int>(nv + f)});
  }
  out.steps.push_back(std::move(step));
  return out;
}

// Face f's ternary lattice point (a, b), a + b <= 3 (a along corner 0 -> 1, b
// along 0 -> 2), as a vertex after two sqrt(3) steps: the corners stay, the
// centre is f's first-step centre, and the points a third along each edge are
// the centres of the first-step faces of its half-edges (sqrt3_step's numbering).
int ternary_vertex(const TriangleTopology& topo, std::size_t f, int a, int b) {
  const int nv = static_cast<int>(topo.vertices()), nv1 = nv + static_cast<int>(topo.faces());
  auto h = [&](int c) { return TriangleTopology::half_edge(f, c); };
  auto centre = [&](std::uint32_t half) { return nv1 + static_cast<int>(half); };
  switch (a * 4 + b) {
    case 0: return topo.vertex(f, 0);
    case 12: return topo.vertex(f, 1);
    case 3: return topo.vertex(f, 2);
    case 5: return nv + static_cast<int>(f);         // (1,1)
    case 4: return centre(h(0));                     // (1,0)
    case 8: return centre(topo.twin(h(0)));          // (2,0)
    case 9: return centre(h(1));                     // (2,1)
    case 6: return centre(topo.twin(h(1)));          // (1,2)
    case 2: return centre(h(2));                     // (0,2)
    case 1: return centre(topo.twin(h(2)));          // (0,1)
    default: throw std::logic_error("not a ternary lattice point");
  }
}

}  // namespace

const std::array<TernaryCell, 9>& ternary_cells() {
  static const std::array<TernaryCell, 9> cells{{{0, 0, false}, {1, 0, false}, {2, 0, false}, {0, 1, false}, {1, 1, false},
                                                 {0, 2, false}, {0, 0, true}, {1, 0, true}, {0, 1, true}}};
  return cells;
}

TriangleStep sqrt3_double_step(const TriangleTopology& topo, const TriangleTables& rules) {
  TriangleStep once = sqrt3_step(topo, rules);
  TriangleStep twice = sqrt3_step(TriangleTopology(once.mesh), rules);
  // The second step's faces by their directed edges (the vertex opposite each),
  // to list them cell by cell.
  std::unordered_map<std::uint64_t, int> opposite_of_edge;
  opposite_of_edge.reserve(3 * twice.mesh.face_count());
  auto key = [](int a, int b) { return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b); };
  const std::vector<int>& fv = twice.mesh.face_vertices;
  for (std::size_t f = 0; f < twice.mesh.face_count(); ++f)
    for (std::size_t c = 0; c < 3; ++c) opposite_of_edge[key(fv[3 * f + c], fv[3 * f + (c + 1) % 3])] = fv[3 * f + (c + 2) % 3];
  TriangleStep out;
  out.mesh.vertex_count = twice.mesh.vertex_count;
  out.mesh.face_sizes.assign(9 * topo.faces(), 3);
  out.mesh.face_vertices.reserve(27 * topo.faces());
  for (std::size_t f = 0; f < topo.faces(); ++f)
    for (const TernaryCell& cell : ternary_cells()) {
      const auto corners = cell.corners();
      int v[3];
      for (int k = 0; k < 3; ++k) v[k] = ternary_vertex(topo, f, corners[k][0], corners[k][1]);
      const auto it = opposite_of_edge.find(key(v[0], v[1]));
      if (it == opposite_of_edge.end() || it->second != v[2])
        throw std::logic_error("two sqrt(3) steps did not give the 1-to-9 split of face " + std::to_string(f));
      out.mesh.face_vertices.insert(out.mesh.face_vertices.end(), {v[0], v[1], v[2]});
    }
  out.steps.push_back(std::move(once.steps[0]));
  out.steps.push_back(std::move(twice.steps[0]));
  return out;
}

CurveCreaseRule triangle_crease_rule(const TriangleTables& t, const std::string& scheme, const std::string& refused) {
  if (t.refinement() == TriangleRefinement::Sqrt3)
    throw MeshError("the scheme " + scheme + " refines by sqrt(3), which splits no edges, so it has no crease rule: " + refused +
                    " are refused");
  if (!t.crease())
    throw MeshError("these " + scheme +
                    " tables carry no crease rule (the scheme names no crease_curve, or the tables predate format 5): " +
                    refused + " are refused; regenerate the tables with this stencilgen");
  return {t.crease()->centre, t.crease()->neighbour};
}

TriangleStep loop_step(const TriangleTopology& topo, const TriangleTables& t, const BoundaryRules* boundary) {
  const std::size_t nf = topo.faces(), nv = topo.vertices(), nh = 3 * nf;
  std::vector<std::uint32_t> edge_point(nh, 0);
  std::vector<std::uint32_t> edge_owner;
  for (std::uint32_t h = 0; h < nh; ++h) {
    const std::uint32_t o = topo.twin(h);
    if (o < h) {
      edge_point[h] = edge_point[o];
      continue;
    }
    edge_point[h] = static_cast<std::uint32_t>(nv + edge_owner.size());
    edge_owner.push_back(h);
  }
  TriangleStep out;
  RefinementStep step;
  step.input_vertices = nv;
  relax_vertices(topo, t, step, boundary);
  SparseEntries row;
  auto at = [&](std::size_t f, int c) { return static_cast<std::uint32_t>(topo.vertex(f, c)); };
  for (std::uint32_t h : edge_owner) {
    if (topo.twin(h) == TriangleTopology::kNoTwin) {  // a boundary edge: its midpoint
      const std::size_t f = TriangleTopology::face_of(h);
      const int c = TriangleTopology::corner_of(h);
      row.assign({{at(f, c), 0.5}, {at(f, c + 1), 0.5}});
      step.add_row(row);
      continue;
    }
    const std::size_t f = TriangleTopology::face_of(h), g = TriangleTopology::face_of(topo.twin(h));
    const int c = TriangleTopology::corner_of(h), d = TriangleTopology::corner_of(topo.twin(h));
    row.assign({{at(f, c), t.edge_end()}, {at(f, c + 1), t.edge_end()}, {at(f, c + 2), t.edge_opposite()}, {at(g, d + 2), t.edge_opposite()}});
    step.add_row(row);
  }
  out.mesh.vertex_count = step.rows();
  out.mesh.face_sizes.assign(4 * nf, 3);
  out.mesh.face_vertices.reserve(12 * nf);
  for (std::size_t f = 0; f < nf; ++f) {
    auto edge = [&](int c) { return static_cast<int>(edge_point[TriangleTopology::half_edge(f, c)]); };
    for (int c = 0; c < 3; ++c) out.mesh.face_vertices.insert(out.mesh.face_vertices.end(), {topo.vertex(f, c), edge(c), edge(c + 2)});
    out.mesh.face_vertices.insert(out.mesh.face_vertices.end(), {edge(0), edge(1), edge(2)});
  }
  out.steps.push_back(std::move(step));
  return out;
}

}  // namespace stencil_runtime
