#include "curve/curve_table_json.hpp"

#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "base/limits.hpp"
#include "common/parameters_json.hpp"

namespace sg {
using ojson = nlohmann::ordered_json;

namespace {
// Where a function of a curve table can sit: far beyond any mask offset, well inside a long.
constexpr long kMaxPosition = 1L << 31;
}  // namespace

std::string curve_table_to_json(const CurveTable& t) {
  ojson doc;
  doc["format"] = kCurveTableFormat;
  doc["version"] = kCurveTableVersion;
  doc["scheme"] = t.scheme;
  doc["scheme_hash"] = t.scheme_hash;
  doc["parameters"] = parameters_json<ojson>(t.parameters);
  doc["arity"] = t.arity;
  doc["n"] = t.n;
  doc["exact"] = true;
  doc["derivative_orders"] = t.derivative_orders;
  if (!t.derivatives_stop.empty()) doc["derivatives_stop"] = t.derivatives_stop;
  ojson functions = ojson::array();
  for (const auto& f : t.functions) {
    ojson fj;
    fj["name"] = f.name;
    fj["placement"] = placement_name(f.placement);
    fj["position"] = f.position;
    fj["support"] = {to_string(f.support_lo), to_string(f.support_hi)};
    auto grid_map = [&](const std::map<long, Rational>& m) {
      ojson values = ojson::object();
      for (const auto& [k, v] : m) values[to_string(Rational(k, t.n))] = to_string(v);
      return values;
    };
    fj["values"] = grid_map(f.values);
    if (!f.derivatives.empty()) {
      ojson derivatives = ojson::array();
      for (std::size_t r = 0; r < f.derivatives.size(); ++r)
        derivatives.push_back({{"order", r + 1}, {"values", grid_map(f.derivatives[r])}});
      fj["derivatives"] = derivatives;
    }
    functions.push_back(fj);
  }
  doc["functions"] = functions;
  return doc.dump(1) + "\n";
}

CurveTable curve_table_from_json(const std::string& text, const std::string& origin) {
  return curve_table_from_document(parse_table_document(text, origin));
}

CurveTable curve_table_from_document(const TableDocument& table) {
  const DocumentReader<ojson> r(table.origin);
  const ojson& doc = table.doc;
  if (table.format != kCurveTableFormat) r.fail("format", "is not \"" + std::string(kCurveTableFormat) + "\"");
  if (r.integer(r.require(doc, "version", ""), "version", 1, kCurveTableVersion) < kCurveTableVersion)
    r.fail("version", "version 1 tables predate derivatives; regenerate them with stencilgen --scheme " + excerpt(table.scheme) + " --n N");
  CurveTable t;
  t.scheme = table.scheme;
  t.scheme_hash = r.string(r.require(doc, "scheme_hash", ""), "scheme_hash");
  for (const auto& [k, v] : doc.at("parameters").items())  // checked by parse_table_document
    t.parameters[k] = r.rational_literal(v, field_path("parameters", k));
  t.arity = static_cast<int>(r.integer(r.require(doc, "arity", ""), "arity", 2, 3));
  t.n = r.integer(r.require(doc, "n", ""), "n", 1, limits::kMaxCurveRate);
  t.derivative_orders = static_cast<int>(r.integer(r.require(doc, "derivative_orders", ""), "derivative_orders", 0, kMaxDerivativeOrder));
  if (doc.contains("derivatives_stop")) t.derivatives_stop = r.string(doc["derivatives_stop"], "derivatives_stop");
  // A map from exact grid parameter k/n to exact value.
  auto read_grid_map = [&](const ojson& object, const std::string& values, std::map<long, Rational>& out) {
    for (const auto& [key, value] : r.object(object, values).items()) {
      const std::string at = field_path(values, key);
      Rational x;
      try {
        x = parse_rational(key) * t.n;
      } catch (const Error& e) {
        r.fail(at, std::string("the parameter: ") + e.what());
      }
      if (denominator(x) != 1) r.fail(at, "the parameter " + excerpt(key) + " is not on the grid (1/n)Z");
      if (!fits_long(numerator(x))) r.fail(at, "the parameter " + excerpt(key) + " is outside every support");
      out[numerator(x).convert_to<long>()] = r.rational_literal(value, at);
    }
  };
  const ojson& functions = r.array(r.require(doc, "functions", ""), "functions");
  for (std::size_t i = 0; i < functions.size(); ++i) {
    const std::string field = field_path("functions", i);
    const ojson& fj = functions[i];
    CurveTable::Function f;
    f.name = r.string(r.require(fj, "name", field), field_path(field, "name"));
    const std::string& p = r.string(r.require(fj, "placement", field), field_path(field, "placement"));
    if (p == "every") f.placement = Placement::Everywhere;
    else if (p == "at-most") f.placement = Placement::AtMost;
    else if (p == "at-least") f.placement = Placement::AtLeast;
    else if (p == "single") f.placement = Placement::Single;
    else r.fail(field_path(field, "placement"), "unknown placement '" + excerpt(p) + "'");
    f.position = r.integer(r.require(fj, "position", field), field_path(field, "position"), -kMaxPosition, kMaxPosition);
    const std::string support = field_path(field, "support");
    const ojson& ends = r.array(r.require(fj, "support", field), support);
    if (ends.size() != 2) r.fail(support, "expected [lo, hi], got " + json_excerpt(ends));
    f.support_lo = r.rational_literal(ends[0], field_path(support, 0));
    f.support_hi = r.rational_literal(ends[1], field_path(support, 1));
    read_grid_map(r.require(fj, "values", field), field_path(field, "values"), f.values);
    if (t.derivative_orders > 0) {
      const std::string dfield = field_path(field, "derivatives");
      const ojson& derivatives = r.array(r.require(fj, "derivatives", field), dfield);
      if (derivatives.size() != static_cast<std::size_t>(t.derivative_orders))
        r.fail(dfield, "expected " + std::to_string(t.derivative_orders) + " orders (derivative_orders), got " +
                           std::to_string(derivatives.size()));
      f.derivatives.resize(derivatives.size());
      for (std::size_t d = 0; d < derivatives.size(); ++d) {
        const std::string entry = field_path(dfield, d);
        r.integer(r.require(derivatives[d], "order", entry), field_path(entry, "order"), static_cast<long>(d) + 1,
                  static_cast<long>(d) + 1);
        read_grid_map(r.require(derivatives[d], "values", entry), field_path(entry, "values"), f.derivatives[d]);
      }
    } else if (fj.contains("derivatives")) {
      r.fail(field_path(field, "derivatives"), "present, but derivative_orders is 0");
    }
    t.functions.push_back(std::move(f));
  }
  return t;
}

}  // namespace sg
