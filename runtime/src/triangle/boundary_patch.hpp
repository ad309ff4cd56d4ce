#pragma once
// The regular patch of a face of a Loop mesh with boundaries (docs/runtime.md,
// "Loop with boundaries"): where the three corners are regular (valence 6
// inside, three faces on the boundary), the limit surface over the face is the
// regular patch (Loop's quartic box spline) over its 12 points, the missing
// ones beyond the boundary being the affine phantoms b_1 + b_2 - r: the point
// across the boundary edge (b_1, b_2) from the real triangle (b_1, b_2, r).
// With them Loop's regular rules reproduce OpenSubdiv's boundary rules (the
// crease curve's vertex mask, boundary edges' midpoints), and the refined
// phantoms are again the same extrapolation, so the patch is exact.
#include <array>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "chart_patch.hpp"

namespace stencil_runtime {

// The phantom points the patches need, each once: rows over mesh vertices,
// numbered `first` + their position.
struct PhantomPoints {
  std::size_t first = 0;
  std::map<std::array<int, 3>, int> index;  // (b_1, b_2, r), b_1 < b_2
  std::vector<std::vector<std::pair<int, double>>> rows;
  int add(int b1, int b2, int r);
};

// Whether vertex v is regular for Loop: valence 6 inside, three faces on the boundary.
bool regular_loop_vertex(const TriangleTopology& topology, int v);

// The face's regular patch (rotation 0) when its three corners are regular,
// with phantoms for the points beyond the boundary (added to `phantoms`);
// nullopt when a corner is not regular or the corners' fans do not unfold
// onto the lattice (a mesh too small or folded there).
std::optional<TrianglePatch> regular_boundary_patch(const TriangleTopology& topology, std::size_t face,
                                                    const TriangleTables& tables, PhantomPoints& phantoms);

}  // namespace stencil_runtime
