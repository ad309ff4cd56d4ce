#include "quad/quad_table.hpp"

#include "base/error.hpp"
#include "common/hash.hpp"
#include "quad/patch_layout.hpp"

namespace sg {

QuadTable make_quad_table(const QuadScheme& scheme, const PatchGrid& patch) {
  if (patch.grid % 2 != 0) throw Error("internal: surface tables need the patch solved on the grid 2n");
  QuadTable t;
  t.scheme = scheme.name;
  t.scheme_hash = hex64(scheme.hash);
  t.parameters = scheme.parameters;
  t.valence = patch.valence;
  t.n = patch.grid / 2;
  t.points = patch.points;
  t.reflection = PatchLayout(patch.valence).reflection();
  t.rules.face_corner = scheme.face_corner;
  t.rules.edge_end = scheme.edge_end;
  t.rules.edge_wing = scheme.edge_wing;
  t.rules.vertex[4] = scheme.vertex_rule(4);
  t.rules.vertex[patch.valence] = scheme.vertex_rule(patch.valence);
  if (scheme.polygon.present) {
    t.rules.polygon = true;
    t.rules.polygon_edge_end = scheme.polygon.edge_end;
    t.rules.polygon_edge_face = scheme.polygon.edge_face;
    for (int v : {4, patch.valence}) t.rules.polygon_vertex[v] = scheme.polygon_vertex_rule(v);
  }
  auto at = [&](long i, long j) { return patch.scaled[static_cast<std::size_t>(j * (patch.grid + 1) + i)]; };
  for (long j = 0; j <= t.n; ++j)
    for (long i = 0; i <= j; ++i) t.nodes.push_back({i, j, at(2 * i, 2 * j)});
  for (long j = 0; j < t.n; ++j)
    for (long i = 0; i <= j; ++i) t.centres.push_back({i, j, at(2 * i + 1, 2 * j + 1)});
  return t;
}

std::vector<std::string> check_quad_table(const QuadTable& t) {
  std::vector<std::string> failures;
  auto check = [&](const QuadTable::Entry& e, const char* kind) {
    Integer sum = 0;
    for (const auto& x : e.weights.num) sum += x;
    if (e.weights.num.size() != t.points || sum != e.weights.den)
      failures.push_back(std::string(kind) + " (" + std::to_string(e.i) + "," + std::to_string(e.j) +
                         "): the weights do not sum to 1");
    if (e.i == e.j)
      for (std::size_t h = 0; h < t.points; ++h)
        if (e.weights.num[h] != e.weights.num[t.reflection[h]]) {
          failures.push_back(std::string(kind) + " (" + std::to_string(e.i) + "," + std::to_string(e.j) +
                             "): not symmetric under the reflection on the diagonal");
          break;
        }
  };
  for (const auto& e : t.nodes) check(e, "node");
  for (const auto& e : t.centres) check(e, "centre");
  return failures;
}

}  // namespace sg
