#pragma once
#include <string>
#include <vector>

#include "common/table_document.hpp"
#include "quad/quad_scheme.hpp"

namespace sg {

// Re-solves the patch of a quad table (JSON) and compares every stored
// stencil exactly; also checks partition of unity, the scheme hash and the
// reflection. Returns failure descriptions (empty when the table is right).
// Throws sg::Error naming the file and field when the table is malformed, or
// when its valence or rate is outside the limits (checked before solving).
std::vector<std::string> verify_quad_table(const TableDocument& table, const QuadScheme& scheme);

}  // namespace sg
