#include "surface_table_json.hpp"

#include <nlohmann/json.hpp>

namespace sg {
using ojson = nlohmann::ordered_json;

namespace {

ojson entry_json(const ScaledVector& w, const Rational& x, const Rational& y) {
  ojson e;
  e["at"] = {to_string(x), to_string(y)};
  e["denominator"] = w.den.str();
  ojson nums = ojson::array();
  for (const auto& v : w.num) nums.push_back(v.str());
  e["numerators"] = nums;
  return e;
}

void append_entries(std::string& out, const char* key, const std::vector<SurfaceTable::Entry>& entries, long denom,
                    long offset, bool last) {
  out += std::string(" \"") + key + "\": [\n";
  for (std::size_t k = 0; k < entries.size(); ++k) {
    const auto& e = entries[k];
    out += "  " + entry_json(e.weights, Rational(2 * e.i + offset, denom), Rational(2 * e.j + offset, denom)).dump();
    out += k + 1 < entries.size() ? ",\n" : "\n";
  }
  out += last ? " ]\n" : " ],\n";
}

}  // namespace

std::string surface_table_to_json(const SurfaceTable& t) {
  ojson head;
  head["format"] = kSurfaceTableFormat;
  head["version"] = kSurfaceTableVersion;
  head["scheme"] = t.scheme;
  head["scheme_hash"] = t.scheme_hash;
  ojson params = ojson::object();
  for (const auto& [k, v] : t.parameters) params[k] = to_string(v);
  head["parameters"] = params;
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
  std::string out = head.dump(1);
  out.resize(out.size() - 2);  // reopen the object ("\n}"): compact arrays follow, one stencil per line
  out += ",\n \"reflection\": " + ojson(t.reflection).dump() + ",\n";
  append_entries(out, "nodes", t.nodes, 2 * t.n, 0, false);
  append_entries(out, "centres", t.centres, 2 * t.n, 1, true);
  out += "}\n";
  return out;
}

}  // namespace sg
