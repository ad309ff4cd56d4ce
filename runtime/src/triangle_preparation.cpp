#include "stencil_runtime/triangle_preparation.hpp"

#include <stdexcept>

#include "stencil_runtime/triangle_patch.hpp"

namespace stencil_runtime {

namespace {

using P = std::array<double, 3>;

void axpy(P& acc, double w, const P& p) {
  for (int k = 0; k < 3; ++k) acc[k] += w * p[k];
}

// Every face has at most one extraordinary corner and its layout can be walked.
bool isolated(const TriangleTopology& topo, const TriangleTables& tables) {
  for (std::size_t f = 0; f < topo.faces(); ++f) {
    int corner = 0, extraordinary = 0;
    for (int c = 0; c < 3; ++c)
      if (topo.valence(topo.vertex(f, c)) != 6) ++extraordinary, corner = c;
    if (extraordinary > 1) return false;
    for (const ChartPoint& p : tables.layout(topo.valence(topo.vertex(f, corner))))
      if (!chart_vertex(topo, f, corner, p)) return false;
  }
  return true;
}

}  // namespace

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
  std::vector<char> done(nv, 0);
  for (std::uint32_t h = 0; h < nh; ++h) {
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
      axpy(p, w, at(TriangleTopology::face_of(e), TriangleTopology::corner_of(e) + 1));
      e = topo.turn_ccw(e);
    } while (e != h);
    out.positions[static_cast<std::size_t>(v)] = p;
  }
  out.face_sizes.assign(4 * nf, 3);
  out.face_vertices.reserve(12 * nf);
  for (std::size_t f = 0; f < nf; ++f) {
    auto edge = [&](int c) { return static_cast<int>(edge_point[TriangleTopology::half_edge(f, c)]); };
    for (int c = 0; c < 3; ++c) out.face_vertices.insert(out.face_vertices.end(), {topo.vertex(f, c), edge(c), edge(c + 2)});
    out.face_vertices.insert(out.face_vertices.end(), {edge(0), edge(1), edge(2)});
  }
  return out;
}

PreparedMesh prepare_triangle_mesh(const Mesh& mesh, const TriangleTables& tables, const std::string& scheme_name) {
  if (tables.refinement() == TriangleRefinement::Sqrt3)
    throw MeshError("sqrt(3) tables: the runtime evaluates Loop triangle meshes only so far. Around an extraordinary "
                    "vertex, sqrt(3)'s rule reaches the triangles of its second ring, and the tables hold only the "
                    "first ring's patches (docs/runtime.md)");
  PreparedMesh out{mesh, 0, {}, mesh.face_sizes};
  TriangleTopology topo(mesh);
  for (std::size_t v = 0; v < topo.vertices(); ++v) {
    const int val = topo.valence(static_cast<int>(v));
    check_valence_limit(v, val);
    if (!tables.has_valence(val)) throw missing_valence_error(v, val, scheme_name);
  }
  while (!isolated(topo, tables)) {
    if (out.steps == 3) throw MeshError("extraordinary vertices are still too close after 3 subdivision steps");
    out.add_four_way_step(loop_subdivide_once(out.mesh, topo, tables));
    topo = TriangleTopology(out.mesh);
  }
  return out;
}

FaceParameter locate_triangle(const PreparedMesh& prepared, std::size_t face, long i, long j, long n) {
  for (int s = 0; s < prepared.steps; ++s) {
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
