#pragma once
#include <string>

#include "curve/curve_table.hpp"

namespace sg {

// Compact binary form (float64, little-endian) for the runtime: per function a
// dense run of values from its first to its last nonzero grid point.
std::string curve_table_to_binary(const CurveTable& table, std::uint64_t scheme_hash);

}  // namespace sg
