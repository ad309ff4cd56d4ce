#include "curve_orbit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <string>
#include <vector>

#include "family/parameter_ops.hpp"
#include "stencil_runtime/error.hpp"

namespace stencil_runtime {

namespace {

// One halving carried back: w <- w H_c, dw <- 2 dw H_c, with the sums restored.
void carry_back(const HalfMatrices& half, int c, double* w, double* dw) {
  double nw[4] = {0, 0, 0, 0}, nd[4] = {0, 0, 0, 0};
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 4; ++j) {
      nw[j] += w[k] * half[c][k][j];
      nd[j] += 2 * dw[k] * half[c][k][j];
    }
  const double sw = nw[0] + nw[1] + nw[2] + nw[3], sd = nd[0] + nd[1] + nd[2] + nd[3];
  for (int j = 0; j < 4; ++j) w[j] = nw[j] + (1 - sw) / 4, dw[j] = nd[j] - sd / 4;
}

struct Orbit {
  std::vector<int> children;  // c at each step
  std::size_t cycle_start = 0;
};

// Power iteration around the cycle children[s..end): returns once both rows are stable.
void solve_cycle(const HalfMatrices& half, const Orbit& orbit, double* w, double* dw) {
  const std::size_t s = orbit.cycle_start, r = orbit.children.size() - s;
  // Any start with the right sums: the uniform row and the slope of a line.
  for (int j = 0; j < 4; ++j) w[j] = 0.25, dw[j] = (2.0 * j - 3.0) / 10.0;  // sum 0, sum_p p dw_p = 1 (p = j - 1)
  const std::int64_t max_cycles = std::max<std::int64_t>(64, kMaxOrbitSteps / static_cast<std::int64_t>(r));
  for (std::int64_t cycle = 0; cycle < max_cycles; ++cycle) {
    double pw[4], pd[4];
    std::copy(w, w + 4, pw), std::copy(dw, dw + 4, pd);
    for (std::size_t i = orbit.children.size(); i-- > s;) carry_back(half, orbit.children[i], w, dw);
    // The eigenvalue of 2^r M for v' is 1; rescale against drift.
    const double slope = -dw[0] + dw[2] + 2 * dw[3];
    if (!(std::fabs(slope) > 0)) break;
    for (int j = 0; j < 4; ++j) dw[j] /= slope;
    double change = 0, size = 0;
    for (int j = 0; j < 4; ++j) {
      change = std::max({change, std::fabs(w[j] - pw[j]), std::fabs(dw[j] - pd[j])});
      size = std::max({size, std::fabs(w[j]), std::fabs(dw[j])});
    }
    if (change <= 4 * std::numeric_limits<double>::epsilon() * size) return;
  }
  throw EvaluationError("the regular curve's basis did not converge around the parameter's cycle of " + std::to_string(r) +
                        " halvings (the scheme is not C1 there)");
}

// One halving, t -> 2t - c: exact in doubles; for fractions in 128 bits, since
// 2 num may not fit in 64 although the result (in [0, den]) does.
double halve(double t, int c) { return scale_minus(t, 2, c); }
__extension__ typedef __int128 Wide;
Fraction halve(const Fraction& t, int c) {
  const Wide num = static_cast<Wide>(t.num) * 2 - static_cast<Wide>(c) * t.den;
  return Fraction::make(static_cast<std::int64_t>(num), t.den);
}

template <class P, class Held>
void follow(const HalfMatrices& half, P t, const Held& held, double* w, double* dw) {
  Orbit orbit;
  // Once the denominator is odd, t -> 2t - c is doubling modulo 1 on the
  // fractions k/den, a bijection: the orbit is purely periodic from there, so
  // the first such point is the one it comes back to.
  bool odd_seen = false;
  P first_odd{};
  for (std::int64_t step = 0;; ++step) {
    if (held(t, w, dw)) break;
    if (step == kMaxOrbitSteps)
      throw EvaluationError("the parameter's orbit under halving is longer than " + std::to_string(kMaxOrbitSteps) +
                            " steps (a denominator too large for evaluation between the stored grids)");
    if constexpr (std::is_same_v<P, Fraction>) {
      if ((t.den & 1) != 0) {
        if (!odd_seen) {
          odd_seen = true, first_odd = t, orbit.cycle_start = orbit.children.size();
        } else if (t == first_odd) {
          solve_cycle(half, orbit, w, dw);
          orbit.children.resize(orbit.cycle_start);  // carry back from the cycle's first point
          break;
        }
      }
    }
    const int c = greater(t, 1, 2) ? 1 : 0;
    orbit.children.push_back(c);
    t = halve(t, c);
  }
  for (std::size_t i = orbit.children.size(); i-- > 0;) carry_back(half, orbit.children[i], w, dw);
}

}  // namespace

void curve_basis_by_orbit(const HalfMatrices& half, const Fraction& t,
                          const std::function<bool(const Fraction&, double*, double*)>& held, double* w, double* dw) {
  if (t.den <= 0 || t.num < 0 || t.num > t.den) throw EvaluationError("curve parameter " + t.str() + " is outside [0, 1]");
  follow(half, Fraction::make(t.num, t.den), held, w, dw);  // the cycle test compares reduced fractions
}

void curve_basis_by_orbit(const HalfMatrices& half, double t, const std::function<bool(double, double*, double*)>& held,
                          double* w, double* dw) {
  if (!(t >= 0 && t <= 1)) throw EvaluationError("curve parameter " + std::to_string(t) + " is outside [0, 1]");
  follow(half, t, held, w, dw);
}

}  // namespace stencil_runtime
