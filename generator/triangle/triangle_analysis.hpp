#pragma once
// Smoothness analysis of a triangle scheme's extraordinary rules at one
// valence, as for quads (quad/quad_analysis.hpp): the spectrum of the local
// subdivision matrix on the two-ring (3v+1 points; for sqrt(3) the two composed
// steps, which remove the lattice's rotation), and the characteristic map from
// the subdominant eigenvectors, sampled through the patch stencils of every
// sector. Computed in double from the 80-digit weights.
#include "common/smoothness_report.hpp"
#include "triangle/triangle_scheme.hpp"

namespace sg {

SmoothnessReport analyse_triangle_valence(const TriangleScheme& scheme, int valence, long samples = 24);

}  // namespace sg
