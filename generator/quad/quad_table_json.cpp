#include "quad/quad_table_json.hpp"

#include <nlohmann/json.hpp>

#include "common/parameters_json.hpp"

namespace sg {
using ojson = nlohmann::ordered_json;

ojson exact_entry_json(const ScaledVector& w, const Rational& x, const Rational& y) {
  ojson e;
  e["at"] = {to_string(x), to_string(y)};
  e["denominator"] = w.den.str();
  ojson nums = ojson::array();
  for (const auto& v : w.num) nums.push_back(v.str());
  e["numerators"] = nums;
  return e;
}

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

#include "base/error.hpp"
#include "common/hash.hpp"
#include "quad/patch_layout.hpp"

namespace sg {

std::string table_format(const std::string& text) {
  try {
    const ojson doc = ojson::parse(text);
    return doc.is_object() ? doc.value("format", "") : "";
  } catch (const ojson::parse_error&) {
    return "";
  }
}

std::vector<std::string> verify_quad_table_json(const std::string& text, const std::string& origin,
                                             const QuadScheme& scheme) {
  std::vector<std::string> failures;
  ojson doc;
  try {
    doc = ojson::parse(text);
    if (doc.at("format") != kQuadTableFormat || doc.at("version") != kQuadTableVersion)
      throw Error("not a version " + std::to_string(kQuadTableVersion) + " surface table");
    if (doc.at("scheme_hash") != hex64(scheme.hash))
      failures.push_back("scheme hash " + doc.at("scheme_hash").get<std::string>() + " is not that of '" +
                         scheme.name + "' (" + hex64(scheme.hash) + ")");
    const int v = doc.at("valence").get<int>();
    const long n = doc.at("n").get<long>();
    if (n < 1 || v < 3) throw Error("invalid valence or n");
    const PatchGrid patch = solve_ev_patch(scheme, v, 2 * n);
    if (doc.at("reflection").get<std::vector<std::size_t>>() != PatchLayout(v).reflection())
      failures.push_back("the reflection permutation is wrong");
    std::size_t expected_count[2] = {static_cast<std::size_t>((n + 1) * (n + 2) / 2),
                                     static_cast<std::size_t>(n * (n + 1) / 2)};
    int kind = 0;
    for (const char* key : {"nodes", "centres"}) {
      const ojson& list = doc.at(key);
      if (list.size() != expected_count[kind])
        failures.push_back(std::string(key) + ": " + std::to_string(list.size()) + " entries, expected " +
                           std::to_string(expected_count[kind]));
      for (const ojson& e : list) {
        const Rational x = parse_rational(e.at("at")[0].get<std::string>()) * 2 * n;
        const Rational y = parse_rational(e.at("at")[1].get<std::string>()) * 2 * n;
        const std::string where = std::string(key) + " at (" + e.at("at")[0].get<std::string>() + ", " +
                                  e.at("at")[1].get<std::string>() + ")";
        if (denominator(x) != 1 || denominator(y) != 1 || x < 0 || y < 0 || x > 2 * n || y > 2 * n) {
          failures.push_back(where + ": not a point of the grid 1/(2n) in the patch");
          continue;
        }
        const Integer den(e.at("denominator").get<std::string>());
        std::vector<Rational> w;
        Integer sum = 0;
        for (const ojson& num : e.at("numerators")) {
          const Integer k(num.get<std::string>());
          sum += k;
          w.emplace_back(k, den);
        }
        if (sum != den) failures.push_back(where + ": the weights do not sum to 1");
        if (w != patch.at(static_cast<long>(numerator(x)), static_cast<long>(numerator(y))))
          failures.push_back(where + ": differs from the re-solved stencil");
      }
      ++kind;
    }
  } catch (const Error& e) {
    failures.push_back(origin + ": " + e.what());
  } catch (const std::exception& e) {
    failures.push_back(origin + ": malformed surface table (" + e.what() + ")");
  }
  return failures;
}

}  // namespace sg
