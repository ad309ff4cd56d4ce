#include "curve/difference_scheme.hpp"

#include <algorithm>

#include "curve/residue_solver.hpp"
#include "curve/support.hpp"

namespace sg {

namespace {

using Mask = std::map<long, Rational>;

// Coefficients beyond this many make the contractivity check give up (it
// multiplies q(z) q(z^a) ... whose length grows like a^L).
constexpr std::size_t kMaxProductLength = 1 << 15;

// m / sigma when sigma = 1 + z + ... + z^(a-1) divides m exactly.
bool divide_by_sigma(const Mask& m, int a, Mask& quotient) {
  quotient.clear();
  if (m.empty()) return true;
  const long lo = m.begin()->first, hi = m.rbegin()->first;
  auto at = [&](const Mask& p, long k) {
    const auto it = p.find(k);
    return it == p.end() ? Rational(0) : it->second;
  };
  // m_k = sum_{j=0..a-1} q_(k-j): solve for q from the lowest term up.
  for (long k = lo; k <= hi - (a - 1); ++k) {
    Rational q = at(m, k);
    for (long j = 1; j < a; ++j) q -= at(quotient, k - j);
    if (q != 0) quotient[k] = q;
  }
  for (long k = std::max(lo, hi - (a - 1) + 1); k <= hi; ++k) {  // the remainder must vanish
    Rational sum = 0;
    for (long j = 0; j < a; ++j) sum += at(quotient, k - j);
    if (sum != at(m, k)) return false;
  }
  return true;
}

std::string coefficient_list(const Mask& m) {
  std::string out;
  for (const auto& [k, c] : m) out += (out.empty() ? "" : ", ") + to_string(c);
  return "(" + out + ")";
}

}  // namespace

bool converges(const Mask& mask, int arity, int max_steps, std::string& why) {
  Mask q;
  if (!divide_by_sigma(mask, arity, q)) {
    why = "does not reproduce constants (its symbol is not divisible by 1 + z" + std::string(arity == 3 ? " + z^2" : "") + ")";
    return false;
  }
  if (q.empty()) {
    why = "has a zero difference scheme";
    return false;
  }
  // P_L(z) = q(z) q(z^a) ... q(z^(a^(L-1))), dense from its lowest power.
  const long q_lo = q.begin()->first, q_hi = q.rbegin()->first;
  std::vector<Rational> product(static_cast<std::size_t>(q_hi - q_lo + 1));
  for (const auto& [k, c] : q) product[static_cast<std::size_t>(k - q_lo)] = c;
  long product_lo = q_lo, scale = 1;  // scale = a^L after L factors
  Rational best = -1;
  int tried = 0;
  for (int step = 1; step <= max_steps; ++step) {
    tried = step;
    scale *= arity;
    // ||S_q^L||_inf: the largest sum of |coefficients| over one residue class mod a^L.
    std::vector<Rational> sums(static_cast<std::size_t>(scale));
    for (std::size_t i = 0; i < product.size(); ++i) {
      const long k = product_lo + static_cast<long>(i);
      sums[static_cast<std::size_t>(((k % scale) + scale) % scale)] += abs(product[i]);
    }
    const Rational norm = *std::max_element(sums.begin(), sums.end());
    if (norm < 1) return true;
    if (best < 0 || norm < best) best = norm;
    // Next factor q(z^(a^L)).
    const std::size_t length = product.size() + static_cast<std::size_t>((q_hi - q_lo) * scale);
    if (step == max_steps || length > kMaxProductLength) break;
    std::vector<Rational> next(length);
    for (std::size_t i = 0; i < product.size(); ++i) {
      if (product[i] == 0) continue;
      for (const auto& [k, c] : q) next[i + static_cast<std::size_t>((k - q_lo) * scale)] += product[i] * c;
    }
    product.swap(next);
    product_lo += q_lo * scale;
  }
  why = "does not converge by Dyn and Levin's test: its own difference scheme " + coefficient_list(q) +
        " is not contractive within " + std::to_string(tried) + " steps (smallest norm of a power: " + to_string(best) + ")";
  return false;
}

std::vector<long> difference_weights(int r) {
  std::vector<long> w(static_cast<std::size_t>(r) + 1);
  long c = 1;
  for (int i = 0; i <= r; ++i) {
    w[static_cast<std::size_t>(i)] = (i % 2 ? -c : c);
    c = c * (r - i) / (i + 1);
  }
  return w;
}

std::map<long, Rational> derivative_from_difference(const TypeValues& psi, int r, long n) {
  const std::vector<long> w = difference_weights(r);
  // phi^(r)(k/n) = sum_i w_i psi_r(k/n - i): psi_r's grid shifted by i n.
  std::map<long, Rational> out;
  for (long k = psi.range.first; k <= psi.range.last + static_cast<long>(r) * n; ++k) {
    Rational value = 0;
    for (std::size_t i = 0; i < w.size(); ++i) value += w[i] * psi.at(k - static_cast<long>(i) * n);
    if (value != 0) out[k] = value;
  }
  return out;
}

std::string convergence_doubt(const CurveScheme& scheme) {
  if (!scheme.is_uniform() || scheme.types[0].placement != Placement::Everywhere) return "";
  Mask s;
  for (const Term& t : scheme.types[0].terms) s[t.shift] += t.coeff;
  std::string why;
  if (converges(s, scheme.arity, 16, why)) return "";
  return "its mask " + coefficient_list(s) + " " + why;
}

DerivativeSchemes derivative_schemes(const CurveScheme& scheme, int max_order) {
  DerivativeSchemes out;
  if (!scheme.is_uniform() || scheme.types[0].placement != Placement::Everywhere) {
    out.stop = "derivative tables are made for uniform schemes only (a non-uniform scheme's derivative is not yet generated)";
    return out;
  }
  const int a = scheme.arity;
  Mask s;
  for (const Term& t : scheme.types[0].terms) s[t.shift] += t.coeff;
  for (int r = 1; r <= max_order; ++r) {
    Mask next;
    if (!divide_by_sigma(s, a, next)) {
      out.stop = "the scheme does not reproduce constants at order " + std::to_string(r - 1);
      return out;
    }
    for (auto& [k, c] : next) c *= a;
    std::string why;
    if (!converges(next, a, 16, why)) {
      Mask unused;
      const bool disproved = !divide_by_sigma(next, a, unused);
      out.stop = std::string(disproved ? "not C" : "not shown to be C") + std::to_string(r) + ": its order-" +
                 std::to_string(r) + " difference scheme " + coefficient_list(next) + " " + why;
      return out;
    }
    CurveScheme d;
    d.name = scheme.name + " (derivative scheme " + std::to_string(r) + ")";
    d.kind = "uniform";
    d.arity = a;
    d.hash = scheme.hash;
    ScalingType type{"psi" + std::to_string(r), Placement::Everywhere, 0, {}, 0, 0};
    for (const auto& [k, c] : next) type.terms.push_back({0, k, c});
    d.types = {type};
    compute_supports(d);
    out.schemes.push_back(std::move(d));
    s = std::move(next);
  }
  return out;
}

CurveTable table_with_derivatives(const CurveScheme& scheme, const CurveSolution& values, const DerivativeSchemes& derivatives) {
  CurveTable table = make_table(scheme, values);
  std::vector<CurveSolution> psi;
  for (const CurveScheme& d : derivatives.schemes) psi.push_back(solve_by_residues(d, values.n));
  add_derivatives(table, psi, derivatives.stop);
  return table;
}

}  // namespace sg
