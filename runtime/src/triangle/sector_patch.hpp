#pragma once
// The patch of a face of a Loop mesh at a boundary vertex B that the regular
// boundary patch does not cover (boundary_patch.hpp): B in other than three
// faces, or a corner (docs/table-format.md, "Loop boundary sectors"). B's faces
// are unfolded onto the tables' wedge chart (k wedges of the lattice round B,
// its two boundary edges the rays 0 and k), and the sector's layout is read
// off it. Every other vertex the layout reaches must be regular (valence 6
// inside, three faces and the crease rule on the boundary): the isolation
// steps make it so.
#include <optional>
#include <vector>

#include "chart_patch.hpp"
#include "tables/patch_kind.hpp"

namespace stencil_runtime {

// Whether B needs a sector's patch: on the boundary (of the mesh, or of the
// mesh cut along its infinitely sharp edges) in other than three faces, or
// with the corner or dart rule (a dart: the end of a slit, whose two sides are
// the wedge's rays 0 and k, the cut's copies of the same points).
bool loop_sector_vertex(const TriangleTopology& topology, int vertex, SectorRule rule);

// The patch of face f, whose corner `corner` is B (with rule `rule`), or
// nullopt when B's neighbourhood does not unfold onto the wedge as far as the
// layout reaches (another irregular vertex, or the mesh's end, too close), or
// a layout vertex other than B is not regular (`rules`: every vertex's rule).
// Throws EvaluationError when the tables hold no such sector.
std::optional<TrianglePatch> loop_sector_patch(const TriangleTopology& topology, std::size_t f, int corner,
                                               const std::vector<SectorRule>& rules, const TriangleTables& tables);

}  // namespace stencil_runtime
