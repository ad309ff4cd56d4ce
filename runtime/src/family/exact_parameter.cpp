#include "stencil_runtime/exact_parameter.hpp"

#include <charconv>
#include <numeric>

namespace stencil_runtime {

namespace {

[[noreturn]] void overflow(const char* what) {
  throw ParameterOverflow(std::string("exact parameter arithmetic overflows 64 bits (") + what + ")");
}

std::int64_t checked_mul(std::int64_t a, std::int64_t b) {
  std::int64_t r = 0;
  if (__builtin_mul_overflow(a, b, &r)) overflow("multiplication");
  return r;
}

std::int64_t checked_add(std::int64_t a, std::int64_t b) {
  std::int64_t r = 0;
  if (__builtin_add_overflow(a, b, &r)) overflow("addition");
  return r;
}

}  // namespace

Fraction Fraction::make(std::int64_t num, std::int64_t den) {
  if (den == 0) throw EvaluationError("a parameter with a zero denominator");
  // Reduced in 128 bits: -2^63 has no 64-bit negation, yet -2^63/1 and
  // 2/-2^63 (= -1/2^62) are fractions the type holds.
  __extension__ typedef __int128 Wide;
  Wide n = num, d = den;
  if (d < 0) n = -n, d = -d;
  const auto magnitude = static_cast<std::uint64_t>(n < 0 ? -n : n);  // at most 2^63
  const Wide g = static_cast<Wide>(std::gcd(magnitude, static_cast<std::uint64_t>(d)));
  n /= g, d /= g;
  if (n < INT64_MIN || n > INT64_MAX || d > INT64_MAX) overflow("a denominator of 2^63");
  return {static_cast<std::int64_t>(n), static_cast<std::int64_t>(d)};
}

std::string Fraction::str() const { return den == 1 ? std::to_string(num) : std::to_string(num) + "/" + std::to_string(den); }

Fraction parse_fraction(std::string_view text) {
  auto whole = [&](std::string_view part, std::int64_t& out) {
    if (!part.empty() && part[0] == '+') part.remove_prefix(1);
    const auto [end, err] = std::from_chars(part.data(), part.data() + part.size(), out);
    return !part.empty() && err == std::errc() && end == part.data() + part.size();
  };
  const auto slash = text.find('/');
  std::int64_t num = 0, den = 1;
  if (!whole(text.substr(0, slash), num) || (slash != std::string_view::npos && !whole(text.substr(slash + 1), den)))
    throw EvaluationError(quoted_excerpt(text) + " is not an exact rational p/q with 64-bit integers p and q");
  if (den == 0) throw EvaluationError(quoted_excerpt(text) + " has a zero denominator");
  try {
    return Fraction::make(num, den);
  } catch (const ParameterOverflow&) {  // 1/-2^63: its denominator 2^63 does not fit
    throw EvaluationError(quoted_excerpt(text) + " is not an exact rational p/q with 64-bit integers p and q once reduced");
  }
}

Fraction add(const Fraction& a, const Fraction& b) {
  const std::int64_t g = std::gcd(a.den, b.den);
  const std::int64_t da = a.den / g, db = b.den / g;
  return Fraction::make(checked_add(checked_mul(a.num, db), checked_mul(b.num, da)), checked_mul(a.den, db));
}

Fraction subtract(const Fraction& a, const Fraction& b) {
  if (b.num == INT64_MIN) overflow("negation");
  return add(a, {-b.num, b.den});
}

Fraction multiply(const Fraction& a, std::int64_t k) {
  const std::int64_t g = std::gcd(k, a.den);
  return Fraction::make(checked_mul(a.num, k / g), a.den / g);
}

int compare(const Fraction& a, const Fraction& b) {
  // a.num * b.den vs b.num * a.den, in 128 bits (both denominators positive).
  __extension__ typedef __int128 Wide;  // GCC and Clang: no warning under -Wpedantic
  const Wide l = static_cast<Wide>(a.num) * b.den, r = static_cast<Wide>(b.num) * a.den;
  return l < r ? -1 : (l > r ? 1 : 0);
}

}  // namespace stencil_runtime
