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

ExpandedPatch expand_patch(int kind, const QuadDescent::Valence& sub, const std::vector<double>& limit,
                           const std::vector<int>& rates, const std::vector<std::vector<double>>& regular,
                           const std::vector<std::int64_t>& regular_first, bool symmetric) {
  const std::size_t points = static_cast<std::size_t>(QuadTables::points(kind));
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
    grid.assign(static_cast<std::size_t>((g + 1) * (g + 1)) * points, Real(0));
    auto at = [&](long a, long b) { return grid.data() + static_cast<std::size_t>(b * (g + 1) + a) * points; };
    auto fill = [&](long a, long b) {
      Real* target = at(a, b);
      if (a == 0 && b == 0) {
        std::copy(limit.begin(), limit.end(), target);
      } else if (2 * a <= g && 2 * b <= g) {  // the extraordinary child
        left_multiply(at(2 * a, 2 * b), sub.ev_child, target);
      } else {  // a regular child: offsets (1,0), (0,1) or (1,1)
        const int c = 2 * a > g ? (2 * b > g ? 2 : 0) : 1;
        const long X = 2 * a - (c != 1 ? g : 0), Y = 2 * b - (c != 0 ? g : 0);
        for (int q = -1; q <= 2; ++q)
          for (int p = -1; p <= 2; ++p) child[static_cast<std::size_t>((q + 1) * 4 + (p + 1))] = phi(X - p * g) * phi(Y - q * g);
        left_multiply(child.data(), sub.regular_children[c], target);
      }
    };
    // This rate's stencils on the grid g by decreasing max(a, b): W(2a, 2b) is
    // known before W(a, b). Nodes and centres only (equal parity); doubling
    // keeps a <= b, so with a reflection that half is enough.
    for (long s = g; s >= 0; --s)
      for (long a = s & 1; a <= s; a += 2) {
        fill(a, s);
        if (!symmetric && a != s) fill(s, a);
      }
    out.nodes.emplace_back();
    out.centres.emplace_back();
    for (int kind_of_point = 0; kind_of_point < 2; ++kind_of_point) {
      const long side = kind_of_point == 0 ? n + 1 : n;
      for (long j = 0; j < side; ++j)
        for (long i = 0; i < (symmetric ? j + 1 : side); ++i) {
          const long a = kind_of_point == 0 ? 2 * i : 2 * i + 1, b = kind_of_point == 0 ? 2 * j : 2 * j + 1;
          auto [it, fresh] = slot.emplace(key(a, b, g), static_cast<std::uint32_t>(out.weights.size() / points));
          if (fresh) {
            const Real* w = at(a, b);
            for (std::size_t h = 0; h < points; ++h) out.weights.push_back(static_cast<double>(w[h]));
          }
          (kind_of_point == 0 ? out.nodes : out.centres).back().push_back(it->second);
        }
    }
  }
  return out;
}

}  // namespace stencil_runtime
