#include "curve/support.hpp"

#include <optional>

#include "base/error.hpp"

namespace sg {
namespace {

struct Option {
  std::size_t to;
  Rational shift;
};

// Smallest fixed point of  v_h = min over options (v_to + shift) / a.
std::vector<Rational> discounted_minimum(const std::vector<std::vector<Option>>& options, long a) {
  const std::size_t n = options.size();
  std::vector<std::size_t> choice(n, 0);
  std::vector<Rational> value(n);
  for (int round = 0;; ++round) {
    if (round > 1000) throw Error("support computation did not settle");
    // Evaluate the current policy: every node follows one pointer; solve along cycles.
    std::vector<int> state(n, 0);  // 0 unvisited, 1 on current path, 2 done
    for (std::size_t start = 0; start < n; ++start) {
      if (state[start] == 2) continue;
      std::vector<std::size_t> path;
      std::size_t h = start;
      while (state[h] == 0) {
        state[h] = 1;
        path.push_back(h);
        h = options[h][choice[h]].to;
      }
      std::size_t resolved = path.size();  // path[resolved..] get values from the cycle
      if (state[h] == 1) {                 // closed a cycle starting at h
        std::size_t c = 0;
        while (path[c] != h) ++c;
        // v_c = sum_i shift_i / a^(i+1) + v_c / a^L
        Rational sum = 0, scale = 1;
        for (std::size_t i = c; i < path.size(); ++i) {
          scale /= a;
          sum += options[path[i]][choice[path[i]]].shift * scale;
        }
        value[h] = sum / (1 - scale);
        state[h] = 2;
        resolved = c;
        for (std::size_t i = path.size(); i-- > c + 1;) {
          const Option& o = options[path[i]][choice[path[i]]];
          value[path[i]] = (value[o.to] + o.shift) / a;
          state[path[i]] = 2;
        }
      }
      for (std::size_t i = resolved; i-- > 0;) {
        const Option& o = options[path[i]][choice[path[i]]];
        value[path[i]] = (value[o.to] + o.shift) / a;
        state[path[i]] = 2;
      }
    }
    bool improved = false;
    for (std::size_t h = 0; h < n; ++h)
      for (std::size_t k = 0; k < options[h].size(); ++k) {
        const Rational candidate = (value[options[h][k].to] + options[h][k].shift) / a;
        if (candidate < value[h]) {
          value[h] = candidate;
          choice[h] = k;
          improved = true;
        }
      }
    if (!improved) return value;
  }
}

}  // namespace

void compute_supports(CurveScheme& scheme) {
  const std::size_t n = scheme.types.size();
  std::vector<std::vector<Option>> lo(n), hi(n);
  for (std::size_t h = 0; h < n; ++h) {
    for (const Term& t : scheme.types[h].terms) {
      if (t.coeff == 0) continue;
      lo[h].push_back({t.type, Rational(t.shift)});
      hi[h].push_back({t.type, Rational(-t.shift)});  // max v = -min(-v)
    }
    if (lo[h].empty()) throw Error(scheme.source + ": type '" + scheme.types[h].name + "' has an all-zero relation");
  }
  const auto low = discounted_minimum(lo, scheme.arity);
  const auto high = discounted_minimum(hi, scheme.arity);
  for (std::size_t h = 0; h < n; ++h) {
    scheme.types[h].support_lo = low[h];
    scheme.types[h].support_hi = -high[h];
  }
}

}  // namespace sg
