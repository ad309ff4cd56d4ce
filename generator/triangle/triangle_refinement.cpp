#include "triangle/triangle_refinement.hpp"

#include <map>
#include <string>

#include "algebra/integer_division.hpp"
#include "base/error.hpp"
#include "triangle/triangle_masks.hpp"

namespace sg {
namespace {

template <class T>
class RowBuilder {
 public:
  void add(std::size_t column, const T& w) { row_[column] += w; }
  void add(const std::map<std::size_t, T>& other, const T& w) {
    for (const auto& [c, x] : other) row_[c] += w * x;
  }
  const std::map<std::size_t, T>& entries() const { return row_; }
  SparseRow<T> finish() const {
    SparseRow<T> out;
    for (const auto& [c, x] : row_)
      if (x != 0) out.emplace_back(c, x);
    return out;
  }

 private:
  std::map<std::size_t, T> row_;
};

template <class T>
class Rules {
 public:
  Rules(const SectorChart& chart, const TriangleWeights<T>& w) : chart_(chart), w_(w) {}

  // Coarse point (a, b) of sector k's frame.
  std::size_t coarse(int k, long a, long b) const {
    const auto id = chart_.index(k, a, b);
    if (!id)
      throw Error("internal: the refinement at valence " + std::to_string(chart_.valence()) + " needs the point (" +
                  std::to_string(a) + "," + std::to_string(b) + ") of sector " + std::to_string(k) +
                  ", beyond the chart's " + std::to_string(chart_.rings()) + " rings");
    return *id;
  }

  // The relaxed old vertex (a, b) of sector k (coarse lattice): the vertex rule.
  std::map<std::size_t, T> vertex_point(int k, long a, long b) const {
    RowBuilder<T> row;
    if (a == 0 && b == 0) {
      const int v = chart_.valence();
      row.add(0, 1 - v * w_.neighbour);
      for (int s = 0; s < v; ++s) row.add(coarse(s, 1, 0), w_.neighbour);
    } else {
      row.add(coarse(k, a, b), 1 - 6 * w_.neighbour_regular);
      for (const auto& d : kTriangleNeighbours) row.add(coarse(k, a + d[0], b + d[1]), w_.neighbour_regular);
    }
    return row.entries();
  }

  // Loop: the refined point (a, b) of sector k (halves of the coarse lattice).
  std::map<std::size_t, T> loop_point(int k, long a, long b) const {
    if (a % 2 == 0 && b % 2 == 0) return vertex_point(k, a / 2, b / 2);
    for (int i = 0; i < 6; ++i) {  // the edge from q to q + d_i, midpoint (a, b) = 2 q + d_i
      const long* d = kTriangleNeighbours[i];
      if ((a - d[0]) % 2 != 0 || (b - d[1]) % 2 != 0) continue;
      const long qa = floor_div(a - d[0], 2), qb = floor_div(b - d[1], 2);
      const long* l = kTriangleNeighbours[(i + 1) % 6];
      const long* r = kTriangleNeighbours[(i + 5) % 6];
      RowBuilder<T> row;
      row.add(coarse(k, qa, qb), w_.edge_end);
      row.add(coarse(k, qa + d[0], qb + d[1]), w_.edge_end);
      row.add(coarse(k, qa + l[0], qb + l[1]), w_.edge_opposite);
      row.add(coarse(k, qa + r[0], qb + r[1]), w_.edge_opposite);
      return row.entries();
    }
    throw Error("internal: no Loop rule for (" + std::to_string(a) + "," + std::to_string(b) + ")");
  }

  // sqrt(3), first step: the point (a, b) of sector k in thirds of the coarse
  // lattice, a + b = 0 mod 3: an old vertex relaxed, or the centroid of a coarse
  // triangle ((2,1) mod 3: corners (0,0),(3,0),(3,3) relative; (1,2): (0,0),(3,3),(0,3)).
  std::map<std::size_t, T> sqrt3_first(int k, long a, long b) const {
    const auto p = chart_.canonical(k, a, b);
    if (!p) throw Error("internal: sqrt(3) point (" + std::to_string(a) + "," + std::to_string(b) + ") is too far round");
    k = p->sector, a = p->a, b = p->b;
    const long ra = pos_mod(a, 3), rb = pos_mod(b, 3);
    if (ra == 0 && rb == 0) return vertex_point(k, a / 3, b / 3);
    static constexpr long corners21[3][2] = {{-2, -1}, {1, -1}, {1, 2}};
    static constexpr long corners12[3][2] = {{-1, -2}, {2, 1}, {-1, 1}};
    const auto& c = (ra == 2 && rb == 1) ? corners21 : corners12;
    if (!((ra == 2 && rb == 1) || (ra == 1 && rb == 2)))
      throw Error("internal: (" + std::to_string(a) + "," + std::to_string(b) + ") is not a first-step sqrt(3) point");
    RowBuilder<T> row;
    for (const auto& o : c) row.add(coarse(k, (a + o[0]) / 3, (b + o[1]) / 3), T(1) / 3);
    return row.entries();
  }

  // sqrt(3), both steps: the point (a, b) of sector k in thirds. First-step
  // points (a + b = 0 mod 3) are relaxed among their first-step neighbours;
  // the others are centroids of first-step triangles.
  std::map<std::size_t, T> sqrt3_point(int k, long a, long b) const {
    static constexpr long step1_dirs[6][2] = {{2, 1}, {1, 2}, {-1, 1}, {-2, -1}, {-1, -2}, {1, -1}};
    static constexpr long tri_a[3][2] = {{-1, 0}, {0, -1}, {1, 1}};  // a + b = 1 mod 3
    static constexpr long tri_b[3][2] = {{1, 0}, {0, 1}, {-1, -1}};  // a + b = 2 mod 3
    RowBuilder<T> row;
    const long s = pos_mod(a + b, 3);
    if (s == 0) {
      if (a == 0 && b == 0) {
        const int v = chart_.valence();
        row.add(sqrt3_first(0, 0, 0), 1 - v * w_.neighbour);
        for (int q = 0; q < v; ++q) row.add(sqrt3_first(q, 2, 1), w_.neighbour);
      } else {
        row.add(sqrt3_first(k, a, b), 1 - 6 * w_.neighbour_regular);
        for (const auto& d : step1_dirs) row.add(sqrt3_first(k, a + d[0], b + d[1]), w_.neighbour_regular);
      }
      return row.entries();
    }
    for (const auto& o : (s == 1 ? tri_a : tri_b)) row.add(sqrt3_first(k, a + o[0], b + o[1]), T(1) / 3);
    return row.entries();
  }

 private:
  const SectorChart& chart_;
  const TriangleWeights<T>& w_;
};

}  // namespace

template <class T>
SparseRow<T> refined_point(TriangleRefinement refinement, const SectorChart& chart, const TriangleWeights<T>& weights,
                           const SectorPoint& p) {
  const Rules<T> rules(chart, weights);
  RowBuilder<T> row;
  row.add(refinement == TriangleRefinement::Loop ? rules.loop_point(p.sector, p.a, p.b) : rules.sqrt3_point(p.sector, p.a, p.b),
          T(1));
  return row.finish();
}

template <class T>
std::vector<SparseRow<T>> refinement_matrix(TriangleRefinement refinement, const SectorChart& chart,
                                            const TriangleWeights<T>& weights) {
  std::vector<SparseRow<T>> rows(chart.size());
  for (std::size_t id = 0; id < chart.size(); ++id) rows[id] = refined_point(refinement, chart, weights, chart.point(id));
  return rows;
}

template SparseRow<Rational> refined_point(TriangleRefinement, const SectorChart&, const TriangleWeights<Rational>&,
                                           const SectorPoint&);
template SparseRow<Real> refined_point(TriangleRefinement, const SectorChart&, const TriangleWeights<Real>&, const SectorPoint&);
template std::vector<SparseRow<Rational>> refinement_matrix(TriangleRefinement, const SectorChart&,
                                                            const TriangleWeights<Rational>&);
template std::vector<SparseRow<Real>> refinement_matrix(TriangleRefinement, const SectorChart&,
                                                        const TriangleWeights<Real>&);

}  // namespace sg
