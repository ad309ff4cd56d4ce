#include "triangle/triangle_masks.hpp"

namespace sg {

BivariateMask loop_regular_mask(const Rational& end, const Rational& opposite, const Rational& centre,
                                const Rational& neighbour) {
  // Where coarse point 0 goes on the fine lattice (fine index = 2 * position).
  BivariateMask mask;
  mask.dilation = 2;
  auto add = [&](long a, long b, const Rational& w) { mask.coefficients[{a, b}] += w; };
  add(0, 0, centre);
  for (int k = 0; k < 6; ++k) {
    const auto* d = kTriangleNeighbours[k];
    const auto* e = kTriangleNeighbours[(k + 1) % 6];
    add(d[0], d[1], end);                         // midpoint of the edge 0 - d
    add(d[0] + e[0], d[1] + e[1], opposite);      // midpoint of the edge d - e, opposite 0
    add(2 * d[0], 2 * d[1], neighbour);           // the vertex d, relaxed towards 0
  }
  return mask;
}

BivariateMask sqrt3_composite_mask(const Rational& alpha) {
  // Positions in thirds of the coarse lattice throughout.
  std::map<LatticeIndex, Rational> step1;
  step1[{0, 0}] += 1 - alpha;
  long dir[6][2];  // the intermediate lattice's unit neighbours, in thirds
  for (int k = 0; k < 6; ++k) {
    const auto* d = kTriangleNeighbours[k];
    const auto* e = kTriangleNeighbours[(k + 1) % 6];
    step1[{3 * d[0], 3 * d[1]}] += alpha / 6;              // neighbour d relaxed towards 0
    step1[{d[0] + e[0], d[1] + e[1]}] += Rational(1, 3);   // centroid of the triangle (0, d, e)
    dir[k][0] = d[0] + e[0];
    dir[k][1] = d[1] + e[1];
  }
  BivariateMask mask;
  mask.dilation = 3;
  for (const auto& [q, c] : step1) {
    if (c == 0) continue;
    mask.coefficients[q] += (1 - alpha) * c;
    for (int k = 0; k < 6; ++k) {
      mask.coefficients[{q.first + dir[k][0], q.second + dir[k][1]}] += alpha / 6 * c;
      // Centroid of the intermediate triangle (q, q + dir_k, q + dir_{k+1}): integral in thirds.
      const long ca = (dir[k][0] + dir[(k + 1) % 6][0]) / 3, cb = (dir[k][1] + dir[(k + 1) % 6][1]) / 3;
      mask.coefficients[{q.first + ca, q.second + cb}] += c / 3;
    }
  }
  for (auto it = mask.coefficients.begin(); it != mask.coefficients.end();)
    it = it->second == 0 ? mask.coefficients.erase(it) : std::next(it);
  return mask;
}

}  // namespace sg
