#pragma once
// One scheme at one rate n: the exact values of every scaling function on (1/n)Z,
// with the identity of the scheme that produced them. Serialised as exact JSON
// (curve_table_json) and compact binary (curve_table_binary); see docs/table-format.md.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "curve/curve_scheme.hpp"
#include "curve/curve_solution.hpp"

namespace sg {

struct CurveTable {
  struct Function {
    std::string name;
    Placement placement = Placement::Everywhere;
    long position = 0;
    Rational support_lo, support_hi;
    std::map<long, Rational> values;  // nonzero values only, keyed by k (parameter k/n)
    // derivatives[r - 1]: the nonzero values of phi^(r) on the grid, r = 1..derivative_orders
    std::vector<std::map<long, Rational>> derivatives;
  };
  std::string scheme;
  std::string scheme_hash;  // hex of CurveScheme::hash
  Bindings parameters;
  int arity = 2;
  long n = 1;
  std::vector<Function> functions;
  int derivative_orders = 0;     // how many derivatives every function carries
  std::string derivatives_stop;  // why there are no more (empty when the generator's maximum was reached)
};

// The largest derivative order stencilgen writes (curves: second derivatives).
inline constexpr int kMaxDerivativeOrder = 2;

CurveTable make_table(const CurveScheme& scheme, const CurveSolution& solution);
// Adds the derivatives of a uniform scheme's table from psi[r - 1], the solution
// of derivative scheme r (difference_scheme.hpp) at the table's rate.
void add_derivatives(CurveTable& table, const std::vector<CurveSolution>& psi, const std::string& stop);
// Adds the first derivative of a non-uniform scheme's table: `derivative`
// holds phi_h' for every type at the table's rate (nonuniform_derivative.hpp).
void add_first_derivative(CurveTable& table, const CurveSolution& derivative, const std::string& stop);
// Back to the dense solution form (for checks), using the scheme's supports:
// the values, or with `order` r >= 1 the r-th derivatives. Throws sg::Error for
// a nonzero entry outside a function's open support, or an order it lacks.
CurveSolution table_to_solution(const CurveTable& table, const CurveScheme& scheme, int order = 0);

const char* placement_name(Placement p);

// Decimal digits of the table's exact numbers (numerators and denominators of
// every value and derivative value): the bulk of its JSON, and of the memory
// it holds. A rate n whose base-`arity` expansions of k/n have a long period
// makes denominators of that many digits, so this grows with n times the
// period (fourpoint at n = 4093: about 1.8e8), while a spline's stays small.
std::uint64_t exact_digits(const CurveTable& table);

}  // namespace sg
