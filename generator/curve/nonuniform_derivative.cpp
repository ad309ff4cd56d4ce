#include "curve/nonuniform_derivative.hpp"

#include <algorithm>

#include "algebra/exact_linear_system.hpp"
#include "base/error.hpp"
#include "curve/difference_scheme.hpp"
#include "curve/residue_solver.hpp"
#include "curve/special_columns.hpp"

namespace sg {

NonuniformDerivative nonuniform_derivative_plan(const CurveScheme& s) {
  NonuniformDerivative plan;
  if (s.is_uniform()) {
    plan.stop = "internal: a uniform scheme's derivative comes from its difference scheme";
    return plan;
  }
  plan.psi.resize(s.types.size());
  for (std::size_t h = 0; h < s.types.size(); ++h) {
    const ScalingType& type = s.types[h];
    if (!type.translation_invariant()) continue;
    CurveScheme uniform;
    uniform.name = s.name + " ('" + type.name + "')";
    uniform.kind = "uniform";
    uniform.arity = s.arity;
    uniform.hash = s.hash;
    ScalingType own = type;
    own.placement = Placement::Everywhere;
    own.position = 0;
    for (Term& t : own.terms) {
      if (t.type != h) {
        plan.stop = "no derivative tables: the uniform type '" + type.name + "' refines into another type";
        return plan;
      }
      t.type = 0;
    }
    uniform.types = {own};
    const DerivativeSchemes d = derivative_schemes(uniform, 1);
    if (d.schemes.empty()) {
      plan.stop = "no derivative tables: the uniform type '" + type.name + "' is " + d.stop;
      return plan;
    }
    plan.psi[h] = d.schemes.front();
  }
  try {
    plan.at_zero = linear_at_zero(s);
  } catch (const Error& e) {
    plan.stop = std::string("no derivative tables: at the special point 0, ") + e.what();
    return plan;
  }
  plan.available = true;
  plan.stop = "second derivatives are not generated for non-uniform schemes (first derivatives are in x; at 0, from the right" +
              std::string(plan.at_zero.left_linear ? ", and " + to_string(plan.at_zero.left_slope) + " times that from the left" : "") +
              ")";
  return plan;
}

CurveSolution solve_nonuniform_derivative(const CurveScheme& s, const NonuniformDerivative& plan, long n) {
  if (!plan.available) throw Error("internal: no derivative plan for scheme '" + s.name + "'");
  const long a = s.arity;
  CurveSolution d = zero_solution(s, n);
  // Invariant types: phi'(x) = psi(x) - psi(x - 1).
  for (std::size_t h = 0; h < s.types.size(); ++h) {
    if (!plan.psi[h]) continue;
    TypeValues& tv = d.types[h];
    for (const auto& [k, v] : derivative_from_difference(solve_by_residues(*plan.psi[h], n).types.at(0), 1, n)) {
      if (!tv.range.contains(k))
        throw Error("scheme '" + s.name + "', n = " + std::to_string(n) + ": the derivative of '" + s.types[h].name +
                    "' is nonzero at " + to_string(Rational(k, n)) + ", outside its open support");
      tv.values[static_cast<std::size_t>(k - tv.range.first)] = v;
    }
  }
  solve_special_orbits(s, d, Rational(a));
  // x = 0: G_h = a (known_h + sum c G_g), with sum_{j in L} xi_j B_j'(0+) = 1.
  const std::vector<std::size_t> at_zero = special_types_at_zero(s, d);
  if (at_zero.empty()) return d;
  ExactLinearSystem system(at_zero.size());
  add_relations_at_zero(s, d, at_zero, Rational(a), system);
  std::vector<std::pair<std::size_t, Rational>> scale;
  Rational rest = 1;
  const LinearAtZero& l = plan.at_zero;
  for (std::size_t i = 0; i < l.functions.size(); ++i) {
    const PlacedFunction& f = l.functions[i];
    if (s.types[f.type].translation_invariant()) rest -= l.xi[i] * d.types[f.type].at(-f.j * n);
    else if (position_in(at_zero, f.type) < at_zero.size()) scale.emplace_back(position_in(at_zero, f.type), l.xi[i]);
  }
  system.add_equation(scale, rest);
  const LinearSolution result = system.solve();
  if (result.status != LinearSolution::Status::Unique)
    throw Error("scheme '" + s.name + "', n = " + std::to_string(n) +
                ": the differentiated relations of the special columns at x = 0 with the linear function's slope have " +
                result.describe());
  for (std::size_t i = 0; i < at_zero.size(); ++i) set_global_value(s, d, at_zero[i], 0, result.values[i]);
  return d;
}

}  // namespace sg
