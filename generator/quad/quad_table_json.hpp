#pragma once
#include <string>

#include "quad/quad_table.hpp"

namespace sg {

inline constexpr const char* kQuadTableFormat = "stencilgen-surface-table";
inline constexpr int kQuadTableVersion = 1;

// Exact JSON, one stencil per line (docs/table-format.md).
std::string quad_table_to_json(const QuadTable& table);

}  // namespace sg
