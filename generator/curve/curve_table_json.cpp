#include "curve/curve_table_json.hpp"

#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "common/parameters_json.hpp"

namespace sg {
using ojson = nlohmann::ordered_json;

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
  ojson functions = ojson::array();
  for (const auto& f : t.functions) {
    ojson fj;
    fj["name"] = f.name;
    fj["placement"] = placement_name(f.placement);
    fj["position"] = f.position;
    fj["support"] = {to_string(f.support_lo), to_string(f.support_hi)};
    ojson values = ojson::object();
    for (const auto& [k, v] : f.values) values[to_string(Rational(k, t.n))] = to_string(v);
    fj["values"] = values;
    functions.push_back(fj);
  }
  doc["functions"] = functions;
  return doc.dump(1) + "\n";
}

CurveTable curve_table_from_json(const std::string& text, const std::string& origin) {
  auto fail = [&](const std::string& what) -> Error { return Error(origin + ": " + what); };
  ojson doc;
  try {
    doc = ojson::parse(text);
  } catch (const ojson::parse_error& e) {
    throw fail(std::string("not valid JSON: ") + e.what());
  }
  try {
    if (doc.at("format") != kCurveTableFormat) throw fail("format is not \"" + std::string(kCurveTableFormat) + "\"");
    if (doc.at("version") != kCurveTableVersion)
      throw fail("version " + doc.at("version").dump() + " is not supported (expected " +
                 std::to_string(kCurveTableVersion) + ")");
    CurveTable t;
    t.scheme = doc.at("scheme").get<std::string>();
    t.scheme_hash = doc.at("scheme_hash").get<std::string>();
    for (const auto& [k, v] : doc.at("parameters").items()) t.parameters[k] = parse_rational(v.get<std::string>());
    t.arity = doc.at("arity").get<int>();
    t.n = doc.at("n").get<long>();
    if (t.n < 1) throw fail("n must be at least 1");
    for (const auto& fj : doc.at("functions")) {
      CurveTable::Function f;
      f.name = fj.at("name").get<std::string>();
      const std::string p = fj.at("placement").get<std::string>();
      if (p == "every") f.placement = Placement::Everywhere;
      else if (p == "at-most") f.placement = Placement::AtMost;
      else if (p == "at-least") f.placement = Placement::AtLeast;
      else if (p == "single") f.placement = Placement::Single;
      else throw fail("function '" + f.name + "': unknown placement '" + p + "'");
      f.position = fj.at("position").get<long>();
      f.support_lo = parse_rational(fj.at("support").at(0).get<std::string>());
      f.support_hi = parse_rational(fj.at("support").at(1).get<std::string>());
      for (const auto& [key, value] : fj.at("values").items()) {
        const Rational x = parse_rational(key) * t.n;
        if (denominator(x) != 1) throw fail("function '" + f.name + "': parameter " + key + " is not on the grid (1/n)Z");
        const Rational v = parse_rational(value.get<std::string>());
        f.values[numerator(x).convert_to<long>()] = v;
      }
      t.functions.push_back(std::move(f));
    }
    return t;
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw fail(std::string("malformed table: ") + e.what());
  }
}

}  // namespace sg
