#pragma once
// One triangle scheme, one valence, one rate n: the stencils of the patch
// around an extraordinary vertex (triangle_patch.hpp) at the grid nodes
// (i/n, j/n), i + j <= n, and at the centres of the grid's small triangles that
// the watertight tessellation samples: "up" triangles ((3i+1)/(3n), (3j+1)/(3n)),
// i + j <= n-1, and "down" triangles ((3i+2)/(3n), (3j+2)/(3n)), i + j <= n-2.
// Stencils refer to the sector-chart points listed in `layout` (those some
// stencil of the table uses). For sqrt(3) at valences other than 6 the table
// also holds the three "band" regions of the EV's second ring
// (triangle_patch.hpp), each on the same grid and with its own layout. Exact (integer numerators over one denominator)
// where the scheme's weights are rational at this valence, else high precision
// (Real) with the largest residual recorded. docs/table-format.md.
#include <string>
#include <vector>

#include "algebra/scaled_vector.hpp"
#include "triangle/sector_chart.hpp"
#include "triangle/triangle_patch.hpp"

namespace sg {

struct TriangleTable {
  struct Entry {
    long i = 0, j = 0;
    ScaledVector exact;        // when the table is exact
    std::vector<Real> approx;  // otherwise
    ScaledVector du, dv;       // the regular table's derivative stencils (when `derivatives`), exact
  };
  std::string scheme, scheme_hash, refinement;
  Bindings parameters;
  int valence = 6;
  long n = 1;
  bool exact = true;
  Real residual = 0;  // max of the eigenvector and partition-of-unity residuals
  bool derivatives = false;  // the regular table (valence 6): entries carry d/du and d/dv stencils
  struct Region {
    int index = 0;  // 0: the patch; 1..3: the band (triangle_patch.hpp)
    std::vector<SectorPoint> layout;
    std::vector<Entry> nodes, up, down;  // j-major
  };
  std::vector<Region> regions;  // [0] is the patch
  struct Rules {
    std::string edge_end, edge_opposite;  // Loop only
    std::string neighbour_regular, neighbour;  // w(6) and w(valence), exact or 40 digits
    std::string crease_curve, crease_centre, crease_neighbour;  // empty without a crease rule
  } rules;
};

// Digits written for high-precision values (the solve carries kRealDigits).
inline constexpr int kTableDigits = 40;

// `patch` solved on the grid 3n.
template <class T>
TriangleTable make_triangle_table(const TriangleScheme& scheme, const TrianglePatch<T>& patch, long n);

// The table of one valence and rate, solved exactly where the scheme's weights
// are rational at the valence and in high precision otherwise. With
// `gradient` (the regular basis's partials on the grid 3n), the regular
// table (valence 6) also holds derivative stencils.
TriangleTable solve_triangle_table(const TriangleScheme& scheme, int valence, long n, const BivariateSolution& regular,
                                   const BivariateGradient* gradient = nullptr);

std::string triangle_table_to_json(const TriangleTable& table);

inline constexpr const char* kTriangleTableFormat = "stencilgen-triangle-table";
inline constexpr int kTriangleTableVersion = 3;  // 2: band regions; 3: du, dv in the regular table

}  // namespace sg
