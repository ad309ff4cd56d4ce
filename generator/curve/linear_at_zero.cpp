#include "curve/linear_at_zero.hpp"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <numeric>

#include <Eigen/Eigenvalues>

#include "algebra/exact_linear_system.hpp"
#include "base/error.hpp"
#include "curve/residue_solver.hpp"

namespace sg {

std::optional<std::size_t> type_at(const CurveScheme& s, long j) {
  for (std::size_t h = 0; h < s.types.size(); ++h)
    if (s.types[h].placed_at(j)) return h;
  return std::nullopt;
}

LinearAtZero linear_at_zero(const CurveScheme& s) {
  const long a = s.arity;
  // Control points whose supports can come near 0.
  long reach = 2;
  for (const ScalingType& t : s.types)
    reach = std::max({reach, std::labs(t.position) + 2, ceil_to_long(abs(t.support_lo)) + 2, ceil_to_long(abs(t.support_hi)) + 2});
  LinearAtZero out;
  // Nearest support ends on either side among the functions not in L.
  Rational right_end = reach, left_end = -reach;
  for (long j = -2 * reach; j <= 2 * reach; ++j) {
    const auto h = type_at(s, j);
    if (!h) continue;
    const Rational lo = s.types[*h].support_lo + j, hi = s.types[*h].support_hi + j;
    if (lo <= 0 && hi >= 0) out.functions.push_back({j, *h});
    else if (lo > 0) right_end = std::min(right_end, lo);
    else left_end = std::max(left_end, hi);
  }
  const auto index_of = [&](long j) -> std::optional<std::size_t> {
    for (std::size_t i = 0; i < out.functions.size(); ++i)
      if (out.functions[i].j == j) return i;
    return std::nullopt;
  };
  // A rate whose grid has at least three points in (0, right_end] and in
  // [left_end, 0), prime to the arity: then the points are not all tied to the
  // one that fixes the scale by the homogeneity l(a x) = a l(x), and the
  // linearity checks below can fail.
  long r = 3 * std::max(1L, ceil_to_long(Rational(1) / std::min(right_end, Rational(-left_end))));
  while (std::gcd(r, a) != 1) ++r;
  const CurveSolution values = solve_by_residues(s, r);
  auto l_at = [&](const std::vector<Rational>& xi, long K) {  // l(K / r)
    Rational sum = 0;
    for (std::size_t i = 0; i < out.functions.size(); ++i)
      sum += xi[i] * values.types[out.functions[i].type].at(K - out.functions[i].j * r);
    return sum;
  };
  // (S_LL - I / a) xi = 0, one row per fine function k in L, and l(1/r) = 1/r.
  ExactLinearSystem system(out.functions.size());
  std::map<std::size_t, std::vector<std::pair<std::size_t, Rational>>> rows;
  const auto m = static_cast<Eigen::Index>(out.functions.size());
  Eigen::MatrixXd local = Eigen::MatrixXd::Zero(m, m);  // S_LL in doubles, for its spectrum
  for (std::size_t i = 0; i < out.functions.size(); ++i) rows[i].emplace_back(i, Rational(-1, a));
  for (std::size_t c = 0; c < out.functions.size(); ++c) {
    const PlacedFunction& f = out.functions[c];
    for (const Term& term : s.types[f.type].terms) {
      const long k = a * f.j + term.shift;
      if (type_at(s, k) != term.type)
        throw Error(s.source + ": the refinement of control point " + std::to_string(f.j) + " puts type '" +
                    s.types[term.type].name + "' at fine point " + std::to_string(k) + ", where another type is placed");
      if (const auto row = index_of(k)) {
        rows[*row].emplace_back(c, term.coeff);
        local(static_cast<Eigen::Index>(*row), static_cast<Eigen::Index>(c)) += to_double(term.coeff);
      }
    }
  }
  for (const auto& [row, entries] : rows) system.add_equation(entries, 0);
  std::vector<std::pair<std::size_t, Rational>> scale;
  for (std::size_t i = 0; i < out.functions.size(); ++i)
    scale.emplace_back(i, values.types[out.functions[i].type].at(1 - out.functions[i].j * r));
  system.add_equation(scale, Rational(1, r));
  const LinearSolution xi = system.solve();
  if (xi.status != LinearSolution::Status::Unique)
    throw Error("the eigenvalue 1/" + std::to_string(a) + " of the subdivision at 0 has " + xi.describe() +
                " with l(1/" + std::to_string(r) + ") = 1/" + std::to_string(r) + " (no unique linear function there)");
  out.xi = xi.values;
  // A one-sided derivative needs 1/a to be the subdominant eigenvalue: every
  // other eigenvalue of S_LL but 1 smaller in modulus (in doubles, with a margin).
  {
    const Eigen::VectorXcd eigenvalues = Eigen::EigenSolver<Eigen::MatrixXd>(local, false).eigenvalues();
    std::vector<double> moduli;
    for (Eigen::Index i = 0; i < eigenvalues.size(); ++i) moduli.push_back(std::abs(eigenvalues[i]));
    std::sort(moduli.rbegin(), moduli.rend());
    const double sub = 1.0 / static_cast<double>(a);
    if (moduli.size() < 2 || std::abs(moduli[0] - 1) > 1e-9 || std::abs(moduli[1] - sub) > 1e-9 ||
        (moduli.size() > 2 && moduli[2] > sub * (1 - 1e-9)))
      throw Error("the subdivision at 0 has the eigenvalue moduli " + [&] {
        std::string list;
        for (std::size_t i = 0; i < std::min<std::size_t>(moduli.size(), 4); ++i) list += (i ? ", " : "") + std::to_string(moduli[i]);
        return list;
      }() + "...: 1/" + std::to_string(a) + " is not its simple subdominant eigenvalue, so no one-sided derivative there is shown");
  }
  if (l_at(out.xi, 0) != 0) throw Error("the linear function at 0 is not 0 there");
  for (long K = 1; Rational(K, r) <= right_end; ++K)
    if (l_at(out.xi, K) != Rational(K, r))
      throw Error("the homogeneous function at 0 is not linear right of 0 (l(" + to_string(Rational(K, r)) + ") = " +
                  excerpt(to_string(l_at(out.xi, K))) + ")");
  out.left_slope = -l_at(out.xi, -1) * r;
  out.left_linear = Rational(-2, r) >= left_end;  // at least one more point to check it by
  for (long K = -1; Rational(K, r) >= left_end; --K)
    if (l_at(out.xi, K) != out.left_slope * Rational(K, r)) out.left_linear = false;
  return out;
}

}  // namespace sg
