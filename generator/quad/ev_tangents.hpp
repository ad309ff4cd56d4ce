#pragma once
// The tangent plane of a quad patch at its extraordinary vertex, where the
// patch has no parametric derivative (valences other than 4): two tangent
// stencils spanned by the left eigenvectors of A0 (the patch's one-step
// subdivision matrix) for its subdominant eigenvalue lambda.
//
// Near the vertex the patch is f(x) = l0.P + c(x) . (L P) + o(lambda^k), with L
// the two left eigenvectors, R the right ones (L R = I), and c(x) = W(x) R the
// characteristic map. So t . P lies in the tangent plane for every t in the
// span of L. The two stencils returned are the directions of the patch's own
// u and v edges there: t_u = c(1, 0) L and t_v = c(0, 1) L (the edges are lines
// of the patch's mirror symmetry, so their images are rays), and t_u.P x t_v.P
// points as du x dv does next to the vertex (the characteristic map keeps or
// turns the orientation of both alike; sector angles are below pi). They are
// not parametric derivatives: their length is arbitrary.
//
// lambda is irrational in general (Catmull-Clark: a root of a quadratic with
// cos(2 pi / v) in it), so the stencils are computed in high precision (Real)
// by inverse subspace iteration from a double estimate, and the residual
// max |t A0 - lambda t| is reported.
#include <optional>
#include <string>
#include <vector>

#include "algebra/real.hpp"
#include "quad/patch_subdivision.hpp"
#include "quad/quad_scheme.hpp"

namespace sg {

struct EvTangents {
  Real eigenvalue;            // lambda, the subdominant eigenvalue of A0
  std::vector<Real> u, v;     // the two tangent stencils over the patch's 2v+8 points
  Real residual;              // max over both of |t A0 - lambda t|, relative to max |t|
};

// The tangents, or nothing (with `why` set) when the subdominant eigenvalue is
// not a real double one with a gap below it: then the scheme has no tangent
// plane there in the sense of Reif's analysis.
std::optional<EvTangents> ev_tangents(const QuadScheme& scheme, int valence, const PatchSubdivision& subdivision,
                                      std::string& why);

}  // namespace sg
