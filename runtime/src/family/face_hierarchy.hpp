#pragma once
// Which prepared faces cover each original face: per refinement step, the
// first child of every face of the level before, and how many times smaller
// across its children are (2 for the 1-to-4 splits and the polygon step, 3 for
// sqrt(3)'s 1-to-9 split). A face's descendants are contiguous at every level.
#include <cstddef>
#include <utility>
#include <vector>

namespace stencil_runtime {

struct FaceHierarchy {
  struct Level {
    std::vector<std::size_t> child_offsets;  // size faces + 1
    int scale = 2;
  };
  std::size_t original_faces = 0;
  std::vector<Level> levels;

  std::size_t prepared_faces() const { return levels.empty() ? original_faces : levels.back().child_offsets.back(); }
  // Records a step that split each of the current faces into `children` faces.
  void add_uniform(std::size_t children, int scale);
  void add(std::vector<std::size_t> child_offsets, int scale) { levels.push_back({std::move(child_offsets), scale}); }
  // The prepared faces [first, last) covering original face `face`.
  std::pair<std::size_t, std::size_t> prepared_range(std::size_t face) const;
  // Rates of the prepared faces from rates of the original faces: a step whose
  // children are s times smaller across gives them ceil(rate / s) (at least 1).
  std::vector<int> prepared_rates(const std::vector<int>& original) const;
};

}  // namespace stencil_runtime
