#pragma once
// A surface: a SurfaceTopology plus the control positions of one frame.
// set_positions() is the per-frame call (no topology work, and no allocation
// after the first call); evaluation reads the current positions. Several
// surfaces (e.g. several animated instances) can share one topology. Not safe
// to evaluate while another thread calls set_positions on the same surface.
#include <cstddef>
#include <memory>
#include <vector>

#include "derivatives.hpp"
#include "exact_parameter.hpp"
#include "mesh.hpp"
#include "surface_topology.hpp"

namespace stencil_runtime {

// A limit point and how far it may be from the exact one: bound == 0 (and
// exact) where the parameter is a rational the tables hold, directly or after
// local subdivision of the patch; otherwise the bound is at most the tolerance asked for.
struct Evaluation {
  Point point{0, 0, 0};
  double bound = 0;
  bool exact = true;
};

class Surface {
 public:
  explicit Surface(std::shared_ptr<const SurfaceTopology> topology);
  Surface(std::shared_ptr<const SurfaceTopology> topology, const std::vector<Point>& control);
  // Copies share the topology. A surface moved from keeps its topology and has
  // no positions (every request on it then says so) until set_positions.
  Surface(const Surface&) = default;
  Surface& operator=(const Surface&) = default;
  Surface(Surface&& other) noexcept;
  Surface& operator=(Surface&& other) noexcept;

  const SurfaceTopology& topology() const { return *topology_; }
  const std::shared_ptr<const SurfaceTopology>& shared_topology() const { return topology_; }

  // New control positions, one per control vertex: applies the refinement
  // matrix R once. Throws EvaluationError for a wrong count, a null `control`
  // or a coordinate that is not finite or exceeds limits::kMaxCoordinate
  // (naming the vertex); the positions before stay then.
  void set_positions(const std::vector<Point>& control);
  void set_positions(const Point* control, std::size_t count);
  bool has_positions() const { return has_positions_; }
  // R * control: the positions of the prepared mesh's vertices.
  const std::vector<Point>& prepared_positions() const { return prepared_; }
  // The diagonal of the bounding box of the control positions last set (0
  // without positions): what relative tolerances are fractions of. The
  // prepared positions can reach beyond it (a boundary's phantom points).
  double control_diagonal() const { return control_diagonal_; }
  // The prepared mesh itself (its faces are all quads or all triangles): the
  // same limit surface, described by more control points.
  Mesh prepared_mesh() const;

  // The limit point at an exact parameter of face `face` (domain(face) says
  // what (u, v) means). Exact (to double rounding) where a stored rate holds
  // the parameter (single-precision tables: to their weights' rounding, which
  // the overloads below report); throws EvaluationError naming the face, the parameter and
  // the stencilgen call that would add the rate otherwise.
  Point evaluate(std::size_t face, const ExactParameter& at) const;

  // The limit point at any parameter, exact where the tables hold it, directly
  // or after the scheme's own subdivision of the patch (every double is an
  // exact binary fraction, so for binary schemes most doubles are reached);
  // otherwise the descent stops once the reported bound is at most
  // `tolerance` (absolute; 0: as deep as doubles allow). Catmull-Clark's and
  // Loop's regular patches are polynomial: there the value at any parameter is
  // exact up to rounding. Throws EvaluationError for a face or parameter
  // outside the surface, a tolerance that is negative or not finite, or a
  // scheme whose tables give no rigorous bound there (docs/runtime.md).
  Evaluation evaluate(std::size_t face, const ExactParameter& at, double tolerance) const;
  Evaluation evaluate(std::size_t face, double u, double v, double tolerance) const;

  // The limit point and its first partial derivatives along the face's (u, v)
  // (for an N-gon's sub-faces, along the face's own (u, v): each sub-face's
  // coordinates are the tile's doubled). Computed by the scheme's own
  // subdivision of the patch down to a regular patch, exact to rounding: for
  // Catmull-Clark and Loop anywhere (polynomial regular patches); for a
  // non-polynomial quad scheme (nonpoly) anywhere too, its regular curve's
  // basis and derivative following the parameter's halvings to a stored grid
  // or round their cycle (curve_orbit.hpp); for sqrt(3) at exact rationals
  // whose descent reaches a stored grid (its tables' derivative stencils).
  // Throws EvaluationError at an extraordinary vertex (no parametric
  // derivative there), for sqrt(3) at other parameters, and for a face or
  // parameter outside the surface.
  Derivatives derivatives(std::size_t face, const ExactParameter& at) const;
  Derivatives derivatives(std::size_t face, double u, double v) const;
  // The unit normal (du x dv normalised, outward for counter-clockwise faces)
  // wherever derivatives() gives one, and also at an extraordinary vertex
  // (every scheme), where there is no parametric derivative: there it is
  // t_u.P x t_v.P from the tables' tangent stencils (left eigenvectors of the
  // patch's subdivision matrix for its subdominant eigenvalue). Throws
  // EvaluationError where derivatives() does otherwise.
  Point normal(std::size_t face, const ExactParameter& at) const;
  Point normal(std::size_t face, double u, double v) const;
  // With the second partial derivatives along (u, v) (duu, duv, dvv): for quad
  // schemes whose regular patches are polynomial (Catmull-Clark), anywhere but
  // an extraordinary vertex; elsewhere EvaluationError says why.
  SecondDerivatives second_derivatives(std::size_t face, const ExactParameter& at) const;
  SecondDerivatives second_derivatives(std::size_t face, double u, double v) const;

 private:
  std::shared_ptr<const SurfaceTopology> topology_;
  std::vector<Point> prepared_;
  std::vector<std::vector<Point>> levels_;  // intermediate refinement levels, kept for reuse
  bool has_positions_ = false;
  double control_diagonal_ = 0;
  double rounding_ = 0;  // single-precision tables: the bound their weights' rounding adds (2^-20 of the largest coordinate)
};

}  // namespace stencil_runtime
