#include "quad/patch_subdivision.hpp"

#include "algebra/integer_division.hpp"
#include "base/error.hpp"
#include "curve/one_ring_mask.hpp"
#include "quad/chart_refiner.hpp"

namespace sg {

ChartRefiner::ChartRefiner(const QuadScheme& s, bool boundary, bool bottom, bool left)
    : s_(s), regular_(s.vertex_rule(4)), bottom_(bottom), left_(left) {
  if (boundary) curve_ = one_ring_mask(s.curve, "the boundary rules are the regular curve's one-ring rules");
}

void ChartRefiner::add(int i, int j, const Rational& w) {
  const auto index = chart(i, j);
  if (!index) throw Error("internal: refined point needs chart point (" + std::to_string(i) + "," + std::to_string(j) + ")");
  row_.add(*index, w);
}

SparseRow ChartRefiner::at(int I, int J) {
  if (!exists(I, J)) throw Error("internal: refined chart point (" + std::to_string(I) + "," + std::to_string(J) + ") lies beyond the boundary");
  if (I >= -1 && I <= 1 && J >= -1 && J <= 1) return one_ring(*chart(I, J));
  const bool odd_i = floor_div(I, 2) * 2 != I, odd_j = floor_div(J, 2) * 2 != J;
  const int i = static_cast<int>(floor_div(I, 2)), j = static_cast<int>(floor_div(J, 2));
  if (!odd_i && !odd_j) {  // vertex point of an old vertex
    if (bottom_ && j == 0) {  // on the boundary: the curve's vertex rule along it
      add(i - 1, 0, curve_[4]), add(i, 0, curve_[2]), add(i + 1, 0, curve_[0]);
    } else if (left_ && i == 0) {
      add(0, j - 1, curve_[4]), add(0, j, curve_[2]), add(0, j + 1, curve_[0]);
    } else {
      add(i, j, regular_.centre);
      for (auto [di, dj] : {std::pair{1, 0}, {0, 1}, {-1, 0}, {0, -1}}) add(i + di, j + dj, regular_.edge);
      for (auto [di, dj] : {std::pair{1, 1}, {-1, 1}, {-1, -1}, {1, -1}}) add(i + di, j + dj, regular_.face);
    }
  } else if (odd_i && !odd_j) {  // horizontal edge (i,j)-(i+1,j)
    if (bottom_ && j == 0) {
      add(i, 0, curve_[3]), add(i + 1, 0, curve_[1]);
    } else {
      add(i, j, s_.edge_end), add(i + 1, j, s_.edge_end);
      for (int d : {-1, 1}) add(i, j + d, s_.edge_wing), add(i + 1, j + d, s_.edge_wing);
    }
  } else if (!odd_i && odd_j) {  // vertical edge (i,j)-(i,j+1)
    if (left_ && i == 0) {
      add(0, j, curve_[3]), add(0, j + 1, curve_[1]);
    } else {
      add(i, j, s_.edge_end), add(i, j + 1, s_.edge_end);
      for (int d : {-1, 1}) add(i + d, j, s_.edge_wing), add(i + d, j + 1, s_.edge_wing);
    }
  } else {  // face [i,i+1]x[j,j+1]
    for (int di : {0, 1})
      for (int dj : {0, 1}) add(i + di, j + dj, s_.face_corner);
  }
  return row_.take();
}

std::array<std::vector<SparseRow>, 3> ChartRefiner::regular_children() {
  std::array<std::vector<SparseRow>, 3> out;
  // 2 p - q as one row.
  auto phantom = [](const SparseRow& p, const SparseRow& q) {
    RowBuilder b;
    for (const auto& [h, w] : p) b.add(h, 2 * w);
    for (const auto& [h, w] : q) b.add(h, -w);
    return b.take();
  };
  for (int c = 0; c < 3; ++c) {
    auto& rows = out[static_cast<std::size_t>(c)];
    rows.resize(16);
    const int oi = PatchSubdivision::kOffsets[c][0], oj = PatchSubdivision::kOffsets[c][1];
    for (int b = -1; b <= 2; ++b)
      for (int a = -1; a <= 2; ++a) {
        const int I = oi + a, J = oj + b;
        SparseRow& row = rows[regular_index(a, b)];
        if (exists(I, J)) row = at(I, J);
        else if (J < 0) row = phantom(at(I, 0), at(I, 1));  // below the bottom boundary
        else row = phantom(at(0, J), at(1, J));            // left of the left boundary
      }
  }
  return out;
}

namespace {

// The chart of a patch round an interior vertex of valence v (patch_layout.hpp).
class InteriorRefiner final : public ChartRefiner {
 public:
  InteriorRefiner(const QuadScheme& s, int valence, const VertexRule& ev_rule)
      : ChartRefiner(s, false, false, false), layout_(valence), v_(valence), ev_rule_(ev_rule) {}
  const PatchLayout& layout() const { return layout_; }

  // Refined one-ring point with canonical index h (EV, e_k or f_k).
  SparseRow one_ring(std::size_t h) override {
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

 private:
  std::optional<std::size_t> chart(int i, int j) const override { return layout_.chart(i, j); }

  PatchLayout layout_;
  int v_;
  VertexRule ev_rule_;
};

}  // namespace

PatchSubdivision build_patch_subdivision(const QuadScheme& scheme, int valence) {
  return build_patch_subdivision(scheme, valence, scheme.vertex_rule(valence));
}

PatchSubdivision build_patch_subdivision(const QuadScheme& scheme, int valence, const VertexRule& ev_rule) {
  InteriorRefiner refine(scheme, valence, ev_rule);
  const PatchLayout& L = refine.layout();
  PatchSubdivision out;
  out.points = L.size();
  out.reflection = L.reflection();
  out.extraordinary_child.resize(L.size());
  for (std::size_t h = 0; h <= 2 * static_cast<std::size_t>(valence); ++h) out.extraordinary_child[h] = refine.one_ring(h);
  for (int t = 0; t < 7; ++t) {
    const auto [I, J] = *L.position(L.outer(t));
    out.extraordinary_child[L.outer(t)] = refine.at(I, J);
  }
  out.regular_children = refine.regular_children();
  return out;
}

std::vector<std::vector<Rational>> dense(const std::vector<SparseRow>& rows, std::size_t columns) {
  std::vector<std::vector<Rational>> m(rows.size(), std::vector<Rational>(columns));
  for (std::size_t r = 0; r < rows.size(); ++r)
    for (const auto& [c, w] : rows[r]) m[r][c] = w;
  return m;
}

SparseRow refined_chart_point(const QuadScheme& scheme, int valence, int I, int J) {
  InteriorRefiner refine(scheme, valence, scheme.vertex_rule(valence));
  return refine.at(I, J);
}

}  // namespace sg
