#pragma once
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "base/limits.hpp"
#include "curve/curve_table.hpp"

namespace sg {

enum class RouteChoice { Residue, Eigen, Both };

// Solves every rate (in parallel, largest first), cross-checks the two routes
// when asked, verifies each table exactly, and returns them in rate order.
// Throws sg::Error on the first failure, and once the tables made hold more
// than `max_digits` decimal digits of exact numbers (exact_digits; the limit
// is a parameter for tests); `progress` receives one line per finished rate.
std::vector<CurveTable> generate_curve_tables(const CurveScheme& scheme, const std::vector<long>& rates,
                                              RouteChoice routes,
                                              const std::function<void(const std::string&)>& progress = {},
                                              std::uint64_t max_digits = limits::kMaxCurveRunDigits);

// Writes OUT/<scheme>/n<N>.json and n<N>.sgc for every table, all or nothing.
void write_curve_tables(const CurveScheme& scheme, const std::vector<CurveTable>& tables,
                        const std::filesystem::path& out_dir);

}  // namespace sg
