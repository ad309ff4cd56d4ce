#pragma once
// One scheme at one rate n: the exact values of every scaling function on (1/n)Z,
// with the identity of the scheme that produced them. Serialised as exact JSON
// (curve_table_json) and compact binary (curve_table_binary); see docs/table-format.md.
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
  };
  std::string scheme;
  std::string scheme_hash;  // hex of CurveScheme::hash
  Bindings parameters;
  int arity = 2;
  long n = 1;
  std::vector<Function> functions;
};

CurveTable make_table(const CurveScheme& scheme, const CurveSolution& solution);
// Back to the dense solution form (for checks), using the scheme's supports.
CurveSolution table_to_solution(const CurveTable& table, const CurveScheme& scheme);

const char* placement_name(Placement p);

}  // namespace sg
