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

}  // namespace stencil_runtime
