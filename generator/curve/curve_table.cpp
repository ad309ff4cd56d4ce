#include "curve/curve_table.hpp"

#include "base/error.hpp"
#include "common/hash.hpp"
#include "curve/difference_scheme.hpp"

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
    CurveTable::Function f{type.name, type.placement, type.position, type.support_lo, type.support_hi, {}, {}};
    const TypeValues& tv = solution.types[h];
    for (long k = tv.range.first; k <= tv.range.last; ++k)
      if (tv.at(k) != 0) f.values[k] = tv.at(k);
    t.functions.push_back(std::move(f));
  }
  return t;
}

void add_derivatives(CurveTable& table, const std::vector<CurveSolution>& psi, const std::string& stop) {
  if (table.functions.size() != 1 || psi.size() > static_cast<std::size_t>(kMaxDerivativeOrder))
    throw Error("derivatives are added to uniform curve tables only, up to order " + std::to_string(kMaxDerivativeOrder));
  CurveTable::Function& f = table.functions[0];
  f.derivatives.assign(psi.size(), {});
  for (std::size_t r = 1; r <= psi.size(); ++r) {
    if (psi[r - 1].n != table.n) throw Error("derivative scheme solved at another rate than the table's");
    f.derivatives[r - 1] = derivative_from_difference(psi[r - 1].types.at(0), static_cast<int>(r), table.n);
  }
  table.derivative_orders = static_cast<int>(psi.size());
  table.derivatives_stop = stop;
}

void add_first_derivative(CurveTable& table, const CurveSolution& derivative, const std::string& stop) {
  if (derivative.n != table.n || derivative.types.size() != table.functions.size())
    throw Error("internal: a derivative solution that does not match its table");
  for (std::size_t h = 0; h < table.functions.size(); ++h) {
    std::map<long, Rational> values;
    const TypeValues& tv = derivative.types[h];
    for (long k = tv.range.first; k <= tv.range.last; ++k)
      if (tv.at(k) != 0) values[k] = tv.at(k);
    table.functions[h].derivatives = {std::move(values)};
  }
  table.derivative_orders = 1;
  table.derivatives_stop = stop;
}

CurveSolution table_to_solution(const CurveTable& table, const CurveScheme& scheme, int order) {
  if (table.functions.size() != scheme.types.size())
    throw Error("table has " + std::to_string(table.functions.size()) + " functions, scheme '" + scheme.name +
                "' has " + std::to_string(scheme.types.size()));
  CurveSolution sol = zero_solution(scheme, table.n);
  for (std::size_t h = 0; h < scheme.types.size(); ++h) {
    const CurveTable::Function& f = table.functions[h];
    if (order > static_cast<int>(f.derivatives.size()))
      throw Error("function '" + excerpt(f.name) + "' has no derivative of order " + std::to_string(order));
    const std::map<long, Rational>& values = order == 0 ? f.values : f.derivatives[static_cast<std::size_t>(order - 1)];
    TypeValues& tv = sol.types[h];
    for (const auto& [k, v] : values) {
      if (!tv.range.contains(k))
        throw Error("function '" + excerpt(f.name) + "' has a nonzero " +
                    (order == 0 ? std::string("value") : "derivative of order " + std::to_string(order)) + " at x = " +
                    to_string(Rational(k, table.n)) + ", outside its open support");
      tv.values[static_cast<std::size_t>(k - tv.range.first)] = v;
    }
  }
  return sol;
}

std::uint64_t exact_digits(const CurveTable& table) {
  std::uint64_t digits = 0;
  const auto add = [&digits](const std::map<long, Rational>& values) {
    for (const auto& [k, r] : values) {
      const mpq_srcptr q = r.backend().data();
      digits += mpz_sizeinbase(mpq_numref(q), 10) + mpz_sizeinbase(mpq_denref(q), 10);
    }
  };
  for (const CurveTable::Function& f : table.functions) {
    add(f.values);
    for (const auto& d : f.derivatives) add(d);
  }
  return digits;
}

}  // namespace sg
