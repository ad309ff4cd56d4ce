#pragma once
// Independent reference computations for the tests. Nothing here calls the
// generator's solvers: Cox-de Boor recursion, plain subdivision of sequences
// and a dense Gauss-Jordan eigenvector solve, all in exact rationals.
#include <boost/multiprecision/gmp.hpp>
#include <map>
#include <stdexcept>
#include <vector>

namespace independent {

using Q = boost::multiprecision::mpq_rational;

// B-spline N_{i,p}(t) on the knot function knot(i), by the Cox-de Boor recursion.
template <class Knot>
Q cox_de_boor(const Knot& knot, long i, int p, const Q& t) {
  if (p == 0) return (knot(i) <= t && t < knot(i + 1)) ? Q(1) : Q(0);
  Q value = 0;
  const Q d1 = knot(i + p) - knot(i), d2 = knot(i + p + 1) - knot(i + 1);
  if (d1 != 0) value += (t - knot(i)) / d1 * cox_de_boor(knot, i, p - 1, t);
  if (d2 != 0) value += (knot(i + p + 1) - t) / d2 * cox_de_boor(knot, i + 1, p - 1, t);
  return value;
}

// The derivative of order `order` of N_{i,p}(t) (de Boor's formula
// N'_{i,p} = p/(t_{i+p} - t_i) N_{i,p-1} - p/(t_{i+p+1} - t_{i+1}) N_{i+1,p-1}, applied `order` times).
template <class Knot>
Q cox_de_boor_derivative(const Knot& knot, long i, int p, const Q& t, int order) {
  if (order == 0) return cox_de_boor(knot, i, p, t);
  if (p == 0) return 0;
  Q value = 0;
  const Q d1 = knot(i + p) - knot(i), d2 = knot(i + p + 1) - knot(i + 1);
  if (d1 != 0) value += Q(p) / d1 * cox_de_boor_derivative(knot, i, p - 1, t, order - 1);
  if (d2 != 0) value -= Q(p) / d2 * cox_de_boor_derivative(knot, i + 1, p - 1, t, order - 1);
  return value;
}

// A sequence p[i] on integers, zero outside the map.
using Sequence = std::map<long, Q>;

// One step of uniform subdivision of arity a with mask s[first..]: p'[a*i + m] += s_m p[i].
inline Sequence subdivide(const Sequence& p, long arity, long first, const std::vector<Q>& mask) {
  Sequence out;
  for (const auto& [i, v] : p)
    for (std::size_t m = 0; m < mask.size(); ++m)
      if (mask[m] != 0) out[arity * i + first + static_cast<long>(m)] += mask[m] * v;
  return out;
}

// Left eigenvector l (sum 1) for eigenvalue 1 of the finite subdivision matrix
// S[r][c] = s_{r - a c} on indices lo..hi, by Gauss-Jordan on (S^T - I | PoU).
inline std::map<long, Q> limit_stencil(long arity, long first, const std::vector<Q>& mask, long lo, long hi) {
  const long m = hi - lo + 1;
  auto s = [&](long idx) { return (idx >= first && idx < first + static_cast<long>(mask.size())) ? mask[idx - first] : Q(0); };
  // Equations: for each column c: sum_r l_r S[r][c] - l_c = 0; plus sum l = 1.
  std::vector<std::vector<Q>> A;
  for (long c = lo; c <= hi; ++c) {
    std::vector<Q> row(m + 1, 0);
    for (long r = lo; r <= hi; ++r) row[r - lo] += s(r - arity * c);
    row[c - lo] -= 1;
    A.push_back(row);
  }
  std::vector<Q> pou(m + 1, 1);
  A.push_back(pou);
  // Gauss-Jordan.
  long rank = 0;
  std::vector<long> where(m, -1);
  for (long col = 0; col < m && rank < static_cast<long>(A.size()); ++col) {
    long piv = -1;
    for (long r = rank; r < static_cast<long>(A.size()); ++r)
      if (A[r][col] != 0) { piv = r; break; }
    if (piv < 0) continue;
    std::swap(A[piv], A[rank]);
    const Q d = A[rank][col];
    for (auto& x : A[rank]) x /= d;
    for (long r = 0; r < static_cast<long>(A.size()); ++r)
      if (r != rank && A[r][col] != 0) {
        const Q f = A[r][col];
        for (long k = 0; k <= m; ++k) A[r][k] -= f * A[rank][k];
      }
    where[col] = rank++;
  }
  if (rank != m) throw std::runtime_error("limit stencil is not unique");
  std::map<long, Q> l;
  for (long c = 0; c < m; ++c) l[lo + c] = A[where[c]][m];
  return l;
}

}  // namespace independent
