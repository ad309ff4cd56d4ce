#include "triangle/triangle_table.hpp"

#include <nlohmann/json.hpp>
#include <algorithm>
#include <set>

#include "base/error.hpp"
#include "common/hash.hpp"
#include "common/parameters_json.hpp"
#include "common/table_encoding.hpp"

namespace sg {
using ojson = nlohmann::ordered_json;

namespace {

std::string rule_string(const std::optional<Rational>& exact, const Real& approx) {
  return exact ? to_string(*exact) : to_string(approx, kTableDigits);
}

}  // namespace

template <class T>
TriangleTable make_triangle_table(const TriangleScheme& scheme, const TrianglePatch<T>& patch, long n) {
  if (patch.grid != 3 * n) throw Error("internal: a triangle table at rate n needs the patch on the grid 3n");
  TriangleTable t;
  t.scheme = scheme.name;
  t.scheme_hash = hex64(scheme.hash);
  t.refinement = scheme.refinement_name();
  t.parameters = scheme.parameters;
  t.valence = patch.valence;
  t.n = n;
  t.exact = std::is_same_v<T, Rational>;
  if constexpr (std::is_same_v<T, Real>) t.residual = std::max(patch.eigen_residual, patch.unity_residual);
  t.derivatives = !patch.du.empty();
  if constexpr (std::is_same_v<T, Real>)
    if (t.derivatives) throw Error("internal: derivative stencils are written for the regular (rational) patch only");
  if (scheme.refinement == TriangleRefinement::Loop) {
    t.rules.edge_end = to_string(scheme.edge_end);
    t.rules.edge_opposite = to_string(scheme.edge_opposite);
  }
  if (scheme.has_crease) {
    t.rules.crease_curve = scheme.crease_curve;
    t.rules.crease_centre = to_string(scheme.crease_centre);
    t.rules.crease_neighbour = to_string(scheme.crease_neighbour);
  }
  t.rules.neighbour_regular = to_string(*scheme.exact_neighbour_weight(6));
  t.rules.neighbour = rule_string(scheme.exact_neighbour_weight(patch.valence), scheme.real_neighbour_weight(patch.valence));

  // Grid points (on 3n) of the nodes and centres, in storage order.
  std::vector<std::pair<long, long>> node_at, up_at, down_at;
  for (long j = 0; j <= n; ++j)
    for (long i = 0; i + j <= n; ++i) node_at.emplace_back(i, j);
  for (long j = 0; j < n; ++j)
    for (long i = 0; i + j <= n - 1; ++i) up_at.emplace_back(i, j);
  for (long j = 0; j + 1 < n; ++j)
    for (long i = 0; i + j <= n - 2; ++i) down_at.emplace_back(i, j);

  for (int r = 0; r < patch_regions(scheme, patch.valence); ++r) {
    TriangleTable::Region region;
    region.index = r;
    std::set<std::size_t> used;
    const bool derivatives = r == 0 && t.derivatives;
    auto scan = [&](long gi, long gj) {
      for (const auto& [h, w] : patch.at(r, gi, gj)) used.insert(h);
      if (derivatives) {
        const auto at = static_cast<std::size_t>(gj * (patch.grid + 1) + gi);
        for (const auto& [h, w] : patch.du[at]) used.insert(h);
        for (const auto& [h, w] : patch.dv[at]) used.insert(h);
      }
    };
    for (auto [i, j] : node_at) scan(3 * i, 3 * j);
    for (auto [i, j] : up_at) scan(3 * i + 1, 3 * j + 1);
    for (auto [i, j] : down_at) scan(3 * i + 2, 3 * j + 2);
    const std::vector<std::size_t> ids(used.begin(), used.end());
    for (std::size_t h : ids) region.layout.push_back(patch.chart.point(h));

    auto pick = [&](const SparseRow<T>& row) {
      std::vector<T> picked(ids.size());
      for (const auto& [h, w] : row) picked[static_cast<std::size_t>(std::lower_bound(ids.begin(), ids.end(), h) - ids.begin())] = w;
      return picked;
    };
    auto entry = [&](long i, long j, long gi, long gj) {
      TriangleTable::Entry e;
      e.i = i, e.j = j;
      std::vector<T> picked = pick(patch.at(r, gi, gj));
      if constexpr (std::is_same_v<T, Rational>) {
        e.exact = scaled_from_rationals(picked);
        if (derivatives) {
          const auto at = static_cast<std::size_t>(gj * (patch.grid + 1) + gi);
          e.du = scaled_from_rationals(pick(patch.du[at]));
          e.dv = scaled_from_rationals(pick(patch.dv[at]));
        }
      } else {
        e.approx = std::move(picked);
      }
      return e;
    };
    for (auto [i, j] : node_at) region.nodes.push_back(entry(i, j, 3 * i, 3 * j));
    for (auto [i, j] : up_at) region.up.push_back(entry(i, j, 3 * i + 1, 3 * j + 1));
    for (auto [i, j] : down_at) region.down.push_back(entry(i, j, 3 * i + 2, 3 * j + 2));
    t.regions.push_back(std::move(region));
  }
  return t;
}

template TriangleTable make_triangle_table(const TriangleScheme&, const TrianglePatch<Rational>&, long);
template TriangleTable make_triangle_table(const TriangleScheme&, const TrianglePatch<Real>&, long);

TriangleTable solve_triangle_table(const TriangleScheme& scheme, int valence, long n, const BivariateSolution& regular,
                                   const BivariateGradient* gradient) {
  // The band points the table samples: nodes and centres of regions 1.. on the grid 3n.
  std::vector<std::array<long, 3>> band;
  for (long r = 1; r < patch_regions(scheme, valence); ++r)
    for (long j = 0; j <= 3 * n; ++j)
      for (long i = 0; i + j <= 3 * n; ++i)
        if (i % 3 == j % 3) band.push_back({r, i, j});
  return scheme.exact_neighbour_weight(valence)
             ? make_triangle_table(scheme, solve_triangle_patch<Rational>(scheme, valence, 3 * n, regular, band, gradient), n)
             : make_triangle_table(scheme, solve_triangle_patch<Real>(scheme, valence, 3 * n, regular, band), n);
}

namespace {

void append_entries(std::string& out, const std::string& indent, const char* key, const TriangleTable& t,
                    const std::vector<TriangleTable::Entry>& entries, long offset, bool last) {
  out += indent + "\"" + key + "\": [\n";
  const long den = 3 * t.n;
  for (std::size_t k = 0; k < entries.size(); ++k) {
    const auto& e = entries[k];
    const Rational x(3 * e.i + offset, den), y(3 * e.j + offset, den);
    ojson j;
    if (t.exact) {
      j = exact_entry_json(e.exact, x, y);
      if (t.derivatives)
        for (const auto& [name, d] : {std::pair{"du", &e.du}, std::pair{"dv", &e.dv}}) {
          ojson nums = ojson::array();
          for (const auto& v : d->num) nums.push_back(v.str());
          j[name] = {{"denominator", d->den.str()}, {"numerators", nums}};
        }
    } else {
      j["at"] = {to_string(x), to_string(y)};
      ojson w = ojson::array();
      for (const Real& v : e.approx) w.push_back(v == 0 ? std::string("0") : to_string(v, kTableDigits));
      j["weights"] = w;
    }
    out += indent + " " + j.dump();
    out += k + 1 < entries.size() ? ",\n" : "\n";
  }
  out += indent + (last ? "]\n" : "],\n");
}

ojson layout_json(const std::vector<SectorPoint>& layout) {
  ojson out = ojson::array();
  for (const SectorPoint& p : layout) out.push_back({p.sector, p.a, p.b});
  return out;
}

void append_region(std::string& out, const std::string& indent, const TriangleTable& t, const TriangleTable::Region& r) {
  append_entries(out, indent, "nodes", t, r.nodes, 0, false);
  append_entries(out, indent, "up_centres", t, r.up, 1, false);
  append_entries(out, indent, "down_centres", t, r.down, 2, true);
}

}  // namespace

std::string triangle_table_to_json(const TriangleTable& t) {
  ojson head;
  head["format"] = kTriangleTableFormat;
  head["version"] = kTriangleTableVersion;
  head["scheme"] = t.scheme;
  head["scheme_hash"] = t.scheme_hash;
  head["refinement"] = t.refinement;
  head["parameters"] = parameters_json<ojson>(t.parameters);
  head["valence"] = t.valence;
  head["n"] = t.n;
  head["exact"] = t.exact;
  if (!t.exact) {
    head["digits"] = kTableDigits;
    head["residual"] = to_string(t.residual, 3);
  }
  head["points"] = t.regions.front().layout.size();
  head["parameterisation"] =
      "patch (EV, e_0, e_1) of sector 0; the point (u, v) lies at u (1,0) + v (1,1) of sector 0's lattice frame";
  head["layout_meaning"] =
      "each control point is [sector k, a, b]: the vertex a (1,0) + b (1,1) in sector k's frame (e_k = (1,0), "
      "e_{k+1} = (1,1), a >= 1, 0 <= b < a; [0,0,0] is the extraordinary vertex)";
  if (t.derivatives)
    head["derivatives_meaning"] =
        "du and dv: the derivatives of the limit point along the patch's u and v, sum of numerators[h] * P[layout[h]] / "
        "denominator, exact (the regular basis's gradient, solved by its scaling relation)";
  if (t.regions.size() > 1)
    head["band_meaning"] =
        "the triangles of the EV's second ring, where its vertex rule still reaches (sqrt(3)): in sector 0's frame, "
        "corners counter-clockwise; the point (u, v) is corner 0 + u (corner 1 - corner 0) + v (corner 2 - corner 0); "
        "each band region has its own layout";
  ojson rules;
  if (!t.rules.edge_end.empty()) {
    rules["edge_end"] = t.rules.edge_end;
    rules["edge_opposite"] = t.rules.edge_opposite;
  }
  rules["neighbour_regular"] = t.rules.neighbour_regular;
  rules["neighbour"] = t.rules.neighbour;
  if (!t.rules.crease_curve.empty())
    rules["crease"] = {{"curve", t.rules.crease_curve},
                       {"centre", t.rules.crease_centre},
                       {"neighbour", t.rules.crease_neighbour},
                       {"meaning", "along a crease: new vertex = centre * old + neighbour * each crease neighbour; new edge "
                                   "point = midpoint"}};
  head["rules"] = rules;
  std::string out = head.dump(1);
  out.resize(out.size() - 2);
  out += ",\n \"layout\": " + layout_json(t.regions.front().layout).dump() + ",\n";
  out += t.exact ? std::string(" \"stencil\": \"limit point = sum of numerators[h] * P[layout[h]] / denominator\",\n")
                 : std::string(" \"stencil\": \"limit point = sum of weights[h] * P[layout[h]] (not exact: " +
                               std::to_string(kTableDigits) + " significant digits)\",\n");
  append_region(out, " ", t, t.regions.front());
  if (t.regions.size() > 1) {
    out.resize(out.size() - 1);  // the band follows the last "]"
    out += ",\n \"band\": [\n";
    for (std::size_t k = 1; k < t.regions.size(); ++k) {
      const TriangleTable::Region& r = t.regions[k];
      ojson corners = ojson::array();
      for (const auto& [a, b] : region_corners(r.index)) corners.push_back({a, b});
      out += "  {\"region\": " + std::to_string(r.index) + ", \"corners\": " + corners.dump() +
             ", \"points\": " + std::to_string(r.layout.size()) + ",\n   \"layout\": " + layout_json(r.layout).dump() +
             ",\n";
      append_region(out, "   ", t, r);
      out += k + 1 < t.regions.size() ? "  },\n" : "  }\n";
    }
    out += " ]\n";
  }
  out += "}\n";
  return out;
}

}  // namespace sg
