#pragma once
// One quad scheme, one valence, one rate n: the exact stencils of the
// extraordinary patch at the grid nodes (i/n, j/n) and the cell centres
// ((2i+1)/(2n), (2j+1)/(2n)) that the watertight tessellation samples. Only
// i <= j is stored; the reflection (x,y) -> (y,x) gives the rest (see
// PatchLayout::reflection). Serialised as exact JSON (quad_table_json) and,
// all valences and rates of a scheme together, as compact binary
// (quad_table_binary); see docs/table-format.md.
#include <map>
#include <string>
#include <vector>

#include "algebra/scaled_vector.hpp"
#include "quad/ev_patch_solver.hpp"
#include "quad/quad_scheme.hpp"

namespace sg {

struct QuadTable {
  struct Entry {
    long i = 0, j = 0;  // i <= j
    ScaledVector weights;
  };
  std::string scheme, scheme_hash;
  Bindings parameters;
  int valence = 4;
  long n = 1;
  std::size_t points = 0;
  std::vector<std::size_t> reflection;
  // The scheme's subdivision rules (valence 4 and this table's valence), so
  // that a reader of the JSON alone can refine a mesh with the scheme's step.
  struct Rules {
    Rational face_corner, edge_end, edge_wing;
    std::map<int, VertexRule> vertex;
    bool polygon = false;  // the polygon rules (quad_scheme.hpp), when the scheme has them
    Rational polygon_edge_end, polygon_edge_face;
    std::map<int, QuadScheme::PolygonVertexRule> polygon_vertex;
  } rules;
  std::vector<Entry> nodes;    // j-major: j = 0..n, i = 0..j
  std::vector<Entry> centres;  // j-major: j = 0..n-1, i = 0..j
};

// `patch` must be solved on the grid 2n.
QuadTable make_quad_table(const QuadScheme& scheme, const PatchGrid& patch);

// Exact re-checks of a table: partition of unity at every stored point and
// agreement of the reflection with the stored half at the diagonal. Returns
// failure descriptions (empty when all hold).
std::vector<std::string> check_quad_table(const QuadTable& table);

}  // namespace sg
