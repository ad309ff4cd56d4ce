#pragma once
// Numerical smoothness analysis of a quad scheme's extraordinary rules at one
// valence (Reif's conditions): the spectrum of the local subdivision matrix on
// the two-ring (6v+1 points, which holds every patch around the vertex) and the
// characteristic map, sampled through the exact patch stencils.
#include "common/smoothness_report.hpp"
#include "quad/quad_scheme.hpp"

namespace sg {

// `samples`: the characteristic map is sampled on the grid (1/samples) of every sector.
SmoothnessReport analyse_quad_valence(const QuadScheme& scheme, int valence, long samples = 32);

}  // namespace sg
