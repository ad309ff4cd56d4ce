#pragma once
// Semi-sharp creases and corners: one subdivision step of a scheme's smooth
// rules with the rows of the points at sharp features replaced by
// OpenSubdiv's creasing masks (Sdc's crease, corner and transition masks),
// the crease rule being the scheme's own crease curve. The sharpness decays
// each step; once it is gone the mesh is smooth and its patches are evaluated
// exactly from the tables (docs/runtime.md). Shared by the quad and triangle
// families, which differ only in where a step puts its edge points.
#include <vector>

#include "mesh/connectivity.hpp"
#include "mesh/sharpness.hpp"
#include "refinement.hpp"

namespace stencil_runtime {

// The subdivision rule along a crease: the curve's vertex mask (neighbour,
// centre, neighbour); new edge points are edge midpoints.
struct CurveCreaseRule {
  double centre = 0, neighbour = 0;
};

// Applies the creasing of `sharpness` (of `parent`'s vertices and edges) to
// `step`, one smooth step of `parent` that keeps the old vertices' numbers
// and puts the new vertex of the edge from corner k (in concatenated
// face-vertex order) to the next corner of its face at `edge_points[k]`.
// Returns the sharpness of the child level.
// Refuses, before any work, a sharpness whose ceil(sharpest) whole-mesh steps
// would make more than limits::kMaxCreaseStepFaces faces: `first` faces after
// the first step, each later step multiplying them by 4. Throws MeshError.
void check_crease_steps(std::size_t faces, std::size_t first, float sharpest);
// Whether those steps make at most `budget` faces.
bool crease_steps_fit(std::size_t first, float sharpest, std::size_t budget);

// A mesh with boundaries: its boundary edges are infinitely sharp (and, with
// `boundary_corners`, its boundary vertices in one face), as in OpenSubdiv; the
// step must already hold the boundary rules (they are not sharpness here).
LevelSharpness sharpen_step(const Connectivity& parent, const LevelSharpness& sharpness, const CurveCreaseRule& rule,
                            const std::vector<int>& edge_points, RefinementStep& step, bool boundary_corners = false);

}  // namespace stencil_runtime
