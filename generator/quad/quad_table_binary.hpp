#pragma once
#include <string>
#include <vector>

#include "common/table_encoding.hpp"
#include "curve/curve_solution.hpp"
#include "quad/quad_scheme.hpp"
#include "quad/quad_table.hpp"

namespace sg {

// Everything `stencilgen --scheme Q --valence ... --n ...` produced.
struct QuadTableSet {
  std::vector<long> rates;
  std::vector<CurveSolution> regular;             // per rate n: the curve on the grid 2n
  std::vector<int> valences;
  std::vector<std::vector<QuadTable>> tables;  // [valence][rate]
};

// One .sgs file: the scheme's subdivision rules (double), regular curve values and, per valence, the stencils of all
// rates, each distinct parameter point stored once (docs/table-format.md).
std::string quad_tables_to_binary(const QuadScheme& scheme, const QuadTableSet& set, BinaryPrecision precision);

}  // namespace sg
