#pragma once
#include <memory>
#include <string>
#include <vector>

#include "common/table_encoding.hpp"
#include "curve/curve_solution.hpp"
#include "curve/curve_table.hpp"
#include "quad/quad_scheme.hpp"
#include "quad/quad_table.hpp"

namespace sg {

struct QuadDescent;

// Everything `stencilgen --scheme Q --valence ... --n ...` produced.
struct QuadTableSet {
  // The scheme's own subdivision of a patch, for evaluation at any parameter
  // (shared, so that this header need not see the patch matrices' types).
  std::shared_ptr<const QuadDescent> descent;
  std::vector<long> rates;
  std::vector<CurveSolution> regular;             // per rate n: the curve on the grid 2n
  std::vector<CurveTable> regular_tables;         // the same as tables, with phi' where the curve is C1
  std::vector<int> valences;
  std::vector<std::vector<QuadTable>> tables;  // [valence][rate]
};

// One .sgs file: the scheme's subdivision rules (double), regular curve values and, per valence, the stencils of all
// rates, each distinct parameter point stored once (docs/table-format.md).
std::string quad_tables_to_binary(const QuadScheme& scheme, const QuadTableSet& set, BinaryPrecision precision);

}  // namespace sg
