#pragma once
#include <string>
#include <vector>

#include "quad/quad_scheme.hpp"

namespace sg {

// Re-solves the patch of a quad table (JSON) and compares every stored
// stencil exactly; also checks partition of unity, the scheme hash and the
// reflection. Returns failure descriptions (empty when the table is right).
std::vector<std::string> verify_quad_table_json(const std::string& text, const std::string& origin,
                                                const QuadScheme& scheme);

}  // namespace sg
