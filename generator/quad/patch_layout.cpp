#include "quad/patch_layout.hpp"

#include "base/error.hpp"

namespace sg {

namespace {
constexpr int kOuter[7][2] = {{2, -1}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {-1, 2}};
int wrap(int k, int v) { return ((k % v) + v) % v; }
}  // namespace

PatchLayout::PatchLayout(int valence) : v_(valence) {
  if (valence < 3) throw Error("valence must be at least 3, got " + std::to_string(valence));
}

std::size_t PatchLayout::edge(int k) const { return static_cast<std::size_t>(1 + 2 * wrap(k, v_)); }
std::size_t PatchLayout::face(int k) const { return static_cast<std::size_t>(2 + 2 * wrap(k, v_)); }

std::optional<std::size_t> PatchLayout::chart(int i, int j) const {
  if (i < -1 || i > 2 || j < -1 || j > 2) return std::nullopt;
  if (i == 0 && j == 0) return ev();
  if (i == 1 && j == 0) return edge(0);
  if (i == 1 && j == 1) return face(0);
  if (i == 0 && j == 1) return edge(1);
  if (i == -1 && j == 1) return face(1);
  if (i == -1 && j == 0) return edge(2);
  if (i == 0 && j == -1) return edge(-1);
  if (i == 1 && j == -1) return face(-1);
  if (i == -1 && j == -1) return v_ == 4 ? std::optional<std::size_t>(face(2)) : std::nullopt;
  for (int t = 0; t < 7; ++t)
    if (kOuter[t][0] == i && kOuter[t][1] == j) return outer(t);
  return std::nullopt;
}

std::optional<std::pair<int, int>> PatchLayout::position(std::size_t index) const {
  for (int j = -1; j <= 2; ++j)
    for (int i = -1; i <= 2; ++i)
      if (chart(i, j) == index) return std::pair{i, j};
  return std::nullopt;
}

std::vector<std::size_t> PatchLayout::reflection() const {
  std::vector<std::size_t> r(size());
  r[ev()] = ev();
  for (int k = 0; k < v_; ++k) {
    r[edge(k)] = edge(1 - k);
    r[face(k)] = face(-k);
  }
  for (int t = 0; t < 7; ++t) r[outer(t)] = outer(6 - t);
  return r;
}

}  // namespace sg
