#include "triangle_patch.hpp"

#include <map>
#include <optional>

#include "error.hpp"
#include "exact_linear_system.hpp"
#include "expression.hpp"
#include "integer_division.hpp"
#include "triangle_masks.hpp"

namespace sg {

Rational loop_beta(int v) {
  const auto c = exact_cos2pi(Rational(1, v));
  if (!c) throw Error("Loop's weights at valence " + std::to_string(v) + " are irrational (cos(2 pi / " + std::to_string(v) +
                      ")); only valences 3, 4 and 6 are solved exactly so far");
  const Rational t = Rational(3, 8) + *c / 4;
  return (Rational(5, 8) - t * t) / v;
}

namespace {

using Row = std::map<std::size_t, Rational>;
using Chart = std::pair<long, long>;

class TriangleLayout {
 public:
  explicit TriangleLayout(int v) : v_(v) {}
  std::size_t size() const { return static_cast<std::size_t>(v_ + 6); }
  std::size_t edge(int k) const { return static_cast<std::size_t>(1 + ((k % v_) + v_) % v_); }
  std::optional<std::size_t> chart(long a, long b) const {
    if (a == 0 && b == 0) return 0;
    if (a == 1 && b == 0) return edge(0);
    if (a == 1 && b == 1) return edge(1);
    if (a == 0 && b == 1) return edge(2);
    if (a == 0 && b == -1) return edge(-1);
    if (v_ == 6 && a == -1 && b == 0) return edge(3);
    if (v_ == 6 && a == -1 && b == -1) return edge(4);
    static const Chart outer[5] = {{1, -1}, {2, 0}, {2, 1}, {2, 2}, {1, 2}};
    for (int t = 0; t < 5; ++t)
      if (outer[t] == Chart{a, b}) return static_cast<std::size_t>(v_ + 1 + t);
    return std::nullopt;
  }
  int valence() const { return v_; }

 private:
  int v_;
};

class LoopRefiner {
 public:
  LoopRefiner(const TriangleLayout& layout, const LoopRules& rules) : L_(layout), r_(rules) {}

  // The refined point at refined chart position y.
  // The edge point of the edge EV - e_k, any k: 3/8 of each end, 1/8 of e_{k-1} and e_{k+1}.
  Row one_ring_edge(int k) const {
    Row row;
    row[0] += r_.edge_end;
    row[L_.edge(k)] += r_.edge_end;
    row[L_.edge(k - 1)] += r_.edge_opposite;
    row[L_.edge(k + 1)] += r_.edge_opposite;
    return row;
  }

  Row at(long ya, long yb) {
    const int v = L_.valence();
    if (ya == 0 && yb == 0) {  // the EV's vertex point
      Row row;
      row[0] += 1 - v * r_.beta_extraordinary;
      for (int k = 0; k < v; ++k) row[L_.edge(k)] += r_.beta_extraordinary;
      return row;
    }
    for (int k = 0; k < 6; ++k)  // the EV's refined one-ring: edge points of EV - e_k
      if (ya == kTriangleNeighbours[k][0] && yb == kTriangleNeighbours[k][1]) {
        const int e = k == 0 ? 0 : k == 1 ? 1 : k == 2 ? 2 : k == 5 ? -1 : (v == 6 ? k : 99);
        if (e == 99) break;
        return one_ring_edge(e);
      }
    Row row;
    if (ya % 2 == 0 && yb % 2 == 0) {  // vertex point of a regular old vertex
      const long pa = ya / 2, pb = yb / 2;
      add(row, pa, pb, 1 - 6 * r_.beta_regular);
      for (const auto& d : kTriangleNeighbours) add(row, pa + d[0], pb + d[1], r_.beta_regular);
      return row;
    }
    for (int k = 0; k < 6; ++k) {  // edge point: y = 2p + d with d a unit neighbour
      const long da = kTriangleNeighbours[k][0], db = kTriangleNeighbours[k][1];
      if ((ya - da) % 2 != 0 || (yb - db) % 2 != 0) continue;
      const long pa = floor_div(ya - da, 2), pb = floor_div(yb - db, 2);
      add(row, pa, pb, r_.edge_end);
      add(row, pa + da, pb + db, r_.edge_end);
      for (int o : {k + 1, k + 5}) add(row, pa + kTriangleNeighbours[o % 6][0], pb + kTriangleNeighbours[o % 6][1], r_.edge_opposite);
      return row;
    }
    throw Error("internal: no refinement rule for (" + std::to_string(ya) + "," + std::to_string(yb) + ")");
  }

 private:
  void add(Row& row, long a, long b, const Rational& w) {
    const auto h = L_.chart(a, b);
    if (!h) throw Error("internal: the refinement needs chart point (" + std::to_string(a) + "," + std::to_string(b) + ")");
    row[*h] += w;
  }
  const TriangleLayout& L_;
  LoopRules r_;
};

std::vector<Rational> times(const std::vector<Rational>& w, const std::vector<Row>& rows, std::size_t m) {
  std::vector<Rational> out(m);
  for (std::size_t r = 0; r < rows.size(); ++r)
    if (w[r] != 0)
      for (const auto& [c, x] : rows[r]) out[c] += w[r] * x;
  return out;
}

}  // namespace

TrianglePatchGrid solve_loop_patch(int valence, long g) {
  if (valence < 3) throw Error("valence must be at least 3");
  if (g < 1) throw Error("rate must be at least 1");
  LoopRules rules;
  rules.beta_extraordinary = loop_beta(valence);
  const TriangleLayout L(valence);
  LoopRefiner refine(L, rules);
  const std::size_t m = L.size();
  // A0: the EV child's control points (same layout, refined chart) from the parent's.
  std::vector<Row> a0(m);
  a0[0] = refine.at(0, 0);
  for (int k = 0; k < valence; ++k) a0[L.edge(k)] = refine.one_ring_edge(k);
  const Chart outer[5] = {{1, -1}, {2, 0}, {2, 1}, {2, 2}, {1, 2}};
  for (int t = 0; t < 5; ++t) a0[static_cast<std::size_t>(valence + 1 + t)] = refine.at(outer[t].first, outer[t].second);

  // The refined points the three regular children use (their box-spline supports).
  const Chart child_points[] = {{1, 0}, {2, 0}, {2, 1}, {1, 1}, {1, -1}, {0, 0}, {0, -1}, {3, 0}, {3, 1}, {2, -1},
                                {3, 2}, {2, 2}, {0, 1}, {3, 3}, {2, 3}, {1, 2}};
  std::vector<Chart> reg_points(std::begin(child_points), std::end(child_points));
  std::vector<Row> reg_rows;
  for (const auto& [a, b] : reg_points) reg_rows.push_back(refine.at(a, b));

  const BivariateMask mask = loop_regular_mask(rules.edge_end, rules.edge_opposite, 1 - 6 * rules.beta_regular, rules.beta_regular);
  const BivariateSolution phi = solve_bivariate(mask, g);

  TrianglePatchGrid out;
  out.valence = valence;
  out.grid = g;
  out.points = m;
  out.stencils.assign(static_cast<std::size_t>((g + 1) * (g + 1)), {});
  auto slot = [&](long i, long j) -> std::vector<Rational>& { return out.stencils[static_cast<std::size_t>(j * (g + 1) + i)]; };
  // Decreasing i + j, so that W(2i, 2j) is known before W(i, j).
  for (long s = g; s >= 1; --s)
    for (long i = 0; i <= s; ++i) {
      const long j = s - i;
      if (2 * s < g) {
        slot(i, j) = times(slot(2 * i, 2 * j), a0, m);
        continue;
      }
      // A regular child: the refined point y = 2 (u + v, v), on the grid 1/g.
      const long ya = 2 * (i + j), yb = 2 * j;
      std::vector<Rational> w(reg_points.size());
      for (std::size_t p = 0; p < reg_points.size(); ++p)
        w[p] = phi.at(ya - g * reg_points[p].first, yb - g * reg_points[p].second);
      slot(i, j) = times(w, reg_rows, m);
    }
  // x = 0: the left eigenvector of A0 for eigenvalue 1, summing to 1.
  const LinearSolution sol = left_fixed_vector(a0);
  if (sol.status != LinearSolution::Status::Unique)
    throw Error("Loop, valence " + std::to_string(valence) + ": the limit stencil has " + sol.describe());
  slot(0, 0) = sol.values;
  return out;
}

}  // namespace sg
