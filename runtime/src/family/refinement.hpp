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

class Refinement {
 public:
  explicit Refinement(std::size_t control_vertices = 0) : control_(control_vertices) {}
  void add(RefinementStep step) { steps_.push_back(std::move(step)); }
  // A step before all the others: the control vertices become its input.
  void prepend(RefinementStep step) {
    control_ = step.input_vertices;
    steps_.insert(steps_.begin(), std::move(step));
  }
  std::size_t control_vertices() const { return control_; }
  std::size_t prepared_vertices() const { return steps_.empty() ? control_ : steps_.back().rows(); }
  const std::vector<RefinementStep>& steps() const { return steps_; }

  // prepared = S_k ... S_1 * control; `levels` holds the intermediate levels
  // and is reused (no allocation once sized).
  void apply(const Point* control, std::vector<std::vector<Point>>& levels, std::vector<Point>& prepared) const;
  // A row over prepared vertices, rewritten over the control vertices
  // (ascending columns, duplicates merged).
  void fold(SparseEntries& row) const;

 private:
  std::size_t control_;
  std::vector<RefinementStep> steps_;
};

// Sorts entries by column and merges duplicates.
void merge_entries(SparseEntries& entries);

}  // namespace stencil_runtime
