#pragma once
#include <memory>
#include <string>
#include <vector>

#include "curve/curve_solution.hpp"
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
  std::vector<int> valences;
  std::vector<std::vector<QuadTable>> tables;  // [valence][rate]
};

enum class BinaryPrecision { Double = 8, Single = 4 };

// One stored scalar, float64 or float32 (the binary tables' weights).
void put_scalar(std::string& out, double value, BinaryPrecision precision);

// p/q in lowest terms, so that equal parameter points of different grids share one stored stencil.
std::pair<long, long> reduced_fraction(long p, long q);

// One .sgs file: the scheme's subdivision rules (double), regular curve values and, per valence, the stencils of all
// rates, each distinct parameter point stored once (docs/table-format.md).
std::string quad_tables_to_binary(const QuadScheme& scheme, const QuadTableSet& set, BinaryPrecision precision);

}  // namespace sg
