#include "family.hpp"

#include <string>

namespace stencil_runtime {

// What a family without these derivatives (so far the triangle family, for
// all but Loop's first derivatives) answers.
namespace {
[[noreturn]] void no_derivatives(const char* what) {
  throw EvaluationError(std::string(what) + " are available for quad schemes only so far (not yet for triangle schemes)");
}
}  // namespace

Derivatives Family::derivatives(std::size_t, const ExactParameter&, const Point*) const { no_derivatives("derivatives"); }
Derivatives Family::derivatives(std::size_t, double, double, const Point*) const { no_derivatives("derivatives"); }
SecondDerivatives Family::second_derivatives(std::size_t, const ExactParameter&, const Point*) const {
  no_derivatives("second derivatives");
}
SecondDerivatives Family::second_derivatives(std::size_t, double, double, const Point*) const {
  no_derivatives("second derivatives");
}
void Family::normals(const TessellationLayout&, std::size_t, std::size_t, const Point*, std::array<float, 3>*) const {
  no_derivatives("tessellation normals");
}

}  // namespace stencil_runtime
