#pragma once
#include <functional>
#include <string>
#include <vector>

#include "common/table_encoding.hpp"
#include "triangle/triangle_table.hpp"

namespace sg {

struct TriangleSectorSet;

// Everything `stencilgen --scheme loop|sqrt3 --valence ... --n ...` produced.
struct TriangleTableSet {
  std::vector<long> rates;
  std::vector<int> valences;
  std::vector<std::vector<TriangleTable>> tables;  // [valence][rate]
};

// One .sgt file: the scheme's rules, and per valence (6 included: regular
// triangles use it) the layout and the stencils of all rates, each distinct
// parameter point stored once (docs/table-format.md). `sectors_out`: where
// to keep the sectors solved for it (for sectors.json).
// Valence 6's points as the binary lists them (the union of its layouts over
// the set's rates, in chart order): what Loop's sectors' regular cells run over.
std::vector<SectorPoint> regular_points(const TriangleScheme& scheme, const TriangleTableSet& set);

std::string triangle_tables_to_binary(const TriangleScheme& scheme, const TriangleTableSet& set, BinaryPrecision precision,
                                      TriangleSectorSet* sectors_out = nullptr,
                                      const std::function<void(const std::string&)>& progress = {});

}  // namespace sg
