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

// A vertex on the boundary in `faces` faces under the boundary rules (boundary_sector.hpp):
// the largest eigenvalues of its sector's subdivision matrix and whether they
// give a tangent plane there (ev_tangents.hpp: real, with a gap, the boundary
// curve's tangent among their eigenvectors, the characteristic map regular on
// each face). One line of text; `ok` says whether there is a tangent plane.
std::string analyse_quad_boundary(const QuadScheme& scheme, int faces, bool& ok);

}  // namespace sg
