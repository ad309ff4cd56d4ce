#pragma once
// Topology of a closed manifold quad mesh: half-edge h = 4 * face + corner.
#include "uniform_topology.hpp"

namespace stencil_runtime {

using QuadTopology = UniformTopology<4>;

}  // namespace stencil_runtime
