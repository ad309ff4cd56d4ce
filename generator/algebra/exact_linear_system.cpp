#include "algebra/exact_linear_system.hpp"

#include <algorithm>
#include <map>
#include <set>

#include "base/error.hpp"

namespace sg {

std::string LinearSolution::describe() const {
  switch (status) {
    case Status::Unique: return "a unique solution";
    case Status::Underdetermined: return "a solution space of dimension " + std::to_string(nullity);
    case Status::Inconsistent: return "no solution (the equations contradict each other)";
  }
  return "";
}

void ExactLinearSystem::add_equation(const std::vector<std::pair<std::size_t, Rational>>& coeffs,
                                     const Rational& rhs) {
  std::map<std::size_t, Rational> merged;
  for (const auto& [col, c] : coeffs) {
    if (col >= unknowns_) throw Error("internal: unknown index out of range");
    merged[col] += c;
  }
  merged[unknowns_] += rhs;
  Integer lcm_den = 1;
  for (const auto& [col, c] : merged)
    if (c != 0) lcm_den = lcm(lcm_den, denominator(c));
  Row row;
  for (const auto& [col, c] : merged)
    if (c != 0) row.entries.emplace_back(col, Integer(numerator(c) * (lcm_den / denominator(c))));
  rows_.push_back(std::move(row));
}

namespace {

using Entries = std::vector<std::pair<std::size_t, Integer>>;

const Integer* find_entry(const Entries& e, std::size_t col) {
  auto it = std::lower_bound(e.begin(), e.end(), col, [](const auto& p, std::size_t c) { return p.first < c; });
  return (it != e.end() && it->first == col) ? &it->second : nullptr;
}

void remove_content(Entries& e) {
  Integer g = 0;
  for (const auto& [c, v] : e) {
    g = gcd(g, v);
    if (g == 1) return;
  }
  if (g > 1)
    for (auto& [c, v] : e) v /= g;
}

// target := p * target - t * pivot_row, where p is the pivot value and t target's entry in `col`.
Entries eliminate(const Entries& target, const Entries& pivot, std::size_t col) {
  const Integer p = *find_entry(pivot, col), t = *find_entry(target, col);
  const Integer g = gcd(p, t);
  const Integer fp = p / g, ft = t / g;
  Entries out;
  out.reserve(target.size() + pivot.size());
  auto a = target.begin(), b = pivot.begin();
  while (a != target.end() || b != pivot.end()) {
    if (b == pivot.end() || (a != target.end() && a->first < b->first)) {
      out.emplace_back(a->first, fp * a->second);
      ++a;
    } else if (a == target.end() || b->first < a->first) {
      out.emplace_back(b->first, -ft * b->second);
      ++b;
    } else {
      Integer v = fp * a->second - ft * b->second;
      if (v != 0) out.emplace_back(a->first, std::move(v));
      ++a;
      ++b;
    }
  }
  remove_content(out);
  return out;
}

}  // namespace

LinearSolution ExactLinearSystem::solve() const {
  const std::size_t n = unknowns_;
  std::vector<Entries> rows;
  rows.reserve(rows_.size());
  for (const Row& r : rows_) rows.push_back(r.entries);

  // Column -> rows that may contain it (pruned lazily); exact live counts per column;
  // a priority queue keyed by (count, column) whose stale entries are skipped.
  std::vector<std::vector<std::size_t>> col_rows(n);
  std::vector<std::size_t> count(n, 0);
  for (std::size_t r = 0; r < rows.size(); ++r)
    for (const auto& [c, v] : rows[r])
      if (c < n) {
        col_rows[c].push_back(r);
        ++count[c];
      }
  std::vector<char> row_used(rows.size(), 0), col_done(n, 0);
  std::vector<std::pair<std::size_t, std::size_t>> pivots;  // (column, row) in elimination order
  std::set<std::pair<std::size_t, std::size_t>> queue;
  for (std::size_t c = 0; c < n; ++c)
    if (count[c] > 0) queue.emplace(count[c], c);
  auto set_count = [&](std::size_t c, std::size_t value) {
    if (col_done[c]) return;
    queue.erase({count[c], c});
    count[c] = value;
    if (value > 0) queue.emplace(value, c);
  };

  while (!queue.empty()) {
    const std::size_t c = queue.begin()->second;
    queue.erase(queue.begin());
    std::vector<std::size_t> live;
    for (std::size_t r : col_rows[c])
      if (!row_used[r] && find_entry(rows[r], c)) live.push_back(r);
    std::sort(live.begin(), live.end());
    live.erase(std::unique(live.begin(), live.end()), live.end());
    std::size_t best = live.front();
    for (std::size_t r : live)
      if (rows[r].size() < rows[best].size()) best = r;
    col_done[c] = 1;
    row_used[best] = 1;
    pivots.emplace_back(c, best);
    for (const auto& [cc, v] : rows[best])
      if (cc < n && cc != c) set_count(cc, count[cc] - 1);
    for (std::size_t r : live) {
      if (r == best) continue;
      Entries updated = eliminate(rows[r], rows[best], c);
      // Adjust counts by the difference between the old and new column sets of row r.
      auto a = rows[r].begin(), b = updated.begin();
      while (a != rows[r].end() || b != updated.end()) {
        if (b == updated.end() || (a != rows[r].end() && a->first < b->first)) {
          if (a->first < n && a->first != c) set_count(a->first, count[a->first] - 1);
          ++a;
        } else if (a == rows[r].end() || b->first < a->first) {
          if (b->first < n) {
            set_count(b->first, count[b->first] + 1);
            col_rows[b->first].push_back(r);
          }
          ++b;
        } else {
          ++a;
          ++b;
        }
      }
      rows[r] = std::move(updated);
    }
  }

  LinearSolution result;
  for (std::size_t r = 0; r < rows.size(); ++r)
    if (!row_used[r] && !rows[r].empty()) {
      // Only the rhs can remain in an unused row; a nonzero rhs is a contradiction.
      bool only_rhs = true;
      for (const auto& [c, v] : rows[r])
        if (c < n) only_rhs = false;
      if (only_rhs) {
        result.status = LinearSolution::Status::Inconsistent;
        return result;
      }
    }
  const std::size_t rank = pivots.size();
  if (rank < n) {
    result.status = LinearSolution::Status::Underdetermined;
    result.nullity = n - rank;
    return result;
  }
  result.values.assign(n, Rational(0));
  for (std::size_t k = rank; k-- > 0;) {
    const auto [c, r] = pivots[k];
    Rational acc = 0;
    Integer diag = 0;
    for (const auto& [cc, v] : rows[r]) {
      if (cc == n) acc += Rational(v);
      else if (cc == c) diag = v;
      else acc -= Rational(v) * result.values[cc];
    }
    result.values[c] = acc / Rational(diag);
  }
  return result;
}

}  // namespace sg
