#pragma once
// `stencilgen verify` for a quad scheme's descent.json: the patch subdivision
// matrices re-derived from the scheme must equal the stored ones exactly, and
// the tangent stencils at the vertex must satisfy their eigen-relation
// t A0 = lambda t with the file's own exact A0 (to 1e-30, as 40-digit
// decimals can) and equal freshly computed ones to 1e-35.
#include <string>
#include <vector>

#include "common/table_document.hpp"
#include "quad/quad_scheme.hpp"

namespace sg {

// The failures found (empty: verified). Throws sg::Error for a malformed file.
std::vector<std::string> verify_quad_descent(const TableDocument& table, const QuadScheme& scheme);

}  // namespace sg
