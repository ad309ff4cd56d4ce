#pragma once
// A face at a vertex on the mesh's boundary, as a patch of its own: the
// vertex B in k faces (its "sector"), the face at position p among them.
//
// Around B the faces are (B, e_j, f_j, e_{j+1}), j = 0..k-1, counter-clockwise;
// B-e_0 and B-e_k are the boundary edges. The patch of face p has B at (0,0),
// u along B->e_p and v along B->e_{p+1}. Its chart (as a regular grid):
//   (1,0) = e_p, (1,1) = f_p, (0,1) = e_{p+1},
//   (-1,1) = f_{p+1}, (-1,0) = e_{p+2}  when p + 1 < k,
//   (0,-1) = e_{p-1}, (1,-1) = f_{p-1}  when p > 0,
//   the outer points (2,-1) [p > 0], (2,0), (2,1), (2,2), (1,2), (0,2), (-1,2) [p < k-1].
// When p = 0 the chart's row j = 0 (i >= 0) is on the boundary and nothing lies
// below it; when p = k-1 its column i = 0 (j >= 0) likewise.
//
// Canonical order: 0 = B; 1 + j = e_j (j = 0..k); k + 2 + j = f_j (j = 0..k-1);
// then the outer points that exist, in the order above (docs/table-format.md).
//
// The rules: the scheme's own inside; along the boundary its regular curve with
// the boundary point held (vertex rule a, 1-2a, a along the boundary; edge rule
// 1/2, 1/2), as in OpenSubdiv; B itself follows the curve's vertex rule over
// e_0 and e_k ("crease"), stays where it is ("corner"), or follows the smooth
// rule ("dart", below).
//
// A cone point (an infinitely sharp vertex inside the mesh on no infinitely
// sharp edge: OpenSubdiv's corner rule with smooth edges round it) is kept
// here too, though its ring is closed: its patch is the interior patch of
// patch_layout.hpp (2v+8 points, that order) with the vertex held in place,
// the same for every face round it, so only position 0 is stored.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/sector_kind.hpp"
#include "quad/quad_scheme.hpp"

namespace sg {

struct PatchSubdivision;  // patch_subdivision.hpp

// The layout of the sectors with a boundary (not a cone's: patch_layout.hpp).
class SectorLayout {
 public:
  explicit SectorLayout(const BoundarySector& s);
  const BoundarySector& sector() const { return s_; }
  std::size_t size() const { return size_; }
  static std::size_t vertex() { return 0; }
  std::size_t edge(int j) const { return static_cast<std::size_t>(1 + j); }                // e_j, j = 0..k
  std::size_t face(int j) const { return static_cast<std::size_t>(s_.faces + 2 + j); }     // f_j, j = 0..k-1
  bool bottom_boundary() const { return s_.position == 0; }
  bool left_boundary() const { return s_.position == s_.faces - 1; }
  // Index of chart point (i,j), i,j in {-1..2}, if the patch has it.
  std::optional<std::size_t> chart(int i, int j) const;
  // The outer points the layout holds, with their chart positions, in canonical order.
  const std::vector<std::pair<int, int>>& outer() const { return outer_; }

 private:
  BoundarySector s_;
  std::vector<std::pair<int, int>> outer_;
  std::size_t size_;
};

// A0 and the regular children of the sector's patch (no reflection: the patch
// of face p mirrors that of face k-1-p, not itself).
PatchSubdivision build_sector_subdivision(const QuadScheme& scheme, const BoundarySector& sector);

// The sectors the runtime needs for boundary vertices in 1..max_faces faces:
// every position p of k = 1 and k >= 3 (in 2 faces the patches are regular
// boundary patches, with phantom points). With `sharp`, also the corners in
// k >= 2 faces (in 1 face a corner's patch is regular too), which sharp corner
// tags and vertices on three or more sharp edges make, the darts of valence
// 3..max_faces, and the cones of valence 3..max_faces (4 included: a sharp
// vertex makes a regular vertex a cone).
std::vector<BoundarySector> boundary_sectors(int max_faces, bool sharp = false);

}  // namespace sg
