#pragma once
// The weights of the limit point at an exact parameter of an original face over
// the prepared vertices, checked: EvaluationError for a face that does not
// exist, a parameter outside its domain, or one no stored rate holds (saying
// which rate would).
#include "family/family.hpp"
#include "stencil_runtime/surface_topology.hpp"

namespace stencil_runtime {

PatchStencil exact_stencil(const SurfaceTopology& topology, std::size_t face, const ExactParameter& at);

}  // namespace stencil_runtime
