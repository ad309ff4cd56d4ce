#pragma once
#include <string>
#include <vector>

#include "curve/curve_table.hpp"

namespace sg {

// Re-checks a table against the scheme it claims to come from, exactly:
// identity (name, hash, arity), every scaling relation at every grid point in
// and around each support, partition of unity at every residue and near the
// special point, and the mirror symmetry of a symmetric uniform mask.
// Returns one line per failure; empty means the table is correct.
std::vector<std::string> verify_curve_table(const CurveTable& table, const CurveScheme& scheme);

}  // namespace sg
