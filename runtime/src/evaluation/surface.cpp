#include "stencil_runtime/surface.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>
#include <utility>

#include "exact_stencil.hpp"
#include "family/family.hpp"
#include "family/stencil_sum.hpp"
#include "mesh/coordinates.hpp"
#include "stencil_runtime/limits.hpp"

namespace stencil_runtime {

Surface::Surface(std::shared_ptr<const SurfaceTopology> topology) : topology_(std::move(topology)) {
  if (!topology_) throw EvaluationError("a Surface needs a topology");
}

Surface::Surface(std::shared_ptr<const SurfaceTopology> topology, const std::vector<Point>& control)
    : Surface(std::move(topology)) {
  set_positions(control);
}

// The topology is shared, not moved: a surface moved from stays usable, without positions.
Surface::Surface(Surface&& other) noexcept
    : topology_(other.topology_), prepared_(std::move(other.prepared_)), levels_(std::move(other.levels_)),
      has_positions_(std::exchange(other.has_positions_, false)), control_diagonal_(std::exchange(other.control_diagonal_, 0.0)),
      rounding_(other.rounding_) {}

Surface& Surface::operator=(Surface&& other) noexcept {
  if (this != &other) {
    topology_ = other.topology_;
    prepared_ = std::move(other.prepared_);
    levels_ = std::move(other.levels_);
    has_positions_ = std::exchange(other.has_positions_, false);
    control_diagonal_ = std::exchange(other.control_diagonal_, 0.0);
    rounding_ = other.rounding_;
    other.prepared_.clear();
  }
  return *this;
}

void Surface::set_positions(const std::vector<Point>& control) { set_positions(control.data(), control.size()); }

void Surface::set_positions(const Point* control, std::size_t count) {
  if (!control) throw EvaluationError("set_positions: the control positions are a null pointer");
  if (count != topology_->vertex_count())
    throw EvaluationError(std::to_string(count) + " control positions for a mesh of " +
                          std::to_string(topology_->vertex_count()) + " vertices");
  if (const std::string fault = coordinate_fault(control, count); !fault.empty()) throw EvaluationError(fault);
  topology_->family().refinement().apply(control, levels_, prepared_);
  control_diagonal_ = box_diagonal(control, count);
  rounding_ = 0;
  if (topology_->tables().single_precision())
    for (const Point& p : prepared_)
      for (double x : p) rounding_ = std::max(rounding_, std::ldexp(std::fabs(x), -20));
  has_positions_ = true;
}

Mesh Surface::prepared_mesh() const {
  if (!has_positions_) throw EvaluationError("the surface has no control positions yet (set_positions)");
  const Connectivity& c = topology_->family().prepared();
  Mesh out;
  out.positions = prepared_;
  out.face_sizes = c.face_sizes;
  out.face_vertices = c.face_vertices;
  return out;
}

Point Surface::evaluate(std::size_t face, const ExactParameter& at) const {
  if (!has_positions_) throw EvaluationError("the surface has no control positions yet (set_positions)");
  const PatchStencil s = exact_stencil(*topology_, face, at);
  return stencil_sum(s.weights, s.points, s.size, prepared_.data());
}

}  // namespace stencil_runtime

namespace stencil_runtime {

namespace {

void check_request(const Surface& s, double tolerance) {
  if (!s.has_positions()) throw EvaluationError("the surface has no control positions yet (set_positions)");
  if (!(tolerance >= 0) || !std::isfinite(tolerance))
    throw EvaluationError("the tolerance must be a finite number >= 0, got " + number_text(tolerance));
}

// `rounding`: what single-precision tables' weights add to the bound (0 for doubles).
Evaluation checked(const Approximation& a, double rounding) {
  for (double x : a.point)
    if (!std::isfinite(x)) throw EvaluationError("the limit point is not finite (coordinates too large)");
  if (rounding > 0) return {a.point, std::max(a.bound, rounding), false};
  return {a.point, a.bound, a.exact};
}

}  // namespace

Evaluation Surface::evaluate(std::size_t face, const ExactParameter& at, double tolerance) const {
  check_request(*this, tolerance);
  const FaceDomain domain = topology_->domain(face);
  if (!domain.contains(at))
    throw EvaluationError(domain.outside(face, at));
  return checked(topology_->family().evaluate(face, at, tolerance, prepared_.data()), rounding_);
}

Evaluation Surface::evaluate(std::size_t face, double u, double v, double tolerance) const {
  check_request(*this, tolerance);
  const FaceDomain domain = topology_->domain(face);
  if (!domain.contains(u, v))
    throw EvaluationError(domain.outside(face, u, v));
  return checked(topology_->family().evaluate(face, u, v, tolerance, prepared_.data()), rounding_);
}

}  // namespace stencil_runtime

namespace stencil_runtime {

namespace {

template <class D>
const D& checked(const D& d) {
  for (const Point* p : {&d.point, &d.du, &d.dv})
    for (double x : *p)
      if (!std::isfinite(x)) throw EvaluationError("the limit point or a derivative is not finite (coordinates too large)");
  if constexpr (std::is_same_v<D, SecondDerivatives>)
    for (const Point* p : {&d.duu, &d.duv, &d.dvv})
      for (double x : *p)
        if (!std::isfinite(x)) throw EvaluationError("a second derivative is not finite (coordinates too large)");
  return d;
}

// A derivative request's face and parameter, checked.
void check_inside(const Surface& surface, std::size_t face, const ExactParameter& at) {
  check_request(surface, 0);
  const FaceDomain domain = surface.topology().domain(face);
  if (!domain.contains(at))
    throw EvaluationError(domain.outside(face, at));
}
void check_inside(const Surface& surface, std::size_t face, double u, double v) {
  check_request(surface, 0);
  const FaceDomain domain = surface.topology().domain(face);
  if (!domain.contains(u, v))
    throw EvaluationError(domain.outside(face, u, v));
}

}  // namespace

Derivatives Surface::derivatives(std::size_t face, const ExactParameter& at) const {
  check_inside(*this, face, at);
  return checked(topology_->family().derivatives(face, at, prepared_.data()));
}

Derivatives Surface::derivatives(std::size_t face, double u, double v) const {
  check_inside(*this, face, u, v);
  return checked(topology_->family().derivatives(face, u, v, prepared_.data()));
}

namespace {
Point checked_normal(const Point& n) {
  for (double x : n)
    if (!std::isfinite(x)) throw EvaluationError("the normal is not finite (coordinates too large)");
  return n;
}
}  // namespace

Point Surface::normal(std::size_t face, const ExactParameter& at) const {
  check_inside(*this, face, at);
  return checked_normal(topology_->family().normal(face, at, prepared_.data()));
}

Point Surface::normal(std::size_t face, double u, double v) const {
  check_inside(*this, face, u, v);
  return checked_normal(topology_->family().normal(face, u, v, prepared_.data()));
}

SecondDerivatives Surface::second_derivatives(std::size_t face, const ExactParameter& at) const {
  check_inside(*this, face, at);
  return checked(topology_->family().second_derivatives(face, at, prepared_.data()));
}

SecondDerivatives Surface::second_derivatives(std::size_t face, double u, double v) const {
  check_inside(*this, face, u, v);
  return checked(topology_->family().second_derivatives(face, u, v, prepared_.data()));
}

}  // namespace stencil_runtime
