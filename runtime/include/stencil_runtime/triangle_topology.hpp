#pragma once
// Topology of a closed manifold triangle mesh: half-edge h = 3 * face + corner.
#include "uniform_topology.hpp"

namespace stencil_runtime {

using TriangleTopology = UniformTopology<3>;

}  // namespace stencil_runtime
