#pragma once
#include "curve/curve_scheme.hpp"

namespace sg {

// Fills support_lo/support_hi of every type with the exact smallest intervals
// I_h = [lo_h, hi_h] satisfying  I_h = hull over terms of (I_type + shift) / arity,
// found by policy iteration (the fixed point is rational: lo = l/(a-1) for a
// uniform mask on [l, r]).
void compute_supports(CurveScheme& scheme);

}  // namespace sg
