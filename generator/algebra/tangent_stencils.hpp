#pragma once
// Tangent stencils at an extraordinary vertex from a patch's one-step
// subdivision matrix A0 (the patch's control points onto those of its child at
// the vertex, same layout), for quad and triangle patches alike.
//
// Near the vertex the patch is f(x) = l0.P + c(x) . (L P) + o(lambda^k), with L
// the two left eigenvectors of A0 for its subdominant eigenvalue lambda, R the
// right ones (L R = I), and c(x) = W(x) R the characteristic map. So t . P lies
// in the tangent plane for every t in the span of L. The stencils returned are
// the directions of the patch's two edges from the vertex: t_u = c(end_u) L
// and t_v = c(end_v) L, where end_u, end_v are the value stencils W at the
// far ends of those edges (the edges are lines of the patch's mirror symmetry,
// so their images under c are rays). t_u.P x t_v.P points as du x dv does next
// to the vertex when the patch's (u, v) frame is positively oriented: the
// characteristic map keeps or turns the orientation of both alike (sector
// angles are below pi). They are not parametric derivatives: they are scaled
// so that the largest weight is 1.
//
// lambda is irrational in general, so the stencils are computed in Real (80
// digits) by inverse subspace iteration from Eigen's double estimate, and the
// residual max |t A0 - lambda t| is reported.
#include <optional>
#include <string>
#include <vector>

#include "algebra/real.hpp"

namespace sg {

struct TangentStencils {
  Real eigenvalue;         // lambda, the subdominant eigenvalue of A0
  std::vector<Real> u, v;  // the two tangent stencils over the patch's points
  Real residual;           // max over both of |t A0 - lambda t| (the largest weight is 1)
};

// `a0`: dense, rows = the child's points, columns = the parent's (square).
// Nothing (with `why` set) when the subdominant eigenvalue is not a real double
// one with a gap below it, or the characteristic map vanishes at the ends.
std::optional<TangentStencils> tangent_stencils(const std::vector<std::vector<Real>>& a0, const std::vector<Real>& end_u,
                                                const std::vector<Real>& end_v, std::string& why);

}  // namespace sg
