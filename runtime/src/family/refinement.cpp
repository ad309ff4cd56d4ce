#include "refinement.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>

namespace stencil_runtime {

void merge_entries(SparseEntries& entries) {
  std::sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::size_t out = 0;
  for (std::size_t k = 0; k < entries.size(); ++k) {
    if (out > 0 && entries[out - 1].first == entries[k].first) entries[out - 1].second += entries[k].second;
    else entries[out++] = entries[k];
  }
  entries.resize(out);
}

void RefinementStep::add_row(SparseEntries& entries) {
  merge_entries(entries);
  for (const auto& [c, w] : entries) {
    columns.push_back(c);
    weights.push_back(w);
  }
  offsets.push_back(columns.size());
}

void RefinementStep::apply(const Point* in, Point* out) const {
  auto rows_in = [&](std::size_t begin, std::size_t end) {
    for (std::size_t r = begin; r != end; ++r) {
      double x = 0, y = 0, z = 0;
      for (std::size_t e = offsets[r]; e != offsets[r + 1]; ++e) {
        const Point& p = in[columns[e]];
        const double w = weights[e];
        x += w * p[0], y += w * p[1], z += w * p[2];
      }
      out[r] = {x, y, z};
    }
  };
  if (rows() < 16384) {
    rows_in(0, rows());
    return;
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rows(), 4096),
                    [&](const tbb::blocked_range<std::size_t>& r) { rows_in(r.begin(), r.end()); });
}

void Refinement::apply(const Point* control, std::vector<std::vector<Point>>& levels, std::vector<Point>& prepared) const {
  prepared.resize(prepared_vertices());
  if (steps_.empty()) {
    std::copy(control, control + control_, prepared.begin());
    return;
  }
  levels.resize(steps_.size() - 1);
  const Point* in = control;
  for (std::size_t s = 0; s < steps_.size(); ++s) {
    Point* out;
    if (s + 1 == steps_.size()) {
      out = prepared.data();
    } else {
      levels[s].resize(steps_[s].rows());
      out = levels[s].data();
    }
    steps_[s].apply(in, out);
    in = out;
  }
}

RefinementStep append_rows(std::size_t vertices, const std::vector<std::vector<std::pair<int, double>>>& extra) {
  RefinementStep step;
  step.input_vertices = vertices;
  SparseEntries row;
  for (std::size_t v = 0; v < vertices; ++v) {
    row.assign(1, {static_cast<std::uint32_t>(v), 1.0});
    step.add_row(row);
  }
  for (const auto& p : extra) {
    row.clear();
    for (const auto& [v, w] : p) row.emplace_back(static_cast<std::uint32_t>(v), w);
    step.add_row(row);
  }
  return step;
}

void Refinement::fold(SparseEntries& row) const {
  SparseEntries next;
  for (std::size_t s = steps_.size(); s-- > 0;) {
    const RefinementStep& step = steps_[s];
    next.clear();
    for (const auto& [r, w] : row)
      for (std::size_t e = step.offsets[r]; e != step.offsets[r + 1]; ++e) next.emplace_back(step.columns[e], w * step.weights[e]);
    merge_entries(next);
    row.swap(next);
  }
  merge_entries(row);
}

}  // namespace stencil_runtime
