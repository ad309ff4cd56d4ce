#include "quad_expansion.hpp"

#include <algorithm>
#include <unordered_map>
#include <numeric>
#include <utility>

namespace stencil_runtime {

namespace {

using Real = long double;

// out = row * M for sparse M (rows over `columns` inputs): out[c] = sum_r row[r] M[r][c].
void left_multiply(const Real* row, const SparseRows& m, Real* out) {
  std::fill(out, out + m.columns_count, Real(0));
  for (std::size_t r = 0; r < m.rows(); ++r) {
    const Real w = row[r];
    if (w == 0) continue;
    for (std::size_t e = m.offsets[r]; e != m.offsets[r + 1]; ++e) out[m.columns[e]] += w * static_cast<Real>(m.weights[e]);
  }
}

}  // namespace

ExpandedPatch expand_patch(int valence, const QuadDescent::Valence& sub, const std::vector<double>& limit,
                           const std::vector<int>& rates, const std::vector<std::vector<double>>& regular,
                           const std::vector<std::int64_t>& regular_first) {
  const std::size_t points = static_cast<std::size_t>(QuadTables::points(valence));
  ExpandedPatch out;
  // One stored stencil per distinct parameter point (x, y) = (p/q, r/q) in
  // lowest common terms, shared by the rates: key (p, r, q).
  std::unordered_map<std::uint64_t, std::uint32_t> slot;
  auto key = [](long a, long b, long g) {
    const long d = std::gcd(std::gcd(a, b), g);
    return (static_cast<std::uint64_t>(a / d) << 42) | (static_cast<std::uint64_t>(b / d) << 21) | static_cast<std::uint64_t>(g / d);
  };
  std::vector<Real> grid, child(16);
  for (std::size_t r = 0; r < rates.size(); ++r) {
    const long n = rates[r], g = 2 * n;
    auto phi = [&](long k) -> Real {  // phi(k / g)
      const std::int64_t i = k - regular_first[r];
      return i >= 0 && i < static_cast<std::int64_t>(regular[r].size()) ? regular[r][static_cast<std::size_t>(i)] : Real(0);
    };
    // This rate's stencils on the grid g, x <= y, by decreasing max(a, b): W(2a, 2b) is known before W(a, b).
    grid.assign(static_cast<std::size_t>((g + 1) * (g + 1)) * points, Real(0));
    auto at = [&](long a, long b) { return grid.data() + static_cast<std::size_t>(b * (g + 1) + a) * points; };
    for (long s = g; s >= 0; --s)
      for (long a = s & 1; a <= s; a += 2) {  // nodes and centres only (equal parity); doubling keeps a <= b
        const long b = s;
        Real* target = at(a, b);
        if (s == 0) {
          std::copy(limit.begin(), limit.end(), target);
        } else if (2 * a <= g && 2 * b <= g) {  // the extraordinary child
          left_multiply(at(2 * a, 2 * b), sub.ev_child, target);
        } else {  // a regular child: offsets (0,1) or (1,1), since a <= b
          const int c = 2 * a > g ? 2 : 1;
          const long X = 2 * a - (c == 2 ? g : 0), Y = 2 * b - g;
          for (int q = -1; q <= 2; ++q)
            for (int p = -1; p <= 2; ++p) child[static_cast<std::size_t>((q + 1) * 4 + (p + 1))] = phi(X - p * g) * phi(Y - q * g);
          left_multiply(child.data(), sub.regular_children[c], target);
        }
      }
    out.nodes.emplace_back();
    out.centres.emplace_back();
    for (int kind = 0; kind < 2; ++kind) {
      const long side = kind == 0 ? n + 1 : n;
      for (long j = 0; j < side; ++j)
        for (long i = 0; i <= j; ++i) {
          const long a = kind == 0 ? 2 * i : 2 * i + 1, b = kind == 0 ? 2 * j : 2 * j + 1;
          auto [it, fresh] = slot.emplace(key(a, b, g), static_cast<std::uint32_t>(out.weights.size() / points));
          if (fresh) {
            const Real* w = at(a, b);
            for (std::size_t h = 0; h < points; ++h) out.weights.push_back(static_cast<double>(w[h]));
          }
          (kind == 0 ? out.nodes : out.centres).back().push_back(it->second);
        }
    }
  }
  return out;
}

}  // namespace stencil_runtime
