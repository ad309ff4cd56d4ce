#include "stencil_runtime/mesh_preparation.hpp"

#include "stencil_runtime/polygon_links.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace stencil_runtime {

Mesh subdivide_once(const Mesh& mesh, const QuadTopology& topo, const SurfaceTables& t) {
  const std::size_t nf = topo.faces(), nv = topo.vertices();
  Mesh out;
  // New points: vertex points [0, nv), face points [nv, nv + nf), edge points after.
  out.positions.resize(nv + nf);
  using P = std::array<double, 3>;
  auto axpy = [](P& acc, double w, const P& p) {
    for (int k = 0; k < 3; ++k) acc[k] += w * p[k];
  };
  for (std::size_t f = 0; f < nf; ++f) {
    P& p = out.positions[nv + f];
    p = {0, 0, 0};
    for (int c = 0; c < 4; ++c) axpy(p, t.face_corner(), mesh.positions[static_cast<std::size_t>(topo.vertex(f, c))]);
  }
  std::vector<std::uint32_t> edge_point(4 * nf, 0);
  for (std::uint32_t h = 0; h < 4 * nf; ++h) {
    const std::uint32_t o = topo.twin(h);
    if (o < h) {
      edge_point[h] = edge_point[o];
      continue;
    }
    const std::size_t f = QuadTopology::face_of(h), g = QuadTopology::face_of(o);
    const int c = QuadTopology::corner_of(h), d = QuadTopology::corner_of(o);
    P p{0, 0, 0};
    axpy(p, t.edge_end(), mesh.positions[static_cast<std::size_t>(topo.vertex(f, c))]);
    axpy(p, t.edge_end(), mesh.positions[static_cast<std::size_t>(topo.vertex(f, c + 1))]);
    for (int k : {2, 3}) {
      axpy(p, t.edge_wing(), mesh.positions[static_cast<std::size_t>(topo.vertex(f, c + k))]);
      axpy(p, t.edge_wing(), mesh.positions[static_cast<std::size_t>(topo.vertex(g, d + k))]);
    }
    edge_point[h] = static_cast<std::uint32_t>(out.positions.size());
    out.positions.push_back(p);
  }
  std::vector<char> done(nv, 0);
  for (std::uint32_t h = 0; h < 4 * nf; ++h) {
    const int v = topo.vertex(QuadTopology::face_of(h), QuadTopology::corner_of(h));
    if (done[static_cast<std::size_t>(v)]) continue;
    done[static_cast<std::size_t>(v)] = 1;
    const auto* rule = t.vertex_rule(topo.valence(v));
    if (!rule) throw MeshError("vertex " + std::to_string(v) + " has valence " + std::to_string(topo.valence(v)) + ", for which the table has no rule");
    P p{0, 0, 0};
    axpy(p, rule->centre, mesh.positions[static_cast<std::size_t>(v)]);
    std::uint32_t e = h;
    do {  // each incident face: its edge neighbour (corner + 1) and its diagonal (corner + 2)
      const std::size_t f = QuadTopology::face_of(e);
      const int c = QuadTopology::corner_of(e);
      axpy(p, rule->edge, mesh.positions[static_cast<std::size_t>(topo.vertex(f, c + 1))]);
      axpy(p, rule->face, mesh.positions[static_cast<std::size_t>(topo.vertex(f, c + 2))]);
      e = topo.twin(QuadTopology::half_edge(f, c + 3));
    } while (e != h);
    out.positions[static_cast<std::size_t>(v)] = p;
  }
  out.face_sizes.assign(4 * nf, 4);
  out.face_vertices.reserve(16 * nf);
  for (std::size_t f = 0; f < nf; ++f)
    for (int c = 0; c < 4; ++c) {
      out.face_vertices.push_back(topo.vertex(f, c));
      out.face_vertices.push_back(static_cast<int>(edge_point[QuadTopology::half_edge(f, c)]));
      out.face_vertices.push_back(static_cast<int>(nv + f));
      out.face_vertices.push_back(static_cast<int>(edge_point[QuadTopology::half_edge(f, c + 3)]));
    }
  return out;
}

namespace {
bool isolated(const QuadTopology& topo) {
  for (std::size_t f = 0; f < topo.faces(); ++f) {
    int extraordinary = 0;
    for (int c = 0; c < 4; ++c) extraordinary += topo.valence(topo.vertex(f, c)) != 4;
    if (extraordinary > 1) return false;
  }
  return true;
}
}  // namespace

Mesh subdivide_polygons(const Mesh& mesh, const SurfaceTables& t) {
  using P = std::array<double, 3>;
  const std::size_t nf = mesh.face_count(), nv = mesh.vertex_count();
  const PolygonLinks links = link_polygons(mesh);
  const auto& start = links.start;
  const auto& next = links.next;
  const auto& face_of = links.face_of;
  const auto& twin = links.twin;
  const auto& valence = links.valence;
  const std::size_t nh = start[nf];
  auto vert = [&](std::size_t h) { return mesh.face_vertices[h]; };
  Mesh out;
  out.positions.assign(nv + nf, P{0, 0, 0});
  for (std::size_t f = 0; f < nf; ++f) {  // face points: centroids
    const double w = 1.0 / mesh.face_sizes[f];
    for (std::size_t h = start[f]; h < start[f + 1]; ++h)
      for (int k = 0; k < 3; ++k) out.positions[nv + f][k] += w * mesh.positions[static_cast<std::size_t>(vert(h))][k];
  }
  std::vector<std::size_t> edge_point(nh);
  for (std::size_t h = 0; h < nh; ++h) {
    if (twin[h] < h) {
      edge_point[h] = edge_point[twin[h]];
      continue;
    }
    P p{0, 0, 0};
    const auto& a = mesh.positions[static_cast<std::size_t>(vert(h))];
    const auto& b = mesh.positions[static_cast<std::size_t>(vert(next[h]))];
    const auto& f1 = out.positions[nv + face_of[h]];
    const auto& f2 = out.positions[nv + face_of[twin[h]]];
    for (int k = 0; k < 3; ++k) p[k] = t.polygon_edge_end() * (a[k] + b[k]) + t.polygon_edge_face() * (f1[k] + f2[k]);
    edge_point[h] = out.positions.size();
    out.positions.push_back(p);
  }
  std::vector<P> mid_sum(nv, P{0, 0, 0}), face_sum(nv, P{0, 0, 0});
  for (std::size_t h = 0; h < nh; ++h) {  // each outgoing half-edge: one incident edge and one incident face
    const std::size_t v = static_cast<std::size_t>(vert(h));
    const auto& a = mesh.positions[v];
    const auto& b = mesh.positions[static_cast<std::size_t>(vert(next[h]))];
    for (int k = 0; k < 3; ++k) {
      mid_sum[v][k] += 0.5 * (a[k] + b[k]);
      face_sum[v][k] += out.positions[nv + face_of[h]][k];
    }
  }
  for (std::size_t v = 0; v < nv; ++v) {
    const auto* rule = t.polygon_vertex_rule(valence[v]);
    if (!rule) throw MeshError("vertex " + std::to_string(v) + " has valence " + std::to_string(valence[v]) + ", for which the table has no rule");
    for (int k = 0; k < 3; ++k)
      out.positions[v][k] = rule->centre * mesh.positions[v][k] + rule->edge * mid_sum[v][k] / valence[v] +
                            rule->face * face_sum[v][k] / valence[v];
  }
  out.face_sizes.assign(nh, 4);
  out.face_vertices.reserve(4 * nh);
  for (std::size_t f = 0; f < nf; ++f)
    for (std::size_t h = start[f]; h < start[f + 1]; ++h) {
      const std::size_t prev = h == start[f] ? start[f + 1] - 1 : h - 1;
      out.face_vertices.push_back(vert(h));
      out.face_vertices.push_back(static_cast<int>(edge_point[h]));
      out.face_vertices.push_back(static_cast<int>(nv + f));
      out.face_vertices.push_back(static_cast<int>(edge_point[prev]));
    }
  return out;
}

PreparedMesh prepare_mesh(const Mesh& mesh, const SurfaceTables& tables, const std::string& scheme_name) {
  PreparedMesh out{mesh, 0, {}, {}, mesh.face_sizes};
  auto missing_valence = [&](std::size_t v, int val) { return missing_valence_error(v, val, scheme_name); };
  const bool all_quads = std::all_of(mesh.face_sizes.begin(), mesh.face_sizes.end(), [](int k) { return k == 4; });
  if (!all_quads) {
    if (!tables.has_polygon_rules()) {
      const auto it = std::find_if(mesh.face_sizes.begin(), mesh.face_sizes.end(), [](int k) { return k != 4; });
      throw MeshError("face " + std::to_string(it - mesh.face_sizes.begin()) + " has " + std::to_string(*it) +
                      " vertices; this scheme's tables have no rules for polygons other than quads");
    }
    // A closed manifold first; then the valences of the polygon mesh (and of the
    // face points, whose valence is the face size) must be covered.
    const std::vector<int> valence = link_polygons(mesh).valence;
    for (std::size_t v = 0; v < valence.size(); ++v)
      if (!tables.has_valence(valence[v]) || !tables.polygon_vertex_rule(valence[v]))
        throw missing_valence(v, valence[v]);
    for (std::size_t f = 0; f < mesh.face_count(); ++f)
      if (mesh.face_sizes[f] != 4 && !tables.has_valence(mesh.face_sizes[f]))
        throw MeshError("face " + std::to_string(f) + " has " + std::to_string(mesh.face_sizes[f]) +
                        " vertices, so its centre becomes a vertex of that valence, which the tables do not cover; generate it with: stencilgen --scheme " +
                        scheme_name + " --valence " + std::to_string(mesh.face_sizes[f]) + " --n <rates> --out <dir>");
    std::vector<std::size_t> offsets(mesh.face_count() + 1, 0);
    for (std::size_t f = 0; f < mesh.face_count(); ++f) offsets[f + 1] = offsets[f] + static_cast<std::size_t>(mesh.face_sizes[f]);
    out.add_step(subdivide_polygons(mesh, tables), std::move(offsets), 2);
  }
  QuadTopology topo(out.mesh);
  for (std::size_t v = 0; v < topo.vertices(); ++v) {
    const int val = topo.valence(static_cast<int>(v));
    check_valence_limit(v, val);
    if (!tables.has_valence(val) || !tables.vertex_rule(val)) throw missing_valence(v, val);
  }
  while (!isolated(topo)) {
    if (out.steps == 3) throw MeshError("extraordinary vertices still share faces after 3 subdivision steps");
    out.add_four_way_step(subdivide_once(out.mesh, topo, tables));
    topo = QuadTopology(out.mesh);
  }
  return out;
}

FaceParameter locate(const PreparedMesh& prepared, std::size_t face, long i, long j, long n) {
  if (prepared.original_sizes.at(face) != 4)
    throw std::out_of_range("face " + std::to_string(face) + " has " + std::to_string(prepared.original_sizes[face]) +
                            " vertices: (u, v) parameters are defined for quads; its surface is that of its " +
                            std::to_string(prepared.original_sizes[face]) + " refined quads");
  for (int s = 0; s < prepared.steps; ++s) {
    // Quadrant of (i, j) in face coordinates; child c has its corner c at the
    // parent's corner c, its own u axis along the parent's edge c -> c+1.
    const bool right = 2 * i > n, top = 2 * j > n;
    const int c = !top ? (right ? 1 : 0) : (right ? 2 : 3);
    const long x = 2 * i - (right ? n : 0), y = 2 * j - (top ? n : 0);  // in the quadrant, parent-aligned
    long ci = 0, cj = 0;
    switch (c) {
      case 0: ci = x, cj = y; break;
      case 1: ci = y, cj = n - x; break;
      case 2: ci = n - x, cj = n - y; break;
      default: ci = n - y, cj = x; break;
    }
    face = prepared.child_offsets[static_cast<std::size_t>(s)][face] + static_cast<std::size_t>(c);
    i = ci, j = cj;
  }
  return {face, i, j};
}

}  // namespace stencil_runtime
