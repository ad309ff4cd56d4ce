#pragma once
// The refined points of a quad patch's chart (refined chart positions (I,J),
// I,J in {-1..3}) from the scheme's rules, for the patch layouts of an
// interior extraordinary vertex and of a boundary sector alike. Outside the
// one ring (|I| or |J| > 1) every old vertex, edge and face is regular, except
// along the boundary half-lines a sector may have: j = 0, i >= 0 ("bottom") and
// i = 0, j >= 0 ("left"), where the boundary curve's rules hold (its vertex
// rule on a boundary vertex, its odd rule on a boundary edge). The one ring is
// the layout's own business (one_ring).
#include <map>
#include <optional>

#include "quad/patch_subdivision.hpp"

namespace sg {

// Accumulates one sparse row, merging repeated columns (a vertex may appear twice in a small mesh's chart).
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

class ChartRefiner {
 public:
  virtual ~ChartRefiner() = default;
  // Refined point at refined chart position (I,J), which must exist.
  SparseRow at(int I, int J);
  // Whether refined position (I,J) exists (it does not beyond a boundary).
  bool exists(int I, int J) const { return !(bottom_ && J < 0) && !(left_ && I < 0); }
  // The three regular children's 16 rows each, phantoms folded in where a child lies on a boundary.
  std::array<std::vector<SparseRow>, 3> regular_children();

 protected:
  // `boundary`: the layout is a boundary sector's (the curve's rules are needed even
  // where the chart itself has no boundary line).
  ChartRefiner(const QuadScheme& s, bool boundary, bool bottom, bool left);
  // Refined one-ring point with canonical index h.
  virtual SparseRow one_ring(std::size_t h) = 0;
  // Index of chart point (i,j) in the patch's canonical order, if the layout has it.
  virtual std::optional<std::size_t> chart(int i, int j) const = 0;
  void add(int i, int j, const Rational& w);

  const QuadScheme& s_;
  VertexRule regular_;
  std::array<Rational, 5> curve_;  // the boundary curve's mask by shift -2..2 (when there is a boundary)
  bool bottom_, left_;
  RowBuilder row_;
};

}  // namespace sg
