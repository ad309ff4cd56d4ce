#pragma once
// The patch subdivision of a quad scheme (quad_descent.hpp) as exact JSON:
// OUT/<scheme>/descent.json beside the exact tables, so that a directory of
// JSON tables alone evaluates at any parameter too (docs/table-format.md).
#include <string>

#include "quad/quad_descent.hpp"
#include "quad/quad_descent_format.hpp"

namespace sg {

std::string quad_descent_to_json(const QuadScheme& scheme, const QuadDescent& descent);

}  // namespace sg
