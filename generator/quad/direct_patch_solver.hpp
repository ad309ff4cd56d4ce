#pragma once
// The paper's route, as an independent check of the recursion: every scaling
// relation of the patch's basis functions on the grid (1/n)^2, together with
// the bivariate scaling relations of the regular basis phi(x)phi(y) and partition
// of unity, assembled into one sparse exact linear system and solved at once.
// Meant for small n (the system has about (2v+8)(n+1)^2 + (4n-1)^2 unknowns).
#include "quad/ev_patch_solver.hpp"

namespace sg {

// Same result as solve_ev_patch(scheme, valence, n) when the system has a unique
// solution; throws sg::Error naming the solution space otherwise.
PatchGrid solve_ev_patch_directly(const QuadScheme& scheme, int valence, long n);

}  // namespace sg
