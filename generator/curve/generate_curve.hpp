#pragma once
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "curve/curve_table.hpp"

namespace sg {

enum class RouteChoice { Residue, Eigen, Both };

// Solves every rate (in parallel), cross-checks the two routes when asked,
// verifies each table exactly, and returns them in rate order. Throws sg::Error
// on the first failure; `progress` receives one line per finished rate.
std::vector<CurveTable> generate_curve_tables(const CurveScheme& scheme, const std::vector<long>& rates,
                                              RouteChoice routes,
                                              const std::function<void(const std::string&)>& progress = {});

// Writes OUT/<scheme>/n<N>.json and n<N>.sgc for every table, all or nothing.
void write_curve_tables(const CurveScheme& scheme, const std::vector<CurveTable>& tables,
                        const std::filesystem::path& out_dir);

}  // namespace sg
