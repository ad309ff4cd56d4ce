#pragma once
// The tangent plane of a quad patch at its extraordinary vertex, where the
// patch has no parametric derivative (valences other than 4): two tangent
// stencils along the patch's u and v edges, from the left eigenvectors of A0
// (the patch's one-step subdivision matrix) for its subdominant eigenvalue
// (algebra/tangent_stencils.hpp says how and why).
#include <optional>
#include <string>
#include <vector>

#include "algebra/tangent_stencils.hpp"
#include "quad/boundary_sector.hpp"
#include "quad/patch_subdivision.hpp"
#include "quad/quad_scheme.hpp"

namespace sg {

using EvTangents = TangentStencils;  // over the patch's 2v+8 points

// The tangents, or nothing (with `why` set) when the subdominant eigenvalue is
// not a real double one with a gap below it: then the scheme has no tangent
// plane there in the sense of Reif's analysis.
std::optional<EvTangents> ev_tangents(const QuadScheme& scheme, int valence, const PatchSubdivision& subdivision,
                                      std::string& why);

// The same at a vertex on a boundary (boundary_tangent_stencils): `u` along the
// patch's u edge, `v` towards its opposite corner (1, 1), since in one face the
// u and v edges are both on the boundary, on a line. Nothing for a corner
// (no tangent plane) and where the surface is not C1 at the vertex.
std::optional<EvTangents> sector_tangents(const QuadScheme& scheme, const BoundarySector& sector,
                                          const PatchSubdivision& subdivision, const std::vector<Rational>& limit,
                                          std::string& why);

}  // namespace sg
