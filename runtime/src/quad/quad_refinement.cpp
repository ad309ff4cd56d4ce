#include "quad_refinement.hpp"

#include <string>

namespace stencil_runtime {

namespace {

MeshError no_rule(int vertex, int valence) {
  return MeshError("vertex " + std::to_string(vertex) + " has valence " + std::to_string(valence) +
                   ", for which the tables have no rule");
}

MeshError no_boundary_rules() {
  return MeshError("internal: a subdivision step on a mesh with boundaries was given no boundary rules");
}

}  // namespace

QuadStep subdivide_quads(const QuadTopology& topo, const QuadTables& t, const BoundaryRules* boundary) {
  if (topo.has_boundary() && !boundary) throw no_boundary_rules();
  const std::size_t nf = topo.faces(), nv = topo.vertices();
  // Edge points are numbered after the face points, in the order of their first half-edge.
  std::vector<std::uint32_t> edge_point(4 * nf, 0);
  std::vector<std::uint32_t> edge_owner;  // the half-edge of each edge point
  for (std::uint32_t h = 0; h < 4 * nf; ++h) {
    const std::uint32_t o = topo.twin(h);
    if (o < h) {
      edge_point[h] = edge_point[o];
      continue;
    }
    edge_point[h] = static_cast<std::uint32_t>(nv + nf + edge_owner.size());
    edge_owner.push_back(h);
  }
  // One outgoing half-edge per vertex; on the boundary, the boundary one (its fan's first).
  std::vector<std::uint32_t> first_out(nv, UINT32_MAX);
  for (std::uint32_t h = 0; h < 4 * nf; ++h) {
    const auto v = static_cast<std::size_t>(topo.vertex(QuadTopology::face_of(h), QuadTopology::corner_of(h)));
    if (first_out[v] == UINT32_MAX || topo.twin(h) == QuadTopology::kNoTwin) first_out[v] = h;
  }
  QuadStep out;
  out.step.input_vertices = nv;
  auto vertex = [&](std::size_t f, int c) { return static_cast<std::uint32_t>(topo.vertex(f, c)); };
  SparseEntries row;
  for (std::size_t v = 0; v < nv; ++v) {  // vertex points: centre, edge neighbours, diagonals
    const int valence = topo.valence(static_cast<int>(v));
    if (topo.on_boundary(static_cast<int>(v))) {
      std::uint32_t e = first_out[v], last = e;
      for (; e != QuadTopology::kNoTwin; e = topo.turn_ccw(e)) last = e;
      boundary_row(row, static_cast<std::uint32_t>(v), vertex(QuadTopology::face_of(first_out[v]), QuadTopology::corner_of(first_out[v]) + 1),
                   vertex(QuadTopology::face_of(last), QuadTopology::corner_of(last) + 3), valence, *boundary);
      out.step.add_row(row);
      continue;
    }
    const auto* rule = t.vertex_rule(valence);
    if (!rule) throw no_rule(static_cast<int>(v), valence);
    row.assign(1, {static_cast<std::uint32_t>(v), rule->centre});
    std::uint32_t e = first_out[v];
    do {
      const std::size_t f = QuadTopology::face_of(e);
      const int c = QuadTopology::corner_of(e);
      row.emplace_back(vertex(f, c + 1), rule->edge);
      row.emplace_back(vertex(f, c + 2), rule->face);
      e = topo.turn_ccw(e);
    } while (e != first_out[v]);
    out.step.add_row(row);
  }
  for (std::size_t f = 0; f < nf; ++f) {  // face points
    row.clear();
    for (int c = 0; c < 4; ++c) row.emplace_back(vertex(f, c), t.face_corner());
    out.step.add_row(row);
  }
  for (std::uint32_t h : edge_owner) {  // edge points: both ends, and the other corners of both faces
    const std::size_t f = QuadTopology::face_of(h);
    const int c = QuadTopology::corner_of(h);
    if (topo.twin(h) == QuadTopology::kNoTwin) {  // a boundary edge: its midpoint
      row.assign({{vertex(f, c), 0.5}, {vertex(f, c + 1), 0.5}});
      out.step.add_row(row);
      continue;
    }
    const std::size_t g = QuadTopology::face_of(topo.twin(h));
    const int d = QuadTopology::corner_of(topo.twin(h));
    row.assign({{vertex(f, c), t.edge_end()}, {vertex(f, c + 1), t.edge_end()}});
    for (int k : {2, 3}) {
      row.emplace_back(vertex(f, c + k), t.edge_wing());
      row.emplace_back(vertex(g, d + k), t.edge_wing());
    }
    out.step.add_row(row);
  }
  out.mesh.vertex_count = out.step.rows();
  out.mesh.face_sizes.assign(4 * nf, 4);
  out.mesh.face_vertices.reserve(16 * nf);
  for (std::size_t f = 0; f < nf; ++f)
    for (int c = 0; c < 4; ++c) {
      out.mesh.face_vertices.push_back(topo.vertex(f, c));
      out.mesh.face_vertices.push_back(static_cast<int>(edge_point[QuadTopology::half_edge(f, c)]));
      out.mesh.face_vertices.push_back(static_cast<int>(nv + f));
      out.mesh.face_vertices.push_back(static_cast<int>(edge_point[QuadTopology::half_edge(f, c + 3)]));
    }
  return out;
}

QuadStep subdivide_polygons(const Connectivity& mesh, const PolygonLinks& links, const QuadTables& t, bool smooth_triangles,
                            const BoundaryRules* boundary) {
  if (links.has_boundary && !boundary) throw no_boundary_rules();
  const std::size_t nf = mesh.face_count(), nv = mesh.vertex_count;
  const auto& start = links.start;
  const std::size_t nh = start[nf];
  auto vert = [&](std::size_t h) { return static_cast<std::uint32_t>(mesh.face_vertices[h]); };
  auto size_of = [&](std::size_t f) { return static_cast<double>(mesh.face_sizes[f]); };
  std::vector<std::size_t> edge_point(nh);
  std::vector<std::size_t> edge_owner;
  for (std::size_t h = 0; h < nh; ++h) {
    if (links.twin[h] < h) {
      edge_point[h] = edge_point[links.twin[h]];
      continue;
    }
    edge_point[h] = nv + nf + edge_owner.size();
    edge_owner.push_back(h);
  }
  // Every outgoing half-edge of a vertex: one incident edge and one incident face.
  std::vector<std::vector<std::size_t>> outgoing(nv);
  for (std::size_t h = 0; h < nh; ++h) outgoing[vert(h)].push_back(h);
  QuadStep out;
  out.step.input_vertices = nv;
  SparseEntries row;
  // A face point (the centroid) with weight w, spread over the face's corners.
  auto add_face_point = [&](std::size_t f, double w) {
    for (std::size_t h = start[f]; h < start[f + 1]; ++h) row.emplace_back(vert(h), w / size_of(f));
  };
  for (std::size_t v = 0; v < nv; ++v) {
    const int valence = links.valence[v];
    if (links.has_boundary && links.boundary[v]) {
      // Its outgoing boundary half-edge leads to one neighbour; the incoming one
      // (the half-edge before an outgoing one, without a twin) comes from the other.
      std::uint32_t after = 0, before = 0;
      for (std::size_t h : outgoing[v]) {
        if (links.twin[h] == PolygonLinks::kNoTwin) after = vert(links.next[h]);
        const std::size_t f = links.face_of[h], prev = h == start[f] ? start[f + 1] - 1 : h - 1;
        if (links.twin[prev] == PolygonLinks::kNoTwin) before = vert(prev);
      }
      boundary_row(row, static_cast<std::uint32_t>(v), after, before, valence, *boundary);
      out.step.add_row(row);
      continue;
    }
    const auto* rule = t.polygon_vertex_rule(valence);
    if (!rule) throw no_rule(static_cast<int>(v), valence);
    // centre * v + edge * mean of the edge midpoints + face * mean of the face points.
    row.assign(1, {static_cast<std::uint32_t>(v), rule->centre});
    for (std::size_t h : outgoing[v]) {
      row.emplace_back(static_cast<std::uint32_t>(v), 0.5 * rule->edge / valence);
      row.emplace_back(vert(links.next[h]), 0.5 * rule->edge / valence);
      add_face_point(links.face_of[h], rule->face / valence);
    }
    out.step.add_row(row);
  }
  for (std::size_t f = 0; f < nf; ++f) {
    row.clear();
    add_face_point(f, 1.0);
    out.step.add_row(row);
  }
  for (std::size_t h : edge_owner) {  // both ends and both face points
    if (links.twin[h] == PolygonLinks::kNoTwin) {  // a boundary edge: its midpoint
      row.assign({{vert(h), 0.5}, {vert(links.next[h]), 0.5}});
      out.step.add_row(row);
      continue;
    }
    const std::size_t f = links.face_of[h], g = links.face_of[links.twin[h]];
    double end = t.polygon_edge_end(), face = t.polygon_edge_face();
    if (smooth_triangles && (mesh.face_sizes[f] == 3 || mesh.face_sizes[g] == 3)) {
      // OpenSubdiv's constant (Sdc's CATMARK_SMOOTH_TRI_EDGE_WEIGHT), in its order of operations.
      auto weight = [&](std::size_t k) { return mesh.face_sizes[k] == 3 ? 0.470 : 0.25; };
      face = 0.5 * (weight(f) + weight(g));
      end = 0.5 * (1.0 - 2.0 * face);
    }
    row.assign({{vert(h), end}, {vert(links.next[h]), end}});
    add_face_point(f, face);
    add_face_point(g, face);
    out.step.add_row(row);
  }
  out.mesh.vertex_count = out.step.rows();
  out.mesh.face_sizes.assign(nh, 4);
  out.mesh.face_vertices.reserve(4 * nh);
  for (std::size_t f = 0; f < nf; ++f)
    for (std::size_t h = start[f]; h < start[f + 1]; ++h) {
      const std::size_t prev = h == start[f] ? start[f + 1] - 1 : h - 1;
      out.mesh.face_vertices.push_back(static_cast<int>(vert(h)));
      out.mesh.face_vertices.push_back(static_cast<int>(edge_point[h]));
      out.mesh.face_vertices.push_back(static_cast<int>(nv + f));
      out.mesh.face_vertices.push_back(static_cast<int>(edge_point[prev]));
    }
  return out;
}

}  // namespace stencil_runtime
