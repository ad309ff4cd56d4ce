#pragma once
// The preparation's refinement as sparse matrices: each whole-mesh subdivision
// step (the polygon step, an isolation step, one of sqrt(3)'s two half-steps)
// is a matrix S whose row r gives new vertex r as a weighted sum of the
// vertices of the level before. Prepared vertices = S_k ... S_1 * control
// vertices: built once from the topology and the scheme's rules, applied to
// new positions every frame, and folded into limit-point rows to express them
// over the control vertices.
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "stencil_runtime/mesh.hpp"

namespace stencil_runtime {

// Sparse (column, weight) entries of one row.
using SparseEntries = std::vector<std::pair<std::uint32_t, double>>;

struct RefinementStep {
  std::size_t input_vertices = 0;
  std::vector<std::size_t> offsets{0};  // row r: entries [offsets[r], offsets[r + 1])
  std::vector<std::uint32_t> columns;
  std::vector<double> weights;

  std::size_t rows() const { return offsets.size() - 1; }
  // Appends a row; `entries` is sorted and duplicate columns merged (in place).
  void add_row(SparseEntries& entries);
  // out[r] = sum of weights * in[columns] (rows in parallel for large steps).
  void apply(const Point* in, Point* out) const;
};

// A step that keeps every one of `vertices` and appends `extra` rows over them
// (phantom points beyond a boundary, copies of vertices on a sharp crease).
RefinementStep append_rows(std::size_t vertices, const std::vector<std::vector<std::pair<int, double>>>& extra);
// A step of those `rows` alone over `vertices` vertices (Refinement::append reads them in place).
RefinementStep rows_over(std::size_t vertices, const std::vector<std::vector<std::pair<int, double>>>& rows);

class Refinement {
 public:
  explicit Refinement(std::size_t control_vertices = 0) : control_(control_vertices) {}
  void add(RefinementStep step);
  // A step before all the others: the control vertices become its input.
  void prepend(RefinementStep step);
  // A step after all the others whose rows read a block of the prepared
  // vertices so far, [input_offset, input_offset + step.input_vertices), and
  // are appended to them: the levels refined round semi-sharp features
  // (quad/semi_sharp_levels.hpp), each made from the level before it. Every
  // add() comes before the first append().
  void append(RefinementStep step, std::size_t input_offset);

  std::size_t control_vertices() const { return control_; }
  std::size_t prepared_vertices() const { return chain_vertices() + appended_vertices_; }
  const std::vector<RefinementStep>& steps() const { return steps_; }

  // prepared = S_k ... S_1 * control; `levels` holds the intermediate levels
  // and is reused (no allocation once sized).
  void apply(const Point* control, std::vector<std::vector<Point>>& levels, std::vector<Point>& prepared) const;
  // A row over prepared vertices, rewritten over the control vertices
  // (ascending columns, duplicates merged).
  void fold(SparseEntries& row) const;

 private:
  struct Appended {
    RefinementStep step;
    std::size_t input_offset = 0, output_offset = 0;
  };
  std::size_t chain_vertices() const { return steps_.empty() ? control_ : steps_.back().rows(); }
  void apply_chain(const Point* control, std::vector<std::vector<Point>>& levels, std::vector<Point>& prepared) const;

  std::size_t control_;
  std::vector<RefinementStep> steps_;
  std::vector<Appended> appended_;
  std::size_t appended_vertices_ = 0;
};

// Sorts entries by column and merges duplicates.
void merge_entries(SparseEntries& entries);

}  // namespace stencil_runtime
