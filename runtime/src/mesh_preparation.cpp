#include "stencil_runtime/mesh_preparation.hpp"

#include <string>
#include <unordered_map>

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

PreparedMesh prepare_mesh(const Mesh& mesh, const SurfaceTables& tables, const std::string& scheme_name) {
  QuadTopology topo(mesh);
  for (std::size_t v = 0; v < topo.vertices(); ++v) {
    const int val = topo.valence(static_cast<int>(v));
    if (val > 64) throw MeshError("vertex " + std::to_string(v) + " has valence " + std::to_string(val) + "; the runtime supports valences up to 64");
    if (!tables.has_valence(val) || !tables.vertex_rule(val))
      throw MeshError("vertex " + std::to_string(v) + " has valence " + std::to_string(val) +
                      ", which the tables do not cover; generate it with: stencilgen --scheme " + scheme_name +
                      " --valence " + std::to_string(val) + " --n <rates> --out <dir>");
  }
  PreparedMesh out{mesh, 0};
  while (!isolated(topo)) {
    if (out.steps == 3) throw MeshError("extraordinary vertices still share faces after 3 subdivision steps");
    out.mesh = subdivide_once(out.mesh, topo, tables);
    ++out.steps;
    topo = QuadTopology(out.mesh);
  }
  return out;
}

FaceParameter locate(std::size_t face, long i, long j, long n, int steps) {
  for (int s = 0; s < steps; ++s) {
    // Quadrant of (i, j) in face coordinates; child c has its corner c at the
    // parent's corner c, its own u axis along the parent's edge c -> c+1.
    const bool right = 2 * i > n, top = 2 * j > n;
    const int c = !top ? (right ? 1 : 0) : (right ? 2 : 3);
    const long x = 2 * i - (right ? n : 0), y = 2 * j - (top ? n : 0);  // in the quadrant, parent-aligned
    // Rotate parent-aligned quadrant coordinates into the child's frame.
    long ci = 0, cj = 0;
    switch (c) {
      case 0: ci = x, cj = y; break;
      case 1: ci = y, cj = n - x; break;
      case 2: ci = n - x, cj = n - y; break;
      default: ci = n - y, cj = x; break;
    }
    face = 4 * face + static_cast<std::size_t>(c);
    i = ci, j = cj;
  }
  return {face, i, j};
}

}  // namespace stencil_runtime
