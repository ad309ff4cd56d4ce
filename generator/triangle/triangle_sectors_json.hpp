#pragma once
// Loop's boundary, dart and cone sectors (triangle_sector.hpp) as exact
// JSON: OUT/<scheme>/sectors.json beside the exact tables, what the binary
// .sgt holds of them rounded to doubles (docs/table-format.md, "Loop sectors
// as exact JSON"). Exact rationals where the sector's rules are rational, 40
// significant digits of the 80-digit solve where they are not (a dart at a
// valence where Loop's smooth rule is irrational), with the residual.
#include <functional>
#include <string>
#include <vector>

#include "common/table_document.hpp"
#include "triangle/sector_chart.hpp"
#include "triangle/triangle_scheme.hpp"
#include "triangle/triangle_sector.hpp"

namespace sg {

inline constexpr const char* kTriangleSectorsFormat = "stencilgen-triangle-sectors";
inline constexpr int kTriangleSectorsVersion = 1;

struct TriangleSectorSet {
  int max_faces = 0;                        // every sector of triangle_sectors(max_faces, true)
  std::vector<SectorPoint> regular_layout;  // valence 6's points as the binary tables list them (the regular cells' rows)
  std::vector<TriangleSectorDescent> sectors;
};

// Solved in parallel; empty for sqrt(3) or a scheme without a crease curve.
// `progress`, when given, hears of every tenth of the sectors (up to 64 faces
// they are thousands, minutes of work).
TriangleSectorSet solve_triangle_sectors(const TriangleScheme& scheme, int max_faces, const std::vector<SectorPoint>& regular_layout,
                                         const std::function<void(const std::string&)>& progress = {});

std::string triangle_sectors_to_json(const TriangleScheme& scheme, const TriangleSectorSet& set);

// `stencilgen verify` of a sectors.json: re-solves every sector from the
// scheme (with the file's regular layout) and compares the documents as
// values (naming the first field that differs), and, where exact, checks from
// the file's own rationals that each limit stencil sums to 1 and is A0's fixed
// point. The failures, empty when it passes.
std::vector<std::string> verify_triangle_sectors(const TableDocument& table, const TriangleScheme& scheme);

}  // namespace sg
