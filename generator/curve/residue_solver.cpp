#include "curve/residue_solver.hpp"

#include <algorithm>
#include <cstdlib>

#include "algebra/exact_linear_system.hpp"
#include "algebra/integer_division.hpp"
#include "base/error.hpp"
#include "curve/difference_scheme.hpp"
#include "curve/partition_of_unity.hpp"
#include "curve/special_columns.hpp"

namespace sg {
namespace {

// Unknowns of one residue class r: values phi_h(j + r/n) for invariant types h.
struct ResidueLayout {
  struct Block { std::size_t type; long jmin, jmax; std::size_t base; };
  std::vector<Block> blocks;
  std::size_t size = 0;
  long slot(std::size_t type, long j) const {
    for (const Block& b : blocks)
      if (b.type == type) return (j >= b.jmin && j <= b.jmax) ? static_cast<long>(b.base + (j - b.jmin)) : -1;
    return -1;
  }
};

// Integer transfer matrix: D * (v_r in terms of v_{a r mod n}), as sparse rows.
using SparseRow = std::vector<std::pair<std::size_t, Integer>>;
using DenseMatrix = std::vector<std::vector<Integer>>;

class InvariantPart {
 public:
  InvariantPart(const CurveScheme& s, long n, CurveSolution& sol) : s_(s), n_(n), a_(s.arity), sol_(sol) {
    for (std::size_t h = 0; h < s.types.size(); ++h)
      if (s.types[h].translation_invariant()) inv_.push_back(h);
    for (std::size_t h : inv_)
      for (const Term& t : s.types[h].terms) {
        if (!s.types[t.type].translation_invariant())
          throw Error(s.source + ": uniform type '" + s.types[h].name + "' refers to special type '" +
                      s.types[t.type].name + "'");
        scale_ = lcm(scale_, denominator(t.coeff));
      }
    layouts_.resize(n);
    for (long r = 0; r < n; ++r) {
      ResidueLayout& L = layouts_[r];
      for (std::size_t h : inv_) {
        const GridRange& g = sol.types[h].range;
        const long jmin = ceil_div(g.first - r, n), jmax = floor_div(g.last - r, n);
        if (jmax < jmin) continue;
        L.blocks.push_back({h, jmin, jmax, L.size});
        L.size += static_cast<std::size_t>(jmax - jmin + 1);
      }
    }
    transfer_.resize(n);
    for (long r = 0; r < n; ++r) transfer_[r] = build_transfer(r);
  }

  void solve() {
    const long n = n_;
    std::vector<int> color(n, 0);  // 0 new, 1 on stack, 2 done
    std::vector<char> solved(n, 0);
    values_.resize(n);
    // Cycles of r -> a r mod n.
    for (long start = 0; start < n; ++start) {
      std::vector<long> path;
      long r = start;
      while (color[r] == 0) {
        color[r] = 1;
        path.push_back(r);
        r = next(r);
      }
      if (color[r] == 1) {
        const auto it = std::find(path.begin(), path.end(), r);
        std::vector<long> cycle(it, path.end());
        std::rotate(cycle.begin(), std::min_element(cycle.begin(), cycle.end()), cycle.end());
        solve_cycle(cycle);
        for (long c : cycle) solved[c] = 1;
      }
      for (long p : path) color[p] = 2;
    }
    // Trees: substitute toward the cycles.
    for (long start = 0; start < n; ++start) {
      std::vector<long> chain;
      for (long r = start; !solved[r]; r = next(r)) chain.push_back(r);
      for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
        values_[*it] = apply(*it, values_[next(*it)]);
        solved[*it] = 1;
      }
    }
    for (long r = 0; r < n; ++r)
      for (const auto& b : layouts_[r].blocks)
        for (long j = b.jmin; j <= b.jmax; ++j) {
          TypeValues& tv = sol_.types[b.type];
          tv.values[j * n + r - tv.range.first] = values_[r][b.base + (j - b.jmin)];
        }
  }

 private:
  long next(long r) const { return pos_mod(a_ * r, n_); }

  std::vector<SparseRow> build_transfer(long r) const {
    const ResidueLayout& from = layouts_[r];
    const ResidueLayout& to = layouts_[next(r)];
    const long q = floor_div(a_ * r, n_);
    std::vector<SparseRow> rows(from.size);
    for (const auto& b : from.blocks)
      for (long j = b.jmin; j <= b.jmax; ++j) {
        SparseRow& row = rows[b.base + (j - b.jmin)];
        for (const Term& t : s_.types[b.type].terms) {
          const long slot = to.slot(t.type, a_ * j - t.shift + q);
          if (slot < 0) continue;  // outside the support: zero
          row.emplace_back(static_cast<std::size_t>(slot), Integer(numerator(t.coeff) * (scale_ / denominator(t.coeff))));
        }
      }
    return rows;
  }

  std::vector<Rational> apply(long r, const std::vector<Rational>& v) const {
    std::vector<Rational> out(layouts_[r].size, 0);
    for (std::size_t i = 0; i < out.size(); ++i)
      for (const auto& [c, x] : transfer_[r][i]) out[i] += Rational(x) * v[c];
    for (auto& x : out) x /= Rational(scale_);
    return out;
  }

  // Row vector of the partition-of-unity functional of `group` at residue r.
  std::vector<Integer> pou_row(long r, const std::vector<std::size_t>& group) const {
    std::vector<Integer> row(layouts_[r].size, 0);
    for (const auto& b : layouts_[r].blocks)
      if (std::find(group.begin(), group.end(), b.type) != group.end())
        for (long j = b.jmin; j <= b.jmax; ++j) row[b.base + (j - b.jmin)] = 1;
    return row;
  }
  std::vector<Integer> row_times(const std::vector<Integer>& w, long r) const {
    std::vector<Integer> out(layouts_[next(r)].size, 0);
    for (std::size_t i = 0; i < w.size(); ++i)
      if (w[i] != 0)
        for (const auto& [c, x] : transfer_[r][i]) out[c] += w[i] * x;
    return out;
  }

  void solve_cycle(const std::vector<long>& cycle) {
    const long r0 = cycle.front();
    const std::size_t m = layouts_[r0].size;
    const std::size_t L = cycle.size();
    // M = T_{r0} T_{r1} ... T_{r_{L-1}}, each scaled by D: M = D^L * P, built right to left.
    DenseMatrix M(m, std::vector<Integer>(m, 0));
    for (std::size_t i = 0; i < m; ++i) M[i][i] = 1;
    for (std::size_t step = L; step-- > 0;) {
      const long r = cycle[step];
      DenseMatrix next_m(layouts_[r].size, std::vector<Integer>(m, 0));
      for (std::size_t i = 0; i < next_m.size(); ++i)
        for (const auto& [c, x] : transfer_[r][i])
          for (std::size_t k = 0; k < m; ++k)
            if (M[c][k] != 0) next_m[i][k] += x * M[c][k];
      M.swap(next_m);
    }
    Integer DL = 1;
    for (std::size_t i = 0; i < L; ++i) DL *= scale_;

    const auto groups = pou_groups(s_, inv_);
    auto attempt = [&](bool all_residues) {
      ExactLinearSystem sys(m);
      for (std::size_t i = 0; i < m; ++i) {
        std::vector<std::pair<std::size_t, Rational>> eq;
        for (std::size_t k = 0; k < m; ++k) {
          Integer v = M[i][k] - (i == k ? DL : Integer(0));
          if (v != 0) eq.emplace_back(k, Rational(v));
        }
        sys.add_equation(eq, 0);
      }
      for (const auto& g : groups) {
        for (std::size_t step = 0; step < (all_residues ? L : 1); ++step) {
          // PoU at cycle[step], pulled back to r0 through T_{r_step} ... T_{r_{L-1}}.
          std::vector<Integer> w = pou_row(cycle[step], g);
          Integer rhs = 1;
          for (std::size_t t = step; t < L && step > 0; ++t) {
            w = row_times(w, cycle[t]);
            rhs *= scale_;
          }
          std::vector<std::pair<std::size_t, Rational>> eq;
          for (std::size_t k = 0; k < m; ++k)
            if (w[k] != 0) eq.emplace_back(k, Rational(w[k]));
          sys.add_equation(eq, Rational(rhs));
        }
      }
      return sys.solve();
    };
    LinearSolution result = attempt(false);
    if (result.status == LinearSolution::Status::Underdetermined && L > 1) result = attempt(true);
    if (result.status != LinearSolution::Status::Unique) {
      std::string where;
      for (long c : cycle) where += (where.empty() ? "" : ", ") + std::to_string(c) + "/" + std::to_string(n_);
      throw Error("scheme '" + s_.name + "', n = " + std::to_string(n_) +
                  ": the scaling relations with partition of unity on the residue cycle {" + where + "} have " +
                  result.describe() + (m == 0 ? " (the support holds no grid point)" : "") +
                  [&] {  // the likely cause, where the scheme's own analysis finds one
                    const std::string doubt = convergence_doubt(s_);
                    return doubt.empty() ? std::string() : "; the scheme is not shown to converge: " + doubt;
                  }());
    }
    values_[r0] = result.values;
    for (std::size_t step = L; step-- > 1;) values_[cycle[step]] = apply(cycle[step], values_[next(cycle[step])]);
  }

  const CurveScheme& s_;
  long n_, a_;
  CurveSolution& sol_;
  std::vector<std::size_t> inv_;
  Integer scale_ = 1;
  std::vector<ResidueLayout> layouts_;
  std::vector<std::vector<SparseRow>> transfer_;
  std::vector<std::vector<Rational>> values_;
};

// Special (single-column) types: every X = K/n but 0 along the orbits, then
// X = 0: W(0) = A W(0) + b with partition of unity.
void solve_special_types(const CurveScheme& s, long n, CurveSolution& sol) {
  solve_special_orbits(s, sol, Rational(1));
  const std::vector<std::size_t> at_zero = special_types_at_zero(s, sol);
  if (at_zero.empty()) return;
  ExactLinearSystem sys(at_zero.size());
  add_relations_at_zero(s, sol, at_zero, Rational(1), sys);
  std::vector<std::pair<std::size_t, Rational>> pou;
  for (std::size_t i = 0; i < at_zero.size(); ++i) pou.emplace_back(i, 1);
  sys.add_equation(pou, 1 - invariant_sum_at(s, sol, 0));
  const LinearSolution result = sys.solve();
  if (result.status != LinearSolution::Status::Unique)
    throw Error("scheme '" + s.name + "', n = " + std::to_string(n) +
                ": the scaling relations of the special columns at x = 0 with partition of unity have " +
                result.describe());
  for (std::size_t i = 0; i < at_zero.size(); ++i) set_global_value(s, sol, at_zero[i], 0, result.values[i]);
}

}  // namespace

CurveSolution solve_by_residues(const CurveScheme& s, long n) {
  if (n < 1) throw Error("rate n must be at least 1, got " + std::to_string(n));
  CurveSolution sol = zero_solution(s, n);
  InvariantPart(s, n, sol).solve();
  solve_special_types(s, n, sol);
  if (const auto failure = check_partition_of_unity(s, sol))
    throw Error("scheme '" + s.name + "', n = " + std::to_string(n) + ": " + *failure +
                "; the scaling relations have no solution with partition of unity");
  return sol;
}

}  // namespace sg
