#include "refinement.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>

#include "stencil_runtime/error.hpp"

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

void Refinement::add(RefinementStep step) {
  // The appended steps read the chain's output by position: it may not change under them.
  if (!appended_.empty()) throw EvaluationError("internal: a refinement step added after an appended one");
  steps_.push_back(std::move(step));
}

void Refinement::prepend(RefinementStep step) {
  if (!appended_.empty() && step.rows() != control_)
    throw EvaluationError("internal: a refinement step prepended that changes the vertices the appended steps read");
  control_ = step.input_vertices;
  steps_.insert(steps_.begin(), std::move(step));
}

void Refinement::append(RefinementStep step, std::size_t input_offset) {
  const std::size_t prepared = prepared_vertices();
  if (input_offset > prepared || step.input_vertices > prepared - input_offset)
    throw EvaluationError("internal: an appended refinement step reads beyond the prepared vertices");
  appended_vertices_ += step.rows();
  appended_.push_back({std::move(step), input_offset, prepared});
}

void Refinement::apply(const Point* control, std::vector<std::vector<Point>>& levels, std::vector<Point>& prepared) const {
  prepared.resize(prepared_vertices());
  apply_chain(control, levels, prepared);
  for (const Appended& a : appended_) a.step.apply(prepared.data() + a.input_offset, prepared.data() + a.output_offset);
}

void Refinement::apply_chain(const Point* control, std::vector<std::vector<Point>>& levels, std::vector<Point>& prepared) const {
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

namespace {

void add_rows(RefinementStep& step, const std::vector<std::vector<std::pair<int, double>>>& rows) {
  SparseEntries row;
  for (const auto& p : rows) {
    row.clear();
    for (const auto& [v, w] : p) row.emplace_back(static_cast<std::uint32_t>(v), w);
    step.add_row(row);
  }
}

}  // namespace

RefinementStep append_rows(std::size_t vertices, const std::vector<std::vector<std::pair<int, double>>>& extra) {
  RefinementStep step;
  step.input_vertices = vertices;
  SparseEntries row;
  for (std::size_t v = 0; v < vertices; ++v) {
    row.assign(1, {static_cast<std::uint32_t>(v), 1.0});
    step.add_row(row);
  }
  add_rows(step, extra);
  return step;
}

RefinementStep rows_over(std::size_t vertices, const std::vector<std::vector<std::pair<int, double>>>& rows) {
  RefinementStep step;
  step.input_vertices = vertices;
  add_rows(step, rows);
  return step;
}

void Refinement::fold(SparseEntries& row) const {
  SparseEntries next;
  // The appended blocks, last first (each reads only blocks before it), then the chain.
  for (std::size_t s = appended_.size(); s-- > 0;) {
    const Appended& a = appended_[s];
    next.clear();
    for (const auto& [r, w] : row) {
      if (r < a.output_offset) {
        next.emplace_back(r, w);
        continue;
      }
      const std::size_t k = r - a.output_offset;
      for (std::size_t e = a.step.offsets[k]; e != a.step.offsets[k + 1]; ++e)
        next.emplace_back(static_cast<std::uint32_t>(a.input_offset + a.step.columns[e]), w * a.step.weights[e]);
    }
    merge_entries(next);
    row.swap(next);
  }
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
