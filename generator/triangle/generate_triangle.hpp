#pragma once
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "triangle/triangle_table_binary.hpp"

namespace sg {

// Solves every (valence, rate) pair in parallel (the patch on the grid 3n, so
// that nodes and both kinds of triangle centres come out together): exactly
// where the scheme's weights are rational at the valence, in high precision
// otherwise. Throws sg::Error on the first failure; `progress` gets a line per
// finished valence (with its largest residual when not exact).
TriangleTableSet generate_triangle_tables(const TriangleScheme& scheme, const std::vector<int>& valences,
                                          const std::vector<long>& rates,
                                          const std::function<void(const std::string&)>& progress = {});

// Writes, all or nothing, into OUT/<scheme>/: v<V>/n<N>.json and <scheme>.sgt.
// Returns the size of the binary file in bytes.
std::size_t write_triangle_tables(const TriangleScheme& scheme, const TriangleTableSet& set,
                                  const std::filesystem::path& out_dir, BinaryPrecision precision,
                                  const std::function<void(const std::string&)>& progress = {});

}  // namespace sg
