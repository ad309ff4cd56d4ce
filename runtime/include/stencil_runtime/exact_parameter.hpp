#pragma once
// Exact rational parameters with 64-bit numerators and denominators and
// overflow-checked arithmetic: a parameter such as 1/3 is evaluated exactly
// where the tables (or the scheme's own subdivision of a patch) hold it.
#include <cstdint>
#include <string>
#include <string_view>

#include "error.hpp"

namespace stencil_runtime {

// Exact parameter arithmetic that would need more than 64 bits; evaluation
// then continues at the nearest double (Surface::evaluate with a tolerance).
struct ParameterOverflow : EvaluationError {
  using EvaluationError::EvaluationError;
};

struct Fraction {
  std::int64_t num = 0, den = 1;  // lowest terms, den > 0

  // num/den reduced; throws EvaluationError for a zero denominator or a
  // value whose reduced form does not fit.
  static Fraction make(std::int64_t num, std::int64_t den);
  double to_double() const { return static_cast<double>(num) / static_cast<double>(den); }
  std::string str() const;  // "p/q", or "p" when q == 1
  bool operator==(const Fraction&) const = default;
};

// "3", "1/3", "-2/4" (reduced); throws EvaluationError naming the text for
// anything else, including numbers that do not fit in 64 bits.
Fraction parse_fraction(std::string_view text);

// Overflow-checked operations (throw ParameterOverflow naming the operation).
Fraction add(const Fraction& a, const Fraction& b);
Fraction subtract(const Fraction& a, const Fraction& b);
Fraction multiply(const Fraction& a, std::int64_t k);
int compare(const Fraction& a, const Fraction& b);  // -1, 0, 1

// A face parameter (u, v): see face_domain.hpp for what it means on each face.
struct ExactParameter {
  Fraction u, v;
  std::string str() const {
    std::string out("(");  // appended: GCC 12 warns falsely (-Wrestrict) on "(" + string once inlined
    out += u.str(), out += ", ", out += v.str(), out += ")";
    return out;
  }
};

}  // namespace stencil_runtime
