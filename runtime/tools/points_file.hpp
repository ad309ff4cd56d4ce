#pragma once
// Points for stencildist and stencilfit: a text file of `x y z` lines (.xyz, .txt; '#'
// starts a comment, blank lines are skipped) or a PLY file (ASCII or binary,
// little- or big-endian) whose first element is `vertex` with float or double
// properties x, y, z, or an OFF file's vertices (its faces are not read).
// Every coordinate must be finite and at most limits::kMaxCoordinate in
// magnitude; errors name the file and the line (or the point, in a binary file).
#include <string>
#include <vector>

#include "stencil_runtime/mesh.hpp"

namespace stencil_tools {

std::vector<stencil_runtime::Point> read_points(const std::string& path);

}  // namespace stencil_tools
