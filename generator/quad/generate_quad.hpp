#pragma once
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "quad/quad_scheme.hpp"
#include "quad/quad_table_binary.hpp"

namespace sg {

// Solves every (valence, rate) pair in parallel (the patch on the grid 2n, so
// that nodes and cell centres come out together), checks each table exactly,
// and returns them. Throws sg::Error on the first failure; `progress` gets a
// line per finished valence.
QuadTableSet generate_quad_tables(const QuadScheme& scheme, const std::vector<int>& valences,
                                        const std::vector<long>& rates,
                                        const std::function<void(const std::string&)>& progress = {});

// Writes, all or nothing, into OUT/<scheme>/: v<V>/n<N>.json (exact),
// regular/n<2N>.json (the curve on the grid 2n, exact) and <scheme>.sgs (binary).
// Returns the size of the binary file in bytes.
std::size_t write_quad_tables(const QuadScheme& scheme, const QuadTableSet& set, const std::filesystem::path& out_dir,
                              BinaryPrecision precision, BinaryLayout layout = BinaryLayout::Generated);

}  // namespace sg
