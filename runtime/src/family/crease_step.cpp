#include "crease_step.hpp"

#include <cmath>
#include <map>
#include <string>

#include "stencil_runtime/limits.hpp"

namespace stencil_runtime {

namespace {

// a * x + b * y, merged.
SparseEntries blend(double a, const SparseEntries& x, double b, const SparseEntries& y) {
  SparseEntries out;
  out.reserve(x.size() + y.size());
  for (const auto& [c, w] : x) out.emplace_back(c, a * w);
  for (const auto& [c, w] : y) out.emplace_back(c, b * w);
  merge_entries(out);
  return out;
}

SparseEntries row_of(const RefinementStep& step, std::size_t r) {
  SparseEntries out;
  for (std::size_t e = step.offsets[r]; e != step.offsets[r + 1]; ++e) out.emplace_back(step.columns[e], step.weights[e]);
  return out;
}

// The step with some rows replaced.
RefinementStep replaced(const RefinementStep& step, std::map<std::size_t, SparseEntries>& rows) {
  RefinementStep out;
  out.input_vertices = step.input_vertices;
  out.columns.reserve(step.columns.size());
  out.weights.reserve(step.weights.size());
  for (std::size_t r = 0; r < step.rows(); ++r) {
    SparseEntries row;
    const auto it = rows.find(r);
    row = it != rows.end() ? std::move(it->second) : row_of(step, r);
    out.add_row(row);
  }
  return out;
}

// The vertex mask of one rule at vertex v (Smooth and Dart: the step's own row).
SparseEntries vertex_mask(CreaseRule rule, const RefinementStep& step, std::uint32_t v, const std::vector<int>& neighbours,
                          const std::vector<float>& sharpness, const CurveCreaseRule& curve) {
  switch (rule) {
    case CreaseRule::Smooth:
    case CreaseRule::Dart: return row_of(step, v);
    case CreaseRule::Corner: return {{v, 1.0}};
    case CreaseRule::Crease: {
      SparseEntries out{{v, curve.centre}};
      for (std::size_t i = 0; i < neighbours.size(); ++i)
        if (sharpness[i] > 0) out.emplace_back(static_cast<std::uint32_t>(neighbours[i]), curve.neighbour);
      merge_entries(out);
      return out;
    }
  }
  return {};
}

}  // namespace

bool crease_steps_fit(std::size_t first, float sharpest, std::size_t budget) {
  std::size_t made = first;
  for (int step = 1; step < static_cast<int>(std::ceil(sharpest)); ++step) {
    if (made > budget) return false;
    made *= 4;  // <= 4 * budget: no overflow for any budget below SIZE_MAX / 4
  }
  return made <= budget;
}

void check_crease_steps(std::size_t faces, std::size_t first, float sharpest) {
  const auto steps = static_cast<int>(std::ceil(sharpest));
  // The steps this mesh can take within the limit: step k + 1 makes first * 4^k faces.
  int allowed = 0;
  for (std::size_t made = first; made <= limits::kMaxCreaseStepFaces && allowed < steps; made *= 4) ++allowed;
  if (allowed < steps)
    throw MeshError("a sharpness of " + number_text(sharpest) + " takes " + std::to_string(steps) +
                    " whole-mesh subdivision steps, which would make more than " +
                    std::to_string(limits::kMaxCreaseStepFaces) + " faces from this mesh's " + std::to_string(faces) +
                    " (the limit); lower the sharpness to at most " + std::to_string(allowed) +
                    " for this mesh (the steps refine the whole mesh, not only round the sharp features)");
}

LevelSharpness sharpen_step(const Connectivity& parent, const LevelSharpness& sharpness, const CurveCreaseRule& curve,
                            const std::vector<int>& new_edge_points, RefinementStep& step, bool boundary_corners) {
  const bool chaikin = sharpness.chaikin();
  // Each vertex's neighbours (one per outgoing half-edge, so one per incident
  // edge on a closed mesh) and the edge point of each of those edges.
  std::vector<std::vector<int>> neighbours(parent.vertex_count);
  std::vector<std::vector<int>> edge_points(parent.vertex_count);
  std::vector<int> faces(parent.vertex_count, 0);
  std::size_t corner = 0;
  for (std::size_t f = 0; f < parent.face_count(); ++f) {
    const std::size_t k = static_cast<std::size_t>(parent.face_sizes[f]);
    for (std::size_t c = 0; c < k; ++c) {
      const int a = parent.face_vertices[corner + c], b = parent.face_vertices[corner + (c + 1) % k];
      neighbours[static_cast<std::size_t>(a)].push_back(b);
      edge_points[static_cast<std::size_t>(a)].push_back(new_edge_points[corner + c]);
      ++faces[static_cast<std::size_t>(a)];
    }
    corner += k;
  }
  // A boundary edge (a half-edge a -> b without b -> a) is infinitely sharp,
  // as OpenSubdiv makes it: b gets it as one more incident edge. Its rows are
  // the step's own boundary rules, and its children are boundary edges again,
  // so its sharpness is not carried to them (but for an infinitely sharp tag, below).
  std::vector<std::vector<char>> on_boundary(parent.vertex_count);
  for (std::size_t a = 0; a < parent.vertex_count; ++a) on_boundary[a].assign(neighbours[a].size(), 0);
  for (std::size_t a = 0; a < parent.vertex_count; ++a)
    for (std::size_t i = 0; i < static_cast<std::size_t>(faces[a]); ++i) {
      const auto b = static_cast<std::size_t>(neighbours[a][i]);
      bool twin = false;
      for (std::size_t j = 0; j < static_cast<std::size_t>(faces[b]) && !twin; ++j) twin = neighbours[b][j] == static_cast<int>(a);
      if (twin) continue;
      on_boundary[a][i] = 1;
      neighbours[b].push_back(static_cast<int>(a));
      edge_points[b].push_back(edge_points[a][i]);
      on_boundary[b].push_back(1);
    }
  LevelSharpness next = sharpness.empty_like();
  std::map<std::size_t, SparseEntries> rows;
  std::vector<float> ps, cs;
  for (std::size_t v = 0; v < parent.vertex_count; ++v) {
    const auto vi = static_cast<int>(v);
    const std::vector<int>& nb = neighbours[v];
    const std::size_t n = nb.size();
    ps.resize(n);
    cs.resize(n);
    bool any = false;  // a semi-sharp feature here (a boundary alone keeps the step's own rows)
    bool boundary = false;
    for (std::size_t i = 0; i < n; ++i) {
      if (on_boundary[v][i]) {
        ps[i] = kInfiniteSharpness;
        boundary = true;
      } else {
        any |= (ps[i] = sharpness.edge(vi, nb[i])) > 0;
      }
    }
    const float tagged = sharpness.vertex(vi);
    if (!any && tagged <= 0) continue;
    // OpenSubdiv's edge-and-corner: a boundary vertex in one face is infinitely sharp.
    const float pv = boundary && boundary_corners && faces[v] == 1 ? kInfiniteSharpness : tagged;
    for (std::size_t i = 0; i < n; ++i) {
      cs[i] = child_edge_sharpness(i, ps.data(), n, chaikin);
      if (!on_boundary[v][i]) next.set_edge(vi, edge_points[v][i], cs[i]);
    }
    const float cv = decayed_sharpness(pv);
    // An infinitely sharp tag stays; a boundary corner is made again at each level.
    if (tagged >= kInfiniteSharpness) next.set_vertex(vi, kInfiniteSharpness);
    else if (pv < kInfiniteSharpness) next.set_vertex(vi, cv);
    const CreaseRule p_rule = crease_rule(pv, ps.data(), n), c_rule = crease_rule(cv, cs.data(), n);
    if (p_rule == CreaseRule::Smooth || p_rule == CreaseRule::Dart) continue;
    const auto u = static_cast<std::uint32_t>(v);
    SparseEntries mask = vertex_mask(p_rule, step, u, nb, ps, curve);
    if (c_rule != p_rule) {
      const double w = transition_weight(pv, cv, ps.data(), cs.data(), n, chaikin);
      mask = blend(w, mask, 1.0 - w, vertex_mask(c_rule, step, u, nb, cs, curve));
    }
    rows[v] = std::move(mask);
  }
  // Edge points of sharp edges: the midpoint while both halves stay sharp, else
  // the smooth point pulled towards it by the edge's sharpness (OpenSubdiv
  // does not clamp that weight to 1).
  for (std::size_t v = 0; v < parent.vertex_count; ++v)
    for (std::size_t i = 0; i < neighbours[v].size(); ++i) {
      const int a = static_cast<int>(v), b = neighbours[v][i], e = edge_points[v][i];
      if (a > b) continue;
      const float s = sharpness.edge(a, b);
      if (on_boundary[v][i]) {
        // Its rows are the boundary's; a tag of infinite sharpness stays on its
        // halves, where boundary interpolation `none` asks for it (sharp_cut.hpp).
        if (s >= kInfiniteSharpness) next.set_edge(a, e, kInfiniteSharpness), next.set_edge(e, b, kInfiniteSharpness);
        continue;
      }
      if (s <= 0) continue;
      const SparseEntries mid{{static_cast<std::uint32_t>(a), 0.5}, {static_cast<std::uint32_t>(b), 0.5}};
      const bool stays = next.edge(a, e) > 0 && next.edge(e, b) > 0;
      rows[static_cast<std::size_t>(e)] = stays ? mid : blend(s, mid, 1.0 - static_cast<double>(s), row_of(step, static_cast<std::size_t>(e)));
    }
  if (!rows.empty()) step = replaced(step, rows);
  return next;
}

}  // namespace stencil_runtime
