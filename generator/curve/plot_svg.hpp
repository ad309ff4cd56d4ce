#pragma once
#include <string>

#include "curve/curve_table.hpp"

namespace sg {

// An SVG drawing of every scaling function of a table (the paper's Figure 2):
// one coloured polyline per function through its exact grid values, in global
// coordinates (each non-uniform type at the control point it is placed at,
// i.e. its column or the innermost column of its uniform side; uniform at 0).
std::string plot_table_svg(const CurveTable& table);

}  // namespace sg
