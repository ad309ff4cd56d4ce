#pragma once
// A fit's convergence as an SVG chart: RMS and max error (fractions of the
// diagonal, log scale) against the iteration.
#include <string>
#include <vector>

#include "stencil_runtime/surface_fit.hpp"

namespace stencil_tools {

std::string convergence_svg(const std::vector<stencil_runtime::FitIteration>& history, const std::string& title);

}  // namespace stencil_tools
