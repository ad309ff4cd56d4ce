#pragma once
// Regular (valence 6) masks of triangle schemes on the triangular lattice, in
// lattice coordinates whose six unit neighbours are, counter-clockwise,
// (1,0), (1,1), (0,1), (-1,0), (-1,-1), (0,-1). Derived from the schemes' own
// rules by refining a single coefficient.
#include "triangle/bivariate_solver.hpp"

namespace sg {

// Loop (dilation 2): edge point = end * (both ends) + opposite * (the two
// opposite vertices); vertex point = centre * old + neighbour * (each of 6).
BivariateMask loop_regular_mask(const Rational& end, const Rational& opposite, const Rational& centre,
                                const Rational& neighbour);

// Two steps of Kobbelt's sqrt(3) (each: a new vertex at every triangle's
// centroid, old vertices relaxed to (1 - alpha) p + alpha/6 * sum of neighbours,
// edges flipped), composed into one ternary step aligned with the lattice
// (dilation 3).
BivariateMask sqrt3_composite_mask(const Rational& alpha);

// The six unit neighbours, counter-clockwise.
inline constexpr long kTriangleNeighbours[6][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 0}, {-1, -1}, {0, -1}};

}  // namespace sg
