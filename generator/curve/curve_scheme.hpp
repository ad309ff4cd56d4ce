#pragma once
// A stationary curve scheme, reduced to what the solvers need: a finite set of
// scaling-function *types* and the exact refinement relation of each.
//
// Type h has a scaling function phi_h in its own local coordinate and satisfies
//     phi_h(x) = sum_terms coeff * phi_type(arity * x - shift).
// A uniform scheme has one type placed at every integer j (basis of control
// point j is phi(x - j)). A non-uniform scheme has a left uniform type (placed
// at j <= position), a right one (j >= position) and one special type per
// column near the special point 0, placed at its single column index p: the
// basis of control point p is phi_h(x - p). Parameters are global: control
// point j sits at x = j, and the special point is x = 0.
#include <cstdint>
#include <string>
#include <vector>

#include "algebra/expression.hpp"
#include "algebra/rational.hpp"

namespace sg {

struct Term {
  std::size_t type;  // index into CurveScheme::types
  long shift;
  Rational coeff;
};

enum class Placement { Everywhere, AtMost, AtLeast, Single };

struct ScalingType {
  std::string name;
  Placement placement = Placement::Everywhere;
  long position = 0;  // AtMost: j <= position; AtLeast: j >= position; Single: j == position
  std::vector<Term> terms;
  // Closed support [lo, hi] of phi_h in local coordinates (exact; see support.hpp).
  Rational support_lo, support_hi;

  bool placed_at(long j) const {
    switch (placement) {
      case Placement::Everywhere: return true;
      case Placement::AtMost: return j <= position;
      case Placement::AtLeast: return j >= position;
      case Placement::Single: return j == position;
    }
    return false;
  }
  bool translation_invariant() const { return placement != Placement::Single; }
};

// Self-similar knot sequence t_i = left * i (i < 0), right * i (i >= 0).
struct KnotSpec {
  int degree = 3;
  Rational left_spacing = 1, right_spacing = 1;
};

struct CurveScheme {
  std::string name;
  std::string description;
  std::string source;          // file it was read from
  std::string kind;            // "uniform", "columns" or "knots"
  int arity = 2;
  Bindings parameters;         // resolved values (after command-line overrides)
  std::uint64_t hash = 0;      // of the canonical scheme content, parameters included
  std::vector<ScalingType> types;

  // A uniform scheme has a single type, placed at every integer.
  bool is_uniform() const { return types.size() == 1; }
};

}  // namespace sg
