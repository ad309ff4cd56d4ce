#include "triangle/sector_chart.hpp"

#include <string>

#include "base/error.hpp"

namespace sg {

SectorChart::SectorChart(int valence, long rings) : v_(valence), rings_(rings) {
  if (valence < 3) throw Error("valence must be at least 3, got " + std::to_string(valence));
  if (rings < 1) throw Error("a sector chart needs at least one ring");
}

std::optional<SectorPoint> SectorChart::canonical(int k, long a, long b, int max_turns) const {
  if (a == 0 && b == 0) return SectorPoint{};
  for (int turn = 0; turn <= max_turns; ++turn) {
    if (a >= 1 && b >= 0 && b < a) return SectorPoint{((k % v_) + v_) % v_, a, b};
    if (b < 0) {  // clockwise into sector k-1
      into_previous_frame(a, b);
      --k;
    } else {  // counter-clockwise into sector k+1
      into_next_frame(a, b);
      ++k;
    }
  }
  return std::nullopt;
}

std::size_t SectorChart::index(const SectorPoint& p) const {
  if (p.a == 0) return 0;
  return 1 + static_cast<std::size_t>(v_ * p.a * (p.a - 1) / 2 + p.sector * p.a + p.b);
}

std::optional<std::size_t> SectorChart::index(int k, long a, long b, int max_turns) const {
  const auto p = canonical(k, a, b, max_turns);
  if (!p || p->a > rings_) return std::nullopt;
  return index(*p);
}

SectorPoint SectorChart::point(std::size_t id) const {
  if (id == 0) return {};
  std::size_t rest = id - 1;
  for (long r = 1;; ++r) {
    const std::size_t ring = static_cast<std::size_t>(v_ * r);
    if (rest < ring) return SectorPoint{static_cast<int>(rest / static_cast<std::size_t>(r)), r, static_cast<long>(rest % static_cast<std::size_t>(r))};
    rest -= ring;
  }
}

}  // namespace sg
