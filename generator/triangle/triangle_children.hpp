#pragma once
// The subdivision of one triangle patch into its children, for evaluation at
// any parameter (the runtime's triangle descent, docs/runtime.md).
//
// A patch (valence v, region r: triangle_patch.hpp) with corners C0, C1, C2 in
// sector 0's frame covers C0 + u (C1 - C0) + v (C2 - C0). One composite step
// (dilation m: Loop 2, sqrt(3) 3) splits it into m^2 cells of the refined
// lattice, in this order: the "up" cells (a, b), b = 0..m-1, a = 0..m-1-b, with
// corners (a,b), (a+1,b), (a,b+1), then the "down" cells (a, b),
// b = 0..m-2, a = 0..m-2-b, with corners (a+1,b), (a+1,b+1), (a,b+1) (units of
// 1/m along the patch's own u and v). A cell's parameter is affine in its
// corners in that order, like a patch's.
//
// Each cell is a patch again, of a kind the tables hold: the EV's own patch
// (the cell at the EV), a band region (sqrt(3): cells within two refined rings
// of the EV), or the regular patch (valence 6) elsewhere. Its control points
// are the refined points at its kind's layout, each an exact combination of the
// parent's layout points.
#include <vector>

#include "algebra/real.hpp"
#include "triangle/sector_chart.hpp"
#include "triangle/triangle_scheme.hpp"

namespace sg {

struct TriangleChild {
  int valence = 6;   // the kind: 6 (regular) or the parent's valence
  int region = 0;
  int rotation = 0;  // the cell's corner that sits at the kind's corner 0
  // One row per point of the kind's layout: (position in the parent's layout, weight).
  std::vector<std::vector<std::pair<std::size_t, double>>> rows;
  // The same weights in full precision (exact rationals or 80-digit reals), for
  // what is computed from them in the generator (the tangent stencils).
  std::vector<std::vector<std::pair<std::size_t, Real>>> real_rows;
  bool nonnegative = true;  // every weight >= 0
};

// The layouts the tables store: layouts[v][r] for every valence v (6 included) and region r.
using TriangleLayouts = std::vector<std::pair<int, std::vector<std::vector<SectorPoint>>>>;

// The m^2 children of valence `valence`'s region `region`. A child may need a
// parent point outside the layout (a layout from low rates lists only the
// points their stencils use): those are appended to `missing` (when given;
// else sg::Error) and the rows are then incomplete. Throws sg::Error for a kind
// without layout.
std::vector<TriangleChild> triangle_children(const TriangleScheme& scheme, int valence, int region,
                                             const TriangleLayouts& layouts, std::vector<SectorPoint>* missing = nullptr);

// Adds to `layouts` every point some child needs, until the children of every
// valence and region are complete (a point added to a layout gets weight 0 in
// the stored stencils).
void close_layouts(const TriangleScheme& scheme, TriangleLayouts& layouts);

// The regular patch's basis as polynomials in (u, v), when it is one: degree d
// and, per point of `layout` (valence 6's), the coefficients of u^e v^f in the
// order f = 0..d, e = 0..d-f. Degree 0 (no coefficients) when no polynomial of
// degree up to 6 interpolates the exact stencils on the grid 1/12 (sqrt(3)).
struct RegularPolynomial {
  int degree = 0;
  std::vector<std::vector<double>> coefficients;
};
RegularPolynomial regular_polynomial(const TriangleScheme& scheme, const std::vector<SectorPoint>& layout);
// Whether the regular patch's basis is a polynomial (Loop's quartic box
// spline): then its derivatives come from that polynomial, and the tables
// need no derivative stencils.
bool regular_basis_is_polynomial(const TriangleScheme& scheme);

}  // namespace sg
