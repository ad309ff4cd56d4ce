#pragma once
// Stencils of a triangle scheme's patch around an extraordinary vertex, on the
// grid (i/g, j/g), i + j <= g, in the arithmetic T: Rational (exact, where the
// scheme's weights are rational at this valence) or Real (high precision, with
// residuals).
//
// Patch: the triangle (EV, e_0, e_1) of sector 0 (sector_chart.hpp), parameters
// (u, v), u + v <= 1, the EV at (0,0), u towards e_0, v towards e_1; the point
// (u, v) sits at u (1,0) + v (1,1) in sector 0's frame. Stencils are sparse
// over the chart's points (sorted by index); the tables keep only the points
// some stencil uses.
//
// Regions: 0 is that patch. For sqrt(3) at valences other than 6 the vertex
// rule also reaches the triangles of the EV's second ring (irregular_radius 2),
// so a table holds three more regions, the "band" triangles of sector 0 (in its
// frame, corners counter-clockwise): 1 = (1,0),(2,0),(2,1); 2 = (1,0),(2,1),(1,1);
// 3 = (1,1),(2,1),(2,2). Region r's point (u, v) is corner 0 + u (corner 1 -
// corner 0) + v (corner 2 - corner 0).
//
// Method (the note, section 3): with A the local subdivision matrix (one
// composite step, dilation m) and x on the grid, W(x) = F(m x) A, where F(y) is
// W(y) when y lies in the patch again (the extraordinary child, recursion) and
// the regular scaling function's stencil at y otherwise (the other children
// are regular). W(0) is the left eigenvector of A for eigenvalue 1.
#include <array>
#include <map>
#include <vector>

#include "triangle/bivariate_solver.hpp"
#include "triangle/sector_chart.hpp"
#include "triangle/triangle_refinement.hpp"
#include "triangle/triangle_scheme.hpp"

namespace sg {

template <class T>
struct TrianglePatch {
  int valence = 6;
  long grid = 1;
  SectorChart chart{6, 1};
  std::vector<SparseRow<T>> stencils;  // index j * (g + 1) + i, for i + j <= g
  // Wedge points beyond the patch (1/g units, a > g): those the recursion
  // passed through and the band points asked for.
  std::map<LatticeIndex, SparseRow<T>> beyond;
  // The regular patch only (valence 6, given its basis's gradient): d/du and
  // d/dv stencils at every grid point, indexed as `stencils`; empty otherwise.
  std::vector<SparseRow<T>> du, dv;
  T eigen_residual = 0;                  // max |W(0) A - W(0)| (zero when exact)
  T unity_residual = 0;                  // max |sum W(x) - 1| over the grid (zero when exact)
  const SparseRow<T>& at(long i, long j) const { return stencils[static_cast<std::size_t>(j * (grid + 1) + i)]; }
  // Region r's point (i/g, j/g); throws sg::Error when it was not solved.
  const SparseRow<T>& at(int region, long i, long j) const;
};

// 1, or 4 where the scheme's vertex rule reaches the second ring (sqrt(3) at a
// valence other than 6).
int patch_regions(const TriangleScheme& scheme, int valence);
// Region r's point (i/g, j/g) as a wedge point of sector 0 (1/g units: a (1,0) + b (1,1)).
LatticeIndex region_point(int region, long i, long j, long g);
// Region r's corners in sector 0's frame (a, b).
std::array<LatticeIndex, 3> region_corners(int region);

// Rings of the chart the scheme's patches need (Loop 3, sqrt(3) 8).
long patch_rings(const TriangleScheme& scheme);
// Radius (coarse rings, in the wedge of sector 0) within which the children are
// not regular and the recursion continues: Loop 1 (the patch), sqrt(3) 2.
long irregular_radius(const TriangleScheme& scheme);

// The regular scaling function on (1/g)Z^2 (rational: valence 6 is).
BivariateSolution solve_regular(const TriangleScheme& scheme, long g);
// With its gradient there (bivariate_solver.hpp), in one pass.
std::pair<BivariateSolution, BivariateGradient> solve_regular_with_gradient(const TriangleScheme& scheme, long g);

// The weights of one valence in T; for Rational, throws sg::Error when the
// scheme's weights are irrational there.
template <class T>
TriangleWeights<T> triangle_weights(const TriangleScheme& scheme, int valence);

// Solves every grid point of region 0 and, besides, the band points (region,
// i, j) listed in `band` (regions 1..3; patch_regions must allow them). With
// `gradient` (the regular basis's partials on the grid g) at valence 6, also
// the derivative stencils du and dv: the patch point (u, v) lies at
// (a, b) = (u + v, v) of the lattice, so d/du = d/da and d/dv = d/da + d/db.
template <class T>
TrianglePatch<T> solve_triangle_patch(const TriangleScheme& scheme, int valence, long g, const BivariateSolution& regular,
                                      const std::vector<std::array<long, 3>>& band = {},
                                      const BivariateGradient* gradient = nullptr);

}  // namespace sg
