#include "triangle/bivariate_solver.hpp"

#include <algorithm>
#include <functional>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include "algebra/exact_linear_system.hpp"
#include "algebra/integer_division.hpp"
#include "base/error.hpp"

namespace sg {

namespace {

using Matrix = std::vector<std::vector<Rational>>;

long cross(LatticeIndex o, LatticeIndex a, LatticeIndex b) {
  return (a.first - o.first) * (b.second - o.second) - (a.second - o.second) * (b.first - o.first);
}

// Convex hull, counter-clockwise, of the mask's indices (monotone chain).
std::vector<LatticeIndex> hull(std::vector<LatticeIndex> p) {
  std::sort(p.begin(), p.end());
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return p;
  std::vector<LatticeIndex> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross(h[k - 2], h[k - 1], p[i - 1]) <= 0) --k;
    h[k++] = p[i - 1];
  }
  h.resize(k - 1);
  return h;
}

Matrix multiply(const Matrix& a, const Matrix& b) {
  const std::size_t r = a.size(), m = b.size(), c = b.empty() ? 0 : b[0].size();
  Matrix out(r, std::vector<Rational>(c));
  for (std::size_t i = 0; i < r; ++i)
    for (std::size_t k = 0; k < m; ++k) {
      if (a[i][k] == 0) continue;
      for (std::size_t j = 0; j < c; ++j)
        if (b[k][j] != 0) out[i][j] += a[i][k] * b[k][j];
    }
  return out;
}

using SparseMatrix = std::vector<std::vector<std::pair<std::size_t, Rational>>>;

std::vector<Rational> matrix_times(const SparseMatrix& a, const std::vector<Rational>& v) {
  std::vector<Rational> out(a.size());
  Rational product;
  for (std::size_t row = 0; row < a.size(); ++row)
    for (const auto& [col, x] : a[row])
      if (v[col] != 0) {
        product = x;
        product *= v[col];
        out[row] += product;
      }
  return out;
}

// The normalisation of one residue cycle: equations over the members of the
// cycle's first class (added to the system that already holds the eigen-equations).
using CycleNormalisation = std::function<void(ExactLinearSystem&, const std::vector<LatticeIndex>& members)>;

// One function to solve for: f(k/n) = factor * sum_i s_i f((m k - n i)/n),
// fixed on each cycle by `normalise`; `what` names f in errors.
struct ClassProblem {
  Rational factor;
  CycleNormalisation normalise;
  std::string what;
};

// Every problem on the grid points of the open support hull, class by class
// (see the header). The problems share the classes, the transfer matrices and
// the cycles' products (a factor only scales them: P_factor = factor^L P), which
// cost most where the cycles are long.
std::vector<std::map<LatticeIndex, Rational>> solve_by_classes(const BivariateMask& mask, long n,
                                                               const std::vector<ClassProblem>& problems) {
  if (n < 1) throw Error("rate must be at least 1, got " + std::to_string(n));
  const long m = mask.dilation;
  if (m < 2) throw Error("dilation must be at least 2");
  std::vector<LatticeIndex> indices;
  for (const auto& [i, s] : mask.coefficients) indices.push_back(i);
  const std::vector<LatticeIndex> H = hull(indices);
  if (H.size() < 3) throw Error("the mask's support must have an interior");
  // Grid point k lies in the open support hull / (m - 1) iff (m - 1) k lies strictly inside n * hull.
  auto inside = [&](long a, long b) {
    const long x = (m - 1) * a, y = (m - 1) * b;
    for (std::size_t e = 0; e < H.size(); ++e) {
      const LatticeIndex p{n * H[e].first, n * H[e].second}, q{n * H[(e + 1) % H.size()].first, n * H[(e + 1) % H.size()].second};
      if (cross(p, q, {x, y}) <= 0) return false;
    }
    return true;
  };
  long lo_a = 0, hi_a = 0, lo_b = 0, hi_b = 0;
  for (const auto& [a, b] : H) lo_a = std::min(lo_a, a), hi_a = std::max(hi_a, a), lo_b = std::min(lo_b, b), hi_b = std::max(hi_b, b);
  // Unknowns by residue class r = (a mod n, b mod n), class index ra * n + rb.
  const std::size_t classes = static_cast<std::size_t>(n * n);
  std::vector<std::vector<LatticeIndex>> members(classes);
  // Position of k inside its class, over the bounding box (kNone outside the support).
  constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  const long box_a0 = floor_div(lo_a * n, m - 1) - 1, box_a1 = ceil_div(hi_a * n, m - 1) + 1;
  const long box_b0 = floor_div(lo_b * n, m - 1) - 1, box_b1 = ceil_div(hi_b * n, m - 1) + 1;
  const long box_w = box_b1 - box_b0 + 1;
  std::vector<std::size_t> slot_of(static_cast<std::size_t>((box_a1 - box_a0 + 1) * box_w), kNone);
  auto slot = [&](long a, long b) {
    if (a < box_a0 || a > box_a1 || b < box_b0 || b > box_b1) return kNone;
    return slot_of[static_cast<std::size_t>((a - box_a0) * box_w + (b - box_b0))];
  };
  for (long a = box_a0; a <= box_a1; ++a)
    for (long b = box_b0; b <= box_b1; ++b)
      if (inside(a, b)) {
        auto& list = members[static_cast<std::size_t>(pos_mod(a, n) * n + pos_mod(b, n))];
        slot_of[static_cast<std::size_t>((a - box_a0) * box_w + (b - box_b0))] = list.size();
        list.push_back({a, b});
      }
  auto image = [&](std::size_t r) {
    const long ra = static_cast<long>(r) / n, rb = static_cast<long>(r) % n;
    return static_cast<std::size_t>(pos_mod(m * ra, n) * n + pos_mod(m * rb, n));
  };
  // Transfer matrix A_r, rows sparse: values on class r from values on class image(r).
  auto transfer_rows = [&](std::size_t r) {
    SparseMatrix A(members[r].size());
    for (std::size_t row = 0; row < members[r].size(); ++row) {
      const auto [a, b] = members[r][row];
      for (const auto& [i, s] : mask.coefficients) {
        const std::size_t col = slot(m * a - n * i.first, m * b - n * i.second);
        if (col != kNone) A[row].emplace_back(col, s);
      }
    }
    return A;
  };
  auto transfer = [&](std::size_t r) {
    const SparseMatrix rows = transfer_rows(r);
    Matrix A(rows.size(), std::vector<Rational>(members[image(r)].size()));
    for (std::size_t row = 0; row < rows.size(); ++row)
      for (const auto& [col, s] : rows[row]) A[row][col] += s;
    return A;
  };

  const std::size_t count = problems.size();
  // value[r][p]: problem p's values on class r.
  std::vector<std::vector<std::vector<Rational>>> value(classes, std::vector<std::vector<Rational>>(count));
  std::vector<char> known(classes, 0);
  // f_r = factor A_r f_image for every problem, one pass over the rows.
  auto substitute = [&](std::size_t r, std::size_t from) {
    const SparseMatrix rows = transfer_rows(r);
    for (std::size_t p = 0; p < count; ++p) {
      value[r][p] = matrix_times(rows, value[from][p]);
      if (problems[p].factor != 1)
        for (Rational& x : value[r][p]) x *= problems[p].factor;
    }
  };
  // Cycles of the functional graph r -> image(r).
  std::vector<int> state(classes, 0);  // 0 unvisited, 1 on the current path, 2 done
  for (std::size_t start = 0; start < classes; ++start) {
    std::vector<std::size_t> path;
    std::size_t r = start;
    while (state[r] == 0) {
      state[r] = 1;
      path.push_back(r);
      r = image(r);
    }
    if (state[r] == 1) {  // a new cycle, beginning at r
      const auto first = std::find(path.begin(), path.end(), r);
      const std::vector<std::size_t> cycle(first, path.end());
      Matrix P = transfer(cycle[0]);
      for (std::size_t k = 1; k < cycle.size(); ++k) P = multiply(P, transfer(cycle[k]));
      const std::size_t size = members[cycle[0]].size();
      for (std::size_t p = 0; p < count; ++p) {
        Rational scale = 1;
        for (std::size_t k = 0; k < cycle.size(); ++k) scale *= problems[p].factor;
        ExactLinearSystem system(size);
        for (std::size_t row = 0; row < size; ++row) {
          std::vector<std::pair<std::size_t, Rational>> eq;
          for (std::size_t col = 0; col < size; ++col) {
            const Rational c = scale * P[row][col] - (row == col ? 1 : 0);
            if (c != 0) eq.emplace_back(col, c);
          }
          system.add_equation(eq, 0);
        }
        problems[p].normalise(system, members[cycle[0]]);
        const LinearSolution sol = system.solve();
        if (sol.status != LinearSolution::Status::Unique)
          throw Error("n = " + std::to_string(n) + ": " + problems[p].what + " on the residue cycle of length " +
                      std::to_string(cycle.size()) + " has " + sol.describe());
        value[cycle[0]][p] = sol.values;
      }
      known[cycle[0]] = 1;
      // Backwards around the cycle: v_{c[k]} = factor A_{c[k]} v_{c[k+1]}.
      for (std::size_t k = cycle.size() - 1; k >= 1; --k) {
        const std::size_t c = cycle[k], next = cycle[(k + 1) % cycle.size()];
        substitute(c, next);
        known[c] = 1;
      }
    }
    for (std::size_t p : path) state[p] = 2;
  }
  // Trees: substitution from the image class, which is known or resolved first.
  std::function<void(std::size_t)> resolve = [&](std::size_t r) {
    if (known[r]) return;
    const std::size_t t = image(r);
    resolve(t);
    substitute(r, t);
    known[r] = 1;
  };
  std::vector<std::map<LatticeIndex, Rational>> out(count);
  for (std::size_t r = 0; r < classes; ++r) {
    resolve(r);
    for (std::size_t p = 0; p < count; ++p)
      for (std::size_t k = 0; k < members[r].size(); ++k) out[p][members[r][k]] = value[r][p][k];
  }
  return out;
}

}  // namespace

namespace {

// Partition of unity on every class: sum_k phi(k/n) = 1.
ClassProblem values_problem() {
  return {Rational(1),
          [](ExactLinearSystem& system, const std::vector<LatticeIndex>& members) {
            std::vector<std::pair<std::size_t, Rational>> eq;
            for (std::size_t col = 0; col < members.size(); ++col) eq.emplace_back(col, Rational(1));
            system.add_equation(eq, 1);
          },
          "the scaling function"};
}

// Component c of the gradient: differentiating the reproduction of constants
// and of linear functions, sum_i phi(x - i) = 1 and sum_i phi(x - i) i = x +
// const, at x = r/n gives on the class of r: sum_k g(k) = 0 and
// sum_k g(k) k_d = -n [d == c].
ClassProblem gradient_problem(const BivariateMask& mask, long n, int c) {
  return {Rational(mask.dilation),
          [c, n](ExactLinearSystem& system, const std::vector<LatticeIndex>& members) {
            std::vector<std::pair<std::size_t, Rational>> constant, first, second;
            for (std::size_t col = 0; col < members.size(); ++col) {
              constant.emplace_back(col, Rational(1));
              if (members[col].first != 0) first.emplace_back(col, Rational(members[col].first));
              if (members[col].second != 0) second.emplace_back(col, Rational(members[col].second));
            }
            system.add_equation(constant, 0);
            system.add_equation(first, c == 0 ? Rational(-n) : Rational(0));
            system.add_equation(second, c == 1 ? Rational(-n) : Rational(0));
          },
          c == 0 ? "the derivative along a" : "the derivative along b"};
}

}  // namespace

BivariateSolution solve_bivariate(const BivariateMask& mask, long n) {
  BivariateSolution out;
  out.n = n;
  out.values = std::move(solve_by_classes(mask, n, {values_problem()}).front());
  return out;
}

BivariateGradient solve_bivariate_gradient(const BivariateMask& mask, long n) {
  auto solved = solve_by_classes(mask, n, {gradient_problem(mask, n, 0), gradient_problem(mask, n, 1)});
  BivariateGradient out;
  out.n = n;
  out.da = std::move(solved[0]);
  out.db = std::move(solved[1]);
  return out;
}

std::pair<BivariateSolution, BivariateGradient> solve_bivariate_with_gradient(const BivariateMask& mask, long n) {
  // A mask symmetric under (a, b) -> (b, a) (Loop's and sqrt(3)'s) has
  // d phi/db (a, b) = d phi/da (b, a): one eigen-solve per cycle fewer.
  bool symmetric = true;
  for (const auto& [i, s] : mask.coefficients) {
    const auto mirror = mask.coefficients.find({i.second, i.first});
    symmetric = symmetric && mirror != mask.coefficients.end() && mirror->second == s;
  }
  auto solved = symmetric ? solve_by_classes(mask, n, {values_problem(), gradient_problem(mask, n, 0)})
                          : solve_by_classes(mask, n, {values_problem(), gradient_problem(mask, n, 0), gradient_problem(mask, n, 1)});
  std::pair<BivariateSolution, BivariateGradient> out;
  out.first.n = out.second.n = n;
  out.first.values = std::move(solved[0]);
  out.second.da = std::move(solved[1]);
  if (symmetric)
    for (const auto& [k, x] : out.second.da) out.second.db.emplace(LatticeIndex{k.second, k.first}, x);
  else
    out.second.db = std::move(solved[2]);
  return out;
}

}  // namespace sg
