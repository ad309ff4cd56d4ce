#pragma once
// The few operations the descent through a patch's children needs, for exact
// parameters (Fraction, overflow-checked) and real ones (double). The real
// operations are exact in binary floating point where the descent uses them:
// 2x - c for x in [c/2, (c+1)/2] and 1 - x for x in [1/2, 1] (Sterbenz);
// 1 - x for small x may round by at most half an ulp of 1, which the bounds allow for.
#include <cmath>
#include <cstdint>
#include <optional>
#include <type_traits>

#include "stencil_runtime/exact_parameter.hpp"

namespace stencil_runtime {

inline double to_real(const Fraction& x) { return x.to_double(); }
inline double to_real(double x) { return x; }

inline bool greater(const Fraction& x, std::int64_t num, std::int64_t den) { return compare(x, Fraction{num, den}) > 0; }
inline bool greater(double x, std::int64_t num, std::int64_t den) { return x * static_cast<double>(den) > static_cast<double>(num); }

// k x - c
inline Fraction scale_minus(const Fraction& x, std::int64_t k, std::int64_t c) { return subtract(multiply(x, k), Fraction{c, 1}); }
inline double scale_minus(double x, std::int64_t k, std::int64_t c) { return static_cast<double>(k) * x - static_cast<double>(c); }

// c - x
inline Fraction from(std::int64_t c, const Fraction& x) { return subtract(Fraction{c, 1}, x); }
inline double from(std::int64_t c, double x) { return static_cast<double>(c) - x; }

// The Fraction arithmetic of exact_parameter.hpp for doubles, so that one
// template serves both (the triangle family's child maps).
inline double add(double a, double b) { return a + b; }
inline double subtract(double a, double b) { return a - b; }
inline double multiply(double a, std::int64_t k) { return a * static_cast<double>(k); }
inline int compare(double a, double b) { return a < b ? -1 : (a > b ? 1 : 0); }
// A parameter with its derivatives along the original face's (u, v) (forward
// differentiation): the same child maps, run on Duals, carry the Jacobian of
// the map from the face's parameter to a sub-patch's, exactly (the maps are
// affine with integer coefficients). Comparisons use the value alone.
struct Dual {
  double value = 0, du = 0, dv = 0;
};
inline double to_real(const Dual& x) { return x.value; }
inline Dual add(const Dual& a, const Dual& b) { return {a.value + b.value, a.du + b.du, a.dv + b.dv}; }
inline Dual subtract(const Dual& a, const Dual& b) { return {a.value - b.value, a.du - b.du, a.dv - b.dv}; }
inline Dual multiply(const Dual& a, std::int64_t k) {
  const double f = static_cast<double>(k);
  return {a.value * f, a.du * f, a.dv * f};
}
inline int compare(const Dual& a, const Dual& b) { return compare(a.value, b.value); }
inline Dual scale_minus(const Dual& x, std::int64_t k, std::int64_t c) {
  return subtract(multiply(x, k), Dual{static_cast<double>(c), 0, 0});
}
inline Dual from(std::int64_t c, const Dual& x) { return subtract(Dual{static_cast<double>(c), 0, 0}, x); }

// The same with an exact value: a descent that must end at a parameter the
// tables hold (sqrt(3)'s derivative stencils) finds it exactly.
struct ExactDual {
  Fraction value;
  double du = 0, dv = 0;
};
inline double to_real(const ExactDual& x) { return x.value.to_double(); }
inline ExactDual add(const ExactDual& a, const ExactDual& b) { return {add(a.value, b.value), a.du + b.du, a.dv + b.dv}; }
inline ExactDual subtract(const ExactDual& a, const ExactDual& b) {
  return {subtract(a.value, b.value), a.du - b.du, a.dv - b.dv};
}
inline ExactDual multiply(const ExactDual& a, std::int64_t k) {
  const double f = static_cast<double>(k);
  return {multiply(a.value, k), a.du * f, a.dv * f};
}
inline int compare(const ExactDual& a, const ExactDual& b) { return compare(a.value, b.value); }
inline ExactDual scale_minus(const ExactDual& x, std::int64_t k, std::int64_t c) {
  return subtract(multiply(x, k), ExactDual{Fraction{c, 1}, 0, 0});
}
inline ExactDual from(std::int64_t c, const ExactDual& x) { return subtract(ExactDual{Fraction{c, 1}, 0, 0}, x); }

template <class P>
P integer(std::int64_t c) {
  if constexpr (std::is_same_v<P, Fraction>) return Fraction{c, 1};
  else if constexpr (std::is_same_v<P, Dual>) return Dual{static_cast<double>(c), 0, 0};
  else if constexpr (std::is_same_v<P, ExactDual>) return ExactDual{Fraction{c, 1}, 0, 0};
  else return static_cast<double>(c);
}

// A double as the exact dyadic fraction it is, when its denominator fits in 62 bits.
inline std::optional<Fraction> exact_fraction(double x) {
  if (!std::isfinite(x)) return std::nullopt;
  if (x == 0) return Fraction{0, 1};
  int e = 0;
  const double m = std::frexp(x, &e);  // x = m 2^e, 0.5 <= |m| < 1
  std::int64_t num = static_cast<std::int64_t>(std::ldexp(m, 53));  // exact: 53 bits
  int den_bits = 53 - e;
  while (den_bits > 0 && (num & 1) == 0) num /= 2, --den_bits;
  if (den_bits < 0) {
    if (den_bits < -9) return std::nullopt;
    return Fraction{num * (std::int64_t{1} << -den_bits), 1};
  }
  if (den_bits > 62) return std::nullopt;
  return Fraction{num, std::int64_t{1} << den_bits};
}

}  // namespace stencil_runtime
