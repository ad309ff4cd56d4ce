#pragma once
// Exact stencils of a quad patch around an extraordinary vertex, on the grid
// (1/g)Z^2 restricted to the patch [0,1]^2.
//
// The recursion of docs/schemes.md: for x in the extraordinary child [0,1/2]^2,
// W(x) = W(2x) A0 (A0: the patch's one-step subdivision matrix onto the child
// patch); for x in one of the three regular children, W(x) is the regular
// (tensor product) stencil at 2x - offset pulled back through the rows of the
// refined mesh that child uses; at x = 0, the left eigenvector of A0 for the
// eigenvalue 1, normalised to sum 1. The same for a vertex inside the mesh
// (valence v) and for a vertex on its boundary (a sector, boundary_sector.hpp).
#include <string>
#include <vector>

#include "algebra/scaled_vector.hpp"
#include "curve/curve_solution.hpp"
#include "quad/boundary_sector.hpp"
#include "quad/quad_scheme.hpp"

namespace sg {

struct PatchSubdivision;  // patch_subdivision.hpp

struct PatchGrid {
  int valence = 4;  // 0 for a boundary sector's patch
  long grid = 1;
  std::size_t points = 0;  // control points per stencil (2v+8 inside the mesh)
  std::vector<ScaledVector> scaled;              // (grid+1)^2 stencils, index j*(grid+1)+i, reduced
  std::vector<std::vector<Rational>> stencils;  // the same as rationals
  const std::vector<Rational>& at(long i, long j) const { return stencils[static_cast<std::size_t>(j * (grid + 1) + i)]; }
};

// W(i/g, j/g) for 0 <= i,j <= g. `curve` must be the solution of scheme.curve at rate g.
PatchGrid solve_ev_patch(const QuadScheme& scheme, int valence, long g, const CurveSolution& curve);
// Throws sg::Error when the extraordinary vertex's limit stencil is not unique.
// Convenience: solves the curve at rate g first.
PatchGrid solve_ev_patch(const QuadScheme& scheme, int valence, long g);

// The same for the patch of a face at a boundary vertex.
PatchGrid solve_sector_patch(const QuadScheme& scheme, const BoundarySector& sector, long g, const CurveSolution& curve);
PatchGrid solve_sector_patch(const QuadScheme& scheme, const BoundarySector& sector, long g);

// The left eigenvector of A0 for the eigenvalue 1 whose entries sum to 1 (the
// vertex's limit stencil, W(0)); throws sg::Error naming `what` when it is not unique.
std::vector<Rational> limit_stencil(const PatchSubdivision& sub, const std::string& what);

// The recursion itself, for any patch subdivision with its limit stencil W(0).
// Where the subdivision has a reflection only i <= j is computed and mirrored.
PatchGrid solve_patch_recursion(const PatchSubdivision& sub, const std::vector<Rational>& limit, long g,
                                const CurveSolution& curve);

}  // namespace sg
