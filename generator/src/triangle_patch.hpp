#pragma once
// Exact stencils of a Loop triangle patch around an extraordinary vertex
// (issue 4, in progress: Loop at the valences whose weights are rational).
//
// Patch: the triangle (EV, e_0, e_1), parameters (u, v), u + v <= 1, with the
// EV at (0,0), u towards e_0 and v towards e_1. Chart: the triangular lattice of
// triangle_masks.hpp, with the patch's corners at (0,0), (1,0), (1,1) (so the
// point (u, v) sits at u (1,0) + v (1,1)). Control points, v + 6 of them:
//   index 0        the EV
//   index 1 + k    e_k, k = 0..v-1, counter-clockwise: e_0 = (1,0), e_1 = (1,1),
//                  e_2 = (0,1), e_{v-1} = (0,-1)
//   index v+1..v+5 the outer points (1,-1), (2,0), (2,1), (2,2), (1,2)
// For v = 6 these are the 12 points of the regular (box-spline) patch.
#include <vector>

#include "bivariate_solver.hpp"
#include "scaled_vector.hpp"

namespace sg {

// Loop's rules: edge point = 3/8 ends + 1/8 opposite vertices; vertex point at
// valence v = (1 - v beta) old + beta per neighbour.
struct LoopRules {
  Rational edge_end = Rational(3, 8), edge_opposite = Rational(1, 8);
  Rational beta_regular = Rational(1, 16);
  Rational beta_extraordinary;  // at the patch's valence
};

// Loop's beta(v) = (5/8 - (3/8 + cos(2 pi / v)/4)^2) / v where it is rational
// (v = 3, 4, 6); throws sg::Error naming the valence otherwise.
Rational loop_beta(int valence);

struct TrianglePatchGrid {
  int valence = 6;
  long grid = 1;
  std::size_t points = 12;
  // W(i/g, j/g) for i, j >= 0, i + j <= g, at index j * (g + 1) + i (other slots empty).
  std::vector<std::vector<Rational>> stencils;
  const std::vector<Rational>& at(long i, long j) const { return stencils[static_cast<std::size_t>(j * (grid + 1) + i)]; }
};

TrianglePatchGrid solve_loop_patch(int valence, long g);

}  // namespace sg
