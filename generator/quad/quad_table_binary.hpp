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

// How the extraordinary patches' stencils go into the .sgs file. Generated:
// only what generates them (the patch subdivision is always there; the limit
// stencil is added), for the runtime to expand at load time; a set whose
// expansion would exceed the runtime's limits (binary_format.hpp) is stored
// instead. Stored: every stencil, each distinct parameter point once.
enum class BinaryLayout { Generated, Stored };

// True when the runtime can expand this set's stencils at load time within its limits.
bool generated_layout_fits(const QuadTableSet& set);

// One .sgs file: the scheme's subdivision rules (double), regular curve values and, per valence, the patch subdivision
// and either the stencils of all rates or the limit stencil that generates them with it (docs/table-format.md).
std::string quad_tables_to_binary(const QuadScheme& scheme, const QuadTableSet& set, BinaryPrecision precision,
                                  BinaryLayout layout = BinaryLayout::Generated);

}  // namespace sg
