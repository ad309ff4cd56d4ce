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
  Real second_eigenvalue;  // the other one of the pair (equal to lambda for a double eigenvalue)
  std::vector<Real> u, v;  // the two tangent stencils over the patch's points
  Real residual;           // max over both of |t A0 - lambda t| (the largest weight is 1); for two distinct
                           // eigenvalues, over the two eigenvectors l (|l A0 - lambda_l l|, largest weight 1)
};

// `a0`: dense, rows = the child's points, columns = the parent's (square).
// Nothing (with `why` set) when the subdominant eigenvalue is not a real double
// one with a gap below it, or the characteristic map vanishes at the ends.
std::optional<TangentStencils> tangent_stencils(const std::vector<std::vector<Real>>& a0, const std::vector<Real>& end_u,
                                                const std::vector<Real>& end_v, std::string& why);

// A vertex on a boundary has no rotational symmetry: its two largest
// eigenvalues below 1 may differ (one of them the boundary curve's, 1/2). The
// tangent plane is then spanned by the two left eigenvectors l_1, l_2 when both
// eigenvalues are real with a gap below them and `boundary_tangent` (the
// boundary curve's tangent stencil at the vertex) lies in their span: then
// near the vertex f(x) = l0.P + lambda_1^k c_1(x) l_1.P + lambda_2^k c_2(x) l_2.P
// + o(lambda_2^k) from inside and along the boundary alike. Where it does not
// lie in their span the surface approaches the vertex along other directions
// from inside than along its boundary: there is no tangent plane (not C1).
// end_u, end_v: value stencils at two points of the patch whose images under
// the characteristic map turn counter-clockwise by less than pi (the far end of
// the u edge and the opposite corner), so that t_u.P x t_v.P points as du x dv.
// `grid`: the value stencils at the nodes (i/g, j/g) of the patch, j-major: the
// characteristic map c = W R sampled there must be regular (every cell turned
// the same way), else its two components do not span the tangent plane (one
// may be a function of the other, as for an eigenvalue that is the square of
// the other one). An empty `boundary_tangent` asks for no such containment (a
// vertex with no boundary through it: a dart, whose slit is folded shut).
std::optional<TangentStencils> boundary_tangent_stencils(const std::vector<std::vector<Real>>& a0,
                                                         const std::vector<Real>& end_u, const std::vector<Real>& end_v,
                                                         const std::vector<Real>& boundary_tangent,
                                                         const std::vector<std::vector<double>>& grid, long g,
                                                         std::string& why);
// The same with the samples at any points of the patch and its cells given as
// polygons of sample indices, counter-clockwise in (u, v) (a triangle patch's
// grid triangles).
std::optional<TangentStencils> boundary_tangent_stencils(const std::vector<std::vector<Real>>& a0,
                                                         const std::vector<Real>& end_u, const std::vector<Real>& end_v,
                                                         const std::vector<Real>& boundary_tangent,
                                                         const std::vector<std::vector<double>>& samples,
                                                         const std::vector<std::vector<std::size_t>>& cells,
                                                         std::string& why);

}  // namespace sg
