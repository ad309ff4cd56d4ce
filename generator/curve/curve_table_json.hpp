#pragma once
#include <string>

#include "common/table_document.hpp"
#include "curve/curve_table.hpp"

namespace sg {

inline constexpr const char* kCurveTableFormat = "stencilgen-curve-table";
inline constexpr int kCurveTableVersion = 2;  // 2: derivatives

std::string curve_table_to_json(const CurveTable& table);
// Reads a table back; errors name `origin` (the file) and the JSON path of the
// field at fault. Rates above limits::kMaxCurveRate are refused.
CurveTable curve_table_from_json(const std::string& text, const std::string& origin);
CurveTable curve_table_from_document(const TableDocument& table);

}  // namespace sg
