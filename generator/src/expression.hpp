#pragma once
// A small exact formula language for scheme files: rationals, named parameters,
// + - * / ^ (integer exponent) and parentheses, e.g. "1/2 + w" or "3/(2*v)".
#include <map>
#include <string>
#include <string_view>

#include "rational.hpp"

namespace sg {

using Bindings = std::map<std::string, Rational>;

// Evaluates `text` exactly. Throws sg::Error naming the offending position or name.
Rational evaluate_expression(std::string_view text, const Bindings& bindings);

}  // namespace sg
