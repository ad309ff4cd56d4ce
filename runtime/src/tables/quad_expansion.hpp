#pragma once
// The extraordinary patch's stencils at every node (i/n, j/n) and cell centre
// ((2i+1)/(2n), (2j+1)/(2n)) of every rate, computed at load time from what
// generates them (docs/schemes.md, the patch recursion): W(x) = W(2x) A0 in the
// extraordinary child, the regular (tensor-product) stencil at 2x - offset
// pulled back through the child's rows otherwise, and the limit stencil at 0.
// With `symmetric` (a patch with a reflection) only x <= y is computed and
// kept (the reflection gives the rest); otherwise (a boundary sector) every
// point. Computed in long double
// (64-bit mantissa), so the few levels of recursion leave the result within
// rounding of the exact rational stencils.
#include <cstdint>
#include <vector>

#include "quad_tables.hpp"

namespace stencil_runtime {

struct ExpandedPatch {
  std::vector<double> weights;                      // stencil_count * points
  std::vector<std::vector<std::uint32_t>> nodes;    // per rate: (i <= j) j-major, or every (i, j) j-major
  std::vector<std::vector<std::uint32_t>> centres;  // per rate
};

// `regular[r]` holds phi(k / (2 rates[r])) for k = regular_first[r] + ...;
// `limit` is W(0) (the patch's weights); `kind` a patch kind (patch_kind.hpp).
ExpandedPatch expand_patch(int kind, const QuadDescent::Valence& subdivision, const std::vector<double>& limit,
                           const std::vector<int>& rates, const std::vector<std::vector<double>>& regular,
                           const std::vector<std::int64_t>& regular_first, bool symmetric = true);

}  // namespace stencil_runtime
