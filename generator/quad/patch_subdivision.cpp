#include "quad/patch_subdivision.hpp"

#include <map>

#include "algebra/integer_division.hpp"
#include "base/error.hpp"

namespace sg {

namespace {

class RowBuilder {
 public:
  void add(std::size_t index, const Rational& w) { acc_[index] += w; }
  SparseRow take() {
    SparseRow row;
    for (auto& [i, w] : acc_)
      if (w != 0) row.emplace_back(i, w);
    acc_.clear();
    return row;
  }

 private:
  std::map<std::size_t, Rational> acc_;
};

class Refiner {
 public:
  Refiner(const QuadScheme& s, int valence)
      : layout_(valence), v_(valence), ev_rule_(s.vertex_rule(valence)), regular_(s.vertex_rule(4)), s_(s) {}

  // Refined point at refined chart position (I,J), I,J in {-1..3}, (I,J) != (-1,-1).
  SparseRow at(int I, int J) {
    if (I >= -1 && I <= 1 && J >= -1 && J <= 1) return one_ring(*layout_.chart(I, J));
    const bool odd_i = floor_div(I, 2) * 2 != I, odd_j = floor_div(J, 2) * 2 != J;
    const int i = static_cast<int>(floor_div(I, 2)), j = static_cast<int>(floor_div(J, 2));
    if (!odd_i && !odd_j) {  // vertex point of an old regular vertex
      add(i, j, regular_.centre);
      for (auto [di, dj] : {std::pair{1, 0}, {0, 1}, {-1, 0}, {0, -1}}) add(i + di, j + dj, regular_.edge);
      for (auto [di, dj] : {std::pair{1, 1}, {-1, 1}, {-1, -1}, {1, -1}}) add(i + di, j + dj, regular_.face);
    } else if (odd_i && !odd_j) {  // horizontal edge (i,j)-(i+1,j)
      add(i, j, s_.edge_end), add(i + 1, j, s_.edge_end);
      for (int d : {-1, 1}) add(i, j + d, s_.edge_wing), add(i + 1, j + d, s_.edge_wing);
    } else if (!odd_i && odd_j) {  // vertical edge (i,j)-(i,j+1)
      add(i, j, s_.edge_end), add(i, j + 1, s_.edge_end);
      for (int d : {-1, 1}) add(i + d, j, s_.edge_wing), add(i + d, j + 1, s_.edge_wing);
    } else {  // face [i,i+1]x[j,j+1]
      for (int di : {0, 1})
        for (int dj : {0, 1}) add(i + di, j + dj, s_.face_corner);
    }
    return row_.take();
  }

  // Refined one-ring point with canonical index h (EV, e_k or f_k).
  SparseRow one_ring(std::size_t h) {
    const PatchLayout& L = layout_;
    if (h == PatchLayout::ev()) {
      row_.add(L.ev(), ev_rule_.centre);
      for (int k = 0; k < v_; ++k) row_.add(L.edge(k), ev_rule_.edge), row_.add(L.face(k), ev_rule_.face);
    } else if (h % 2 == 1) {  // e_k: edge EV-e_k between the quads k-1 and k
      const int k = static_cast<int>(h - 1) / 2;
      row_.add(L.ev(), s_.edge_end), row_.add(L.edge(k), s_.edge_end);
      for (std::size_t w : {L.edge(k - 1), L.face(k - 1), L.edge(k + 1), L.face(k)}) row_.add(w, s_.edge_wing);
    } else {  // f_k: quad (EV, e_k, f_k, e_{k+1})
      const int k = static_cast<int>(h - 2) / 2;
      for (std::size_t c : {L.ev(), L.edge(k), L.face(k), L.edge(k + 1)}) row_.add(c, s_.face_corner);
    }
    return row_.take();
  }

  const PatchLayout& layout() const { return layout_; }

 private:
  void add(int i, int j, const Rational& w) {
    const auto index = layout_.chart(i, j);
    if (!index) throw Error("internal: refined point needs chart point (" + std::to_string(i) + "," + std::to_string(j) + ")");
    row_.add(*index, w);
  }

  PatchLayout layout_;
  int v_;
  VertexRule ev_rule_, regular_;
  const QuadScheme& s_;
  RowBuilder row_;
};

}  // namespace

PatchSubdivision build_patch_subdivision(const QuadScheme& scheme, int valence) {
  Refiner refine(scheme, valence);
  const PatchLayout& L = refine.layout();
  PatchSubdivision out{L, {}, {}};
  out.extraordinary_child.resize(L.size());
  for (std::size_t h = 0; h <= 2 * static_cast<std::size_t>(valence); ++h) out.extraordinary_child[h] = refine.one_ring(h);
  for (int t = 0; t < 7; ++t) {
    const auto [I, J] = *L.position(L.outer(t));
    out.extraordinary_child[L.outer(t)] = refine.at(I, J);
  }
  for (int c = 0; c < 3; ++c) {
    auto& rows = out.regular_children[c];
    rows.resize(16);
    for (int b = -1; b <= 2; ++b)
      for (int a = -1; a <= 2; ++a)
        rows[regular_index(a, b)] = refine.at(PatchSubdivision::kOffsets[c][0] + a, PatchSubdivision::kOffsets[c][1] + b);
  }
  return out;
}

std::vector<std::vector<Rational>> dense(const std::vector<SparseRow>& rows, std::size_t columns) {
  std::vector<std::vector<Rational>> m(rows.size(), std::vector<Rational>(columns));
  for (std::size_t r = 0; r < rows.size(); ++r)
    for (const auto& [c, w] : rows[r]) m[r][c] = w;
  return m;
}

}  // namespace sg

namespace sg {

SparseRow refined_chart_point(const QuadScheme& scheme, int valence, int I, int J) {
  Refiner refine(scheme, valence);
  return refine.at(I, J);
}

}  // namespace sg
