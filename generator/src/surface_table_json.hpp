#pragma once
#include <string>

#include "surface_table.hpp"

namespace sg {

inline constexpr const char* kSurfaceTableFormat = "stencilgen-surface-table";
inline constexpr int kSurfaceTableVersion = 1;

// Exact JSON, one stencil per line (docs/table-format.md).
std::string surface_table_to_json(const SurfaceTable& table);

}  // namespace sg
