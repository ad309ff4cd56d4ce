#include "algebra/rational.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <new>

#include "base/error.hpp"

namespace sg {

namespace {

// GMP (and MPFR, which allocates through it) ends the process when an
// allocation fails; these throw std::bad_alloc instead, so that an impossible
// allocation reaches the caller, and stencilgen's error boundary, like any other.
void* gmp_allocate(std::size_t size) {
  void* p = std::malloc(size);
  if (!p) throw std::bad_alloc();
  return p;
}
void* gmp_reallocate(void* old, std::size_t, std::size_t size) {
  void* p = std::realloc(old, size);
  if (!p) throw std::bad_alloc();
  return p;
}
void gmp_free(void* p, std::size_t) { std::free(p); }
[[maybe_unused]] const bool kGmpAllocationThrows = (mp_set_memory_functions(gmp_allocate, gmp_reallocate, gmp_free), true);

bool all_digits(std::string_view s) {
  if (s.empty()) return false;
  for (char c : s)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  return true;
}
}  // namespace

Rational parse_rational(std::string_view text) {
  std::string_view body = text;
  bool negative = false;
  if (!body.empty() && (body.front() == '-' || body.front() == '+')) {
    negative = body.front() == '-';
    body.remove_prefix(1);
  }
  const auto slash = body.find('/');
  const std::string_view num = body.substr(0, slash);
  const std::string_view den = slash == std::string_view::npos ? std::string_view("1") : body.substr(slash + 1);
  if (!all_digits(num) || !all_digits(den))
    throw Error("'" + std::string(text) + "' is not an exact rational (expected p or p/q with integers p, q)");
  const Integer n{std::string(num)}, d{std::string(den)};
  if (d == 0) throw Error("'" + std::string(text) + "' has a zero denominator");
  Rational r(n, d);
  return negative ? Rational(-r) : r;
}

std::string to_string(const Rational& value) {
  if (denominator(value) == 1) return numerator(value).str();
  return numerator(value).str() + "/" + denominator(value).str();
}

bool fits_long(const Integer& value) {
  return value <= std::numeric_limits<long>::max() && value >= std::numeric_limits<long>::min();
}

long to_long(const Integer& value, const std::string& what) {
  if (!fits_long(value)) throw Error(what + " " + value.str() + " does not fit in a 64-bit integer");
  return value.convert_to<long>();
}

Integer floor_integer(const Rational& value) {
  Integer q = numerator(value) / denominator(value);  // truncates toward zero
  if (value < 0 && q * denominator(value) != numerator(value)) q -= 1;
  return q;
}

long floor_to_long(const Rational& value) {
  const Integer q = floor_integer(value);
  if (!fits_long(q)) throw Error("the floor of " + to_string(value) + " does not fit in a 64-bit integer");
  return q.convert_to<long>();
}

long ceil_to_long(const Rational& value) {
  const Integer q = -floor_integer(-value);  // negated as an Integer, where it cannot overflow
  if (!fits_long(q)) throw Error("the ceiling of " + to_string(value) + " does not fit in a 64-bit integer");
  return q.convert_to<long>();
}

double to_double(const Rational& value) {
  // Round-to-nearest-even by hand: mpz's own conversion truncates.
  if (value == 0) return 0.0;
  Integer n = abs(numerator(value)), d = denominator(value);
  // Scale so that the integer quotient has at least 64 bits.
  const long shift = static_cast<long>(msb(n)) - static_cast<long>(msb(d)) - 66;
  if (shift > 0) d <<= shift; else n <<= -shift;
  Integer q, rem;
  divide_qr(n, d, q, rem);
  const long drop = static_cast<long>(msb(q)) - 52;  // bits below the 53 we keep
  Integer keep = q >> drop;
  const Integer rest = q - (keep << drop);
  const Integer half = Integer(1) << (drop - 1);
  if (rest > half || (rest == half && (rem != 0 || (keep & 1) != 0))) keep += 1;
  const double result = std::ldexp(keep.convert_to<double>(), static_cast<int>(shift + drop));
  return value < 0 ? -result : result;
}

}  // namespace sg
