#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "quad/quad_table.hpp"

namespace sg {

inline constexpr const char* kQuadTableFormat = "stencilgen-surface-table";
inline constexpr int kQuadTableVersion = 1;

// One exact stencil entry of a table file: {"at": [x, y], "denominator", "numerators"}
// (the quad and the exact triangle tables share it).
nlohmann::ordered_json exact_entry_json(const ScaledVector& w, const Rational& x, const Rational& y);

// Exact JSON, one stencil per line (docs/table-format.md).
std::string quad_table_to_json(const QuadTable& table);

}  // namespace sg

namespace sg {

// Re-solves the patch of a quad table (JSON) and compares every stored
// stencil exactly; also checks partition of unity, the scheme hash and the
// reflection. Returns failure descriptions (empty when the table is right).
std::vector<std::string> verify_quad_table_json(const std::string& text, const std::string& origin,
                                             const QuadScheme& scheme);

// The "format" field of a table file, or "" when it has none.
std::string table_format(const std::string& text);

}  // namespace sg
