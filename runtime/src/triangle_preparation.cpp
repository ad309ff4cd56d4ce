#include "stencil_runtime/triangle_preparation.hpp"

#include <stdexcept>
#include <unordered_map>


namespace stencil_runtime {

namespace {

using P = std::array<double, 3>;

void axpy(P& acc, double w, const P& p) {
  for (int k = 0; k < 3; ++k) acc[k] += w * p[k];
}

// Every face's patch, or false when one cannot be gathered.
bool gather_patches(const TriangleTopology& topo, const TriangleTables& tables, std::vector<TrianglePatch>& patches) {
  patches.clear();
  patches.reserve(topo.faces());
  for (std::size_t f = 0; f < topo.faces(); ++f) {
    auto patch = find_triangle_patch(topo, f, tables);
    if (!patch) return false;
    patches.push_back(std::move(*patch));
  }
  return true;
}

// The vertex rule at every vertex: (1 - valence w) p + w (sum of the neighbours).
void relax_vertices(const Mesh& mesh, const TriangleTopology& topo, const TriangleTables& t, Mesh& out) {
  std::vector<char> done(topo.vertices(), 0);
  for (std::uint32_t h = 0; h < 3 * topo.faces(); ++h) {
    const int v = topo.vertex(TriangleTopology::face_of(h), TriangleTopology::corner_of(h));
    if (done[static_cast<std::size_t>(v)]) continue;
    done[static_cast<std::size_t>(v)] = 1;
    const int valence = topo.valence(v);
    double w = 0;
    if (!t.neighbour_weight(valence, w))
      throw MeshError("vertex " + std::to_string(v) + " has valence " + std::to_string(valence) +
                      ", for which the table has no rule");
    P p{0, 0, 0};
    axpy(p, 1 - valence * w, mesh.positions[static_cast<std::size_t>(v)]);
    std::uint32_t e = h;
    do {
      axpy(p, w, mesh.positions[static_cast<std::size_t>(topo.vertex(TriangleTopology::face_of(e), TriangleTopology::corner_of(e) + 1))]);
      e = topo.turn_ccw(e);
    } while (e != h);
    out.positions[static_cast<std::size_t>(v)] = p;
  }
}

// One sqrt(3) step: vertices [0, nv) relaxed, then the centre of face f at nv + f;
// face h (a half-edge of the input) is (start of h, centre of the face across
// h, centre of h's face): the flipped edges.
Mesh sqrt3_step(const Mesh& mesh, const TriangleTopology& topo, const TriangleTables& t) {
  const std::size_t nf = topo.faces(), nv = topo.vertices();
  Mesh out;
  out.positions.resize(nv + nf);
  relax_vertices(mesh, topo, t, out);
  for (std::size_t f = 0; f < nf; ++f) {
    P c{0, 0, 0};
    for (int k = 0; k < 3; ++k) axpy(c, 1.0 / 3, mesh.positions[static_cast<std::size_t>(topo.vertex(f, k))]);
    out.positions[nv + f] = c;
  }
  out.face_sizes.assign(3 * nf, 3);
  out.face_vertices.reserve(9 * nf);
  for (std::uint32_t h = 0; h < 3 * nf; ++h) {
    const std::size_t f = TriangleTopology::face_of(h);
    out.face_vertices.insert(out.face_vertices.end(),
                             {topo.vertex(f, TriangleTopology::corner_of(h)),
                              static_cast<int>(nv + TriangleTopology::face_of(topo.twin(h))), static_cast<int>(nv + f)});
  }
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

Mesh sqrt3_subdivide_twice(const Mesh& mesh, const TriangleTopology& topo, const TriangleTables& rules) {
  const Mesh once = sqrt3_step(mesh, topo, rules);
  const Mesh twice = sqrt3_step(once, TriangleTopology(once), rules);
  // The second step's faces by their directed edges (the vertex opposite each),
  // to list them cell by cell.
  std::unordered_map<std::uint64_t, int> opposite_of_edge;
  opposite_of_edge.reserve(3 * twice.face_count());
  auto key = [](int a, int b) { return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b); };
  const std::vector<int>& fv = twice.face_vertices;
  for (std::size_t f = 0; f < twice.face_count(); ++f)
    for (std::size_t c = 0; c < 3; ++c) opposite_of_edge[key(fv[3 * f + c], fv[3 * f + (c + 1) % 3])] = fv[3 * f + (c + 2) % 3];
  Mesh out;
  out.positions = twice.positions;
  out.face_sizes.assign(9 * topo.faces(), 3);
  out.face_vertices.reserve(27 * topo.faces());
  for (std::size_t f = 0; f < topo.faces(); ++f)
    for (const TernaryCell& cell : ternary_cells()) {
      const auto corners = cell.corners();
      int v[3];
      for (int k = 0; k < 3; ++k) v[k] = ternary_vertex(topo, f, corners[k][0], corners[k][1]);
      const auto it = opposite_of_edge.find(key(v[0], v[1]));
      if (it == opposite_of_edge.end() || it->second != v[2])
        throw std::logic_error("two sqrt(3) steps did not give the 1-to-9 split of face " + std::to_string(f));
      out.face_vertices.insert(out.face_vertices.end(), {v[0], v[1], v[2]});
    }
  return out;
}

Mesh loop_subdivide_once(const Mesh& mesh, const TriangleTopology& topo, const TriangleTables& t) {
  const std::size_t nf = topo.faces(), nv = topo.vertices(), nh = 3 * nf;
  Mesh out;
  // New points: vertex points [0, nv), then one edge point per edge.
  out.positions.resize(nv);
  auto at = [&](std::size_t f, int c) -> const P& { return mesh.positions[static_cast<std::size_t>(topo.vertex(f, c))]; };
  std::vector<std::uint32_t> edge_point(nh, 0);
  for (std::uint32_t h = 0; h < nh; ++h) {
    const std::uint32_t o = topo.twin(h);
    if (o < h) {
      edge_point[h] = edge_point[o];
      continue;
    }
    const std::size_t f = TriangleTopology::face_of(h), g = TriangleTopology::face_of(o);
    const int c = TriangleTopology::corner_of(h), d = TriangleTopology::corner_of(o);
    P p{0, 0, 0};
    axpy(p, t.edge_end(), at(f, c));
    axpy(p, t.edge_end(), at(f, c + 1));
    axpy(p, t.edge_opposite(), at(f, c + 2));
    axpy(p, t.edge_opposite(), at(g, d + 2));
    edge_point[h] = static_cast<std::uint32_t>(out.positions.size());
    out.positions.push_back(p);
  }
  relax_vertices(mesh, topo, t, out);
  out.face_sizes.assign(4 * nf, 3);
  out.face_vertices.reserve(12 * nf);
  for (std::size_t f = 0; f < nf; ++f) {
    auto edge = [&](int c) { return static_cast<int>(edge_point[TriangleTopology::half_edge(f, c)]); };
    for (int c = 0; c < 3; ++c) out.face_vertices.insert(out.face_vertices.end(), {topo.vertex(f, c), edge(c), edge(c + 2)});
    out.face_vertices.insert(out.face_vertices.end(), {edge(0), edge(1), edge(2)});
  }
  return out;
}

PreparedTriangleMesh prepare_triangle_mesh(const Mesh& mesh, const TriangleTables& tables, const std::string& scheme_name) {
  PreparedMesh out{mesh, 0, {}, {}, mesh.face_sizes};
  TriangleTopology topo(mesh);
  std::vector<TrianglePatch> patches;
  for (std::size_t v = 0; v < topo.vertices(); ++v) {
    const int val = topo.valence(static_cast<int>(v));
    check_valence_limit(v, val);
    if (!tables.has_valence(val)) throw missing_valence_error(v, val, scheme_name);
  }
  const bool sqrt3 = tables.refinement() == TriangleRefinement::Sqrt3;
  while (!gather_patches(topo, tables, patches)) {
    if (out.steps == 3)
      throw MeshError(std::string("extraordinary vertices are still too close after 3 ") +
                      (sqrt3 ? "double sqrt(3) steps" : "subdivision steps"));
    if (sqrt3) out.add_uniform_step(sqrt3_subdivide_twice(out.mesh, topo, tables), 9, 3);
    else out.add_four_way_step(loop_subdivide_once(out.mesh, topo, tables));
    topo = TriangleTopology(out.mesh);
  }
  return {std::move(out), std::move(topo), std::move(patches)};
}

FaceParameter locate_triangle(const PreparedMesh& prepared, std::size_t face, long i, long j, long n) {
  for (int s = 0; s < prepared.steps; ++s) {
    if (prepared.step_scales[static_cast<std::size_t>(s)] == 3) {
      // Cell coordinates (3i, 3j) on n: the first of the nine cells that holds them.
      const long x = 3 * i, y = 3 * j;
      int c = 0;
      for (const TernaryCell& cell : ternary_cells()) {
        long ci = 0, cj = 0;
        if (cell.down) ci = x + y - (cell.a + cell.b + 1) * n, cj = (cell.a + 1) * n - x;
        else ci = x - cell.a * n, cj = y - cell.b * n;
        if (ci >= 0 && cj >= 0 && ci + cj <= n) {
          i = ci, j = cj;
          break;
        }
        ++c;
      }
      face = prepared.child_offsets[static_cast<std::size_t>(s)][face] + static_cast<std::size_t>(c);
      continue;
    }
    // Barycentric coordinates times 2n: (k, a, b) on corners 0, 1, 2. The child
    // at corner c holds the points where corner c's weight is at least 1/2.
    const long a = 2 * i, b = 2 * j, k = 2 * n - a - b;
    int c;
    long ci, cj;
    if (k >= n) c = 0, ci = a, cj = b;
    else if (a >= n) c = 1, ci = b, cj = k;
    else if (b >= n) c = 2, ci = k, cj = a;
    else c = 3, ci = n - k, cj = n - a;  // middle child: corners at the midpoints of edges 0, 1, 2
    face = prepared.child_offsets[static_cast<std::size_t>(s)][face] + static_cast<std::size_t>(c);
    i = ci, j = cj;
  }
  return {face, i, j};
}

}  // namespace stencil_runtime
