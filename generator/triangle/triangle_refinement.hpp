#pragma once
// The local subdivision matrix of a triangle scheme around an extraordinary
// vertex, on a sector chart (sector_chart.hpp): row p expresses the refined
// point p (same chart, on the lattice refined by the dilation m) in the coarse
// points. Loop: one step (m = 2). sqrt(3): two steps composed (m = 3), the
// intermediate rotated lattice expressed in thirds of the coarse lattice.
// Written once in lattice coordinates; the sector chart carries every lattice
// move to the right sector, whatever the valence.
#include <utility>
#include <vector>

#include "triangle/sector_chart.hpp"
#include "triangle/triangle_scheme.hpp"

namespace sg {

template <class T>
using SparseRow = std::vector<std::pair<std::size_t, T>>;

// The refined point p (fine lattice units, sector p.sector's frame) in the
// coarse points. Throws sg::Error when it needs a coarse point beyond the chart's rings.
template <class T>
SparseRow<T> refined_point(TriangleRefinement refinement, const SectorChart& chart, const TriangleWeights<T>& weights,
                           const SectorPoint& p);

// One row per chart point (chart.size() rows). Throws sg::Error when a row
// needs a coarse point beyond the chart's rings.
template <class T>
std::vector<SparseRow<T>> refinement_matrix(TriangleRefinement refinement, const SectorChart& chart,
                                            const TriangleWeights<T>& weights);

}  // namespace sg
