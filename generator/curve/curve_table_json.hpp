#pragma once
#include <string>

#include "curve/curve_table.hpp"

namespace sg {

inline constexpr const char* kCurveTableFormat = "stencilgen-curve-table";
inline constexpr int kCurveTableVersion = 1;

std::string curve_table_to_json(const CurveTable& table);
// `origin` names the file in error messages.
CurveTable curve_table_from_json(const std::string& text, const std::string& origin);

}  // namespace sg
