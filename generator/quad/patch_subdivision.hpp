#pragma once
// One subdivision step of a quad patch around an extraordinary vertex, as
// exact matrices over the patch's control points: for a vertex inside the mesh
// the 2v+8 points of patch_layout.hpp, for a vertex on a boundary the points of
// its sector (boundary_sector.hpp). Built from the scheme's face, edge and
// vertex rules (and, on a boundary, its boundary curve's rules) on the patch's
// chart; the mesh itself is never needed.
#include <array>
#include <utility>
#include <vector>

#include "quad/patch_layout.hpp"
#include "quad/quad_scheme.hpp"

namespace sg {

using SparseRow = std::vector<std::pair<std::size_t, Rational>>;  // (parent index, weight)

struct PatchSubdivision {
  std::size_t points = 0;  // control points of the patch (and of its extraordinary child)
  // The patch's mirror symmetry (x,y) -> (y,x) on its points, W(y,x)[reflection[h]]
  // = W(x,y)[h]; empty where the patch has none (a face in a boundary sector).
  std::vector<std::size_t> reflection;
  // Rows of A0: the control points of the extraordinary child patch [0,1/2]^2
  // (again canonical order, same layout) in terms of the parent's points.
  std::vector<SparseRow> extraordinary_child;
  // The three regular children [1/2,1]x[0,1/2], [0,1/2]x[1/2,1], [1/2,1]^2
  // (offsets (1,0), (0,1), (1,1) in half-patch units): their 16 control points
  // in regular order (patch_layout.hpp), in terms of the parent's points. A
  // child on a boundary has its missing row or column folded in as the
  // "phantom" 2 p(boundary) - p(next inside) (docs/runtime.md, "Boundaries").
  std::array<std::vector<SparseRow>, 3> regular_children;
  static constexpr int kOffsets[3][2] = {{1, 0}, {0, 1}, {1, 1}};
};

PatchSubdivision build_patch_subdivision(const QuadScheme& scheme, int valence);
// The same with another rule at the extraordinary vertex (a cone point's: it stays put).
PatchSubdivision build_patch_subdivision(const QuadScheme& scheme, int valence, const VertexRule& ev_rule);

// Dense copy of the rows (rows x columns), for analysis and checks.
std::vector<std::vector<Rational>> dense(const std::vector<SparseRow>& rows, std::size_t columns);

// The refined point at refined chart position (I,J) (I,J in {-1..3}, not
// (-1,-1)) of the patch around a vertex of the given valence, in terms of the
// patch's control points. Used to assemble larger local matrices by rotation.
SparseRow refined_chart_point(const QuadScheme& scheme, int valence, int I, int J);

}  // namespace sg
