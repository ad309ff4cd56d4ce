#include "face_hierarchy.hpp"

#include <algorithm>

namespace stencil_runtime {

void FaceHierarchy::add_uniform(std::size_t children, int scale) {
  const std::size_t faces = prepared_faces();
  std::vector<std::size_t> offsets(faces + 1);
  for (std::size_t f = 0; f <= faces; ++f) offsets[f] = children * f;
  add(std::move(offsets), scale);
}

std::pair<std::size_t, std::size_t> FaceHierarchy::prepared_range(std::size_t face) const {
  std::size_t first = face, last = face + 1;
  for (const Level& level : levels) {
    first = level.child_offsets[first];
    last = level.child_offsets[last];
  }
  return {first, last};
}

std::vector<int> FaceHierarchy::prepared_rates(const std::vector<int>& original) const {
  std::vector<int> rates = original;
  for (const Level& level : levels) {
    std::vector<int> next(level.child_offsets.back());
    for (std::size_t f = 0; f + 1 < level.child_offsets.size(); ++f)
      for (std::size_t c = level.child_offsets[f]; c < level.child_offsets[f + 1]; ++c)
        next[c] = std::max(1, (rates[f] + level.scale - 1) / level.scale);
    rates = std::move(next);
  }
  return rates;
}

}  // namespace stencil_runtime
