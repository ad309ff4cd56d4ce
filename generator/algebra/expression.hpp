#pragma once
// A small exact formula language for scheme files: rationals, named parameters,
// + - * / ^ (integer exponent), parentheses and cos2pi(r) = cos(2 pi r) where
// that is rational (r a multiple of 1/4 or 1/6), e.g. "1/2 + w", "3/(2*v)",
// "(4 - 2*cos2pi(1/v))/9".
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include "algebra/rational.hpp"
#include "algebra/real.hpp"
#include "base/error.hpp"

namespace sg {

using Bindings = std::map<std::string, Rational>;

// Thrown by the exact evaluator where a value is irrational (cos2pi of most
// arguments), so that a caller can fall back to evaluate_expression_real.
struct IrrationalValue : Error {
  using Error::Error;
};

// Evaluates `text` exactly. Throws sg::Error naming the offending position or
// name (IrrationalValue where the value is irrational).
Rational evaluate_expression(std::string_view text, const Bindings& bindings);

// The same formula in high precision (Real): cos2pi is evaluated for any argument.
Real evaluate_expression_real(std::string_view text, const Bindings& bindings);

// cos(2 pi r) when it is rational (Niven's theorem: 0, +-1/2, +-1), else nullopt.
std::optional<Rational> exact_cos2pi(const Rational& r);

}  // namespace sg
