#include "quad/quad_table_json.hpp"

#include <nlohmann/json.hpp>

#include "common/parameters_json.hpp"
#include "common/table_encoding.hpp"

namespace sg {
using ojson = nlohmann::ordered_json;

namespace {

void append_entries(std::string& out, const char* key, const std::vector<QuadTable::Entry>& entries, long denom,
                    long offset, bool last) {
  out += std::string(" \"") + key + "\": [\n";
  for (std::size_t k = 0; k < entries.size(); ++k) {
    const auto& e = entries[k];
    out += "  " + exact_entry_json(e.weights, Rational(2 * e.i + offset, denom), Rational(2 * e.j + offset, denom)).dump();
    out += k + 1 < entries.size() ? ",\n" : "\n";
  }
  out += last ? " ]\n" : " ],\n";
}

}  // namespace

std::string quad_table_to_json(const QuadTable& t) {
  ojson head;
  head["format"] = kQuadTableFormat;
  head["version"] = kQuadTableVersion;
  head["scheme"] = t.scheme;
  head["scheme_hash"] = t.scheme_hash;
  head["parameters"] = parameters_json<ojson>(t.parameters);
  head["valence"] = t.valence;
  head["n"] = t.n;
  head["exact"] = true;
  head["points"] = t.points;
  head["layout"] =
      "index 0: extraordinary vertex; 1+2k: edge neighbour e_k; 2+2k: face neighbour f_k (k = 0..v-1, "
      "counter-clockwise, e_0 = (1,0), f_0 = (1,1), e_1 = (0,1)); 2v+1..2v+7: (2,-1), (2,0), (2,1), (2,2), (1,2), "
      "(0,2), (-1,2). Limit point = sum of numerators[h] * P[h] / denominator.";
  head["symmetry"] =
      "only points with x <= y are listed; the stencil at (y,x) has weight w[h] at index reflection[h], where w is "
      "the stencil at (x,y)";
  ojson rules;
  rules["face_corner"] = to_string(t.rules.face_corner);
  rules["edge_end"] = to_string(t.rules.edge_end);
  rules["edge_wing"] = to_string(t.rules.edge_wing);
  ojson vertex = ojson::object();
  for (const auto& [v, r] : t.rules.vertex)
    vertex[std::to_string(v)] = {to_string(r.centre), to_string(r.edge), to_string(r.face)};
  rules["vertex"] = vertex;
  if (t.rules.polygon) {
    ojson polygon;
    polygon["edge_end"] = to_string(t.rules.polygon_edge_end);
    polygon["edge_face_point"] = to_string(t.rules.polygon_edge_face);
    ojson pv = ojson::object();
    for (const auto& [v, r] : t.rules.polygon_vertex)
      pv[std::to_string(v)] = {to_string(r.centre), to_string(r.midpoint), to_string(r.face)};
    polygon["vertex"] = pv;
    rules["polygon"] = polygon;
  }
  head["rules"] = rules;
  std::string out = head.dump(1);
  out.resize(out.size() - 2);  // reopen the object ("\n}"): compact arrays follow, one stencil per line
  out += ",\n \"reflection\": " + ojson(t.reflection).dump() + ",\n";
  append_entries(out, "nodes", t.nodes, 2 * t.n, 0, false);
  append_entries(out, "centres", t.centres, 2 * t.n, 1, true);
  out += "}\n";
  return out;
}

}  // namespace sg
