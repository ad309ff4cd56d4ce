#include "curve/curve_table.hpp"

#include "base/error.hpp"
#include "common/hash.hpp"

namespace sg {

const char* placement_name(Placement p) {
  switch (p) {
    case Placement::Everywhere: return "every";
    case Placement::AtMost: return "at-most";
    case Placement::AtLeast: return "at-least";
    case Placement::Single: return "single";
  }
  return "?";
}

CurveTable make_table(const CurveScheme& scheme, const CurveSolution& solution) {
  CurveTable t;
  t.scheme = scheme.name;
  t.scheme_hash = hex64(scheme.hash);
  t.parameters = scheme.parameters;
  t.arity = scheme.arity;
  t.n = solution.n;
  for (std::size_t h = 0; h < scheme.types.size(); ++h) {
    const ScalingType& type = scheme.types[h];
    CurveTable::Function f{type.name, type.placement, type.position, type.support_lo, type.support_hi, {}};
    const TypeValues& tv = solution.types[h];
    for (long k = tv.range.first; k <= tv.range.last; ++k)
      if (tv.at(k) != 0) f.values[k] = tv.at(k);
    t.functions.push_back(std::move(f));
  }
  return t;
}

CurveSolution table_to_solution(const CurveTable& table, const CurveScheme& scheme) {
  if (table.functions.size() != scheme.types.size())
    throw Error("table has " + std::to_string(table.functions.size()) + " functions, scheme '" + scheme.name +
                "' has " + std::to_string(scheme.types.size()));
  CurveSolution sol;
  sol.n = table.n;
  for (std::size_t h = 0; h < scheme.types.size(); ++h) {
    TypeValues tv;
    tv.range = open_support_grid(scheme.types[h], table.n);
    tv.values.assign(static_cast<std::size_t>(std::max(0L, tv.range.size())), Rational(0));
    for (const auto& [k, v] : table.functions[h].values) {
      if (!tv.range.contains(k))
        throw Error("function '" + excerpt(table.functions[h].name) + "' has a nonzero value at x = " +
                    to_string(Rational(k, table.n)) + ", outside its support");
      tv.values[k - tv.range.first] = v;
    }
    sol.types.push_back(std::move(tv));
  }
  return sol;
}

}  // namespace sg
