#include "family.hpp"

namespace stencil_runtime {

// What a family without derivatives (so far the triangle family) answers.
namespace {
[[noreturn]] void no_derivatives() {
  throw EvaluationError("derivatives are available for quad schemes only so far (not yet for triangle schemes)");
}
}  // namespace

Derivatives Family::derivatives(std::size_t, const ExactParameter&, const Point*) const { no_derivatives(); }
Derivatives Family::derivatives(std::size_t, double, double, const Point*) const { no_derivatives(); }
SecondDerivatives Family::second_derivatives(std::size_t, const ExactParameter&, const Point*) const { no_derivatives(); }
SecondDerivatives Family::second_derivatives(std::size_t, double, double, const Point*) const { no_derivatives(); }
void Family::normals(const TessellationLayout&, std::size_t, std::size_t, const Point*, std::array<float, 3>*) const {
  no_derivatives();
}

}  // namespace stencil_runtime
