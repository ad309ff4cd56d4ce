#pragma once
// Exact arithmetic for the generator: GMP rationals and integers through
// Boost.Multiprecision. Nothing on the exact path uses floating point.
#include <boost/multiprecision/gmp.hpp>
#include <string>
#include <string_view>

namespace sg {

using Rational = boost::multiprecision::mpq_rational;
using Integer = boost::multiprecision::mpz_int;

// Parses "7", "-3", "+5", "-1/16" (no spaces, nonzero denominator). Throws sg::Error.
Rational parse_rational(std::string_view text);

// "p/q" in lowest terms, or "p" when q == 1.
std::string to_string(const Rational& value);

// Whether `value` is in the range of long.
bool fits_long(const Integer& value);
// `value` as a long; throws sg::Error ("WHAT VALUE does not fit ...") when it is out of range.
long to_long(const Integer& value, const std::string& what);

// The largest integer <= value, exactly.
Integer floor_integer(const Rational& value);

// floor and ceiling of a rational as a (small) integer; throw sg::Error if it does not fit.
long floor_to_long(const Rational& value);
long ceil_to_long(const Rational& value);

// Nearest double (ties to even), via MPFR-free exact rounding.
double to_double(const Rational& value);

}  // namespace sg
