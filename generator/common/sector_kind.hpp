#pragma once
// Which patch a face at a special vertex takes, for every family: the vertex B
// on the mesh's boundary (or on an infinitely sharp crease, after the mesh is
// cut along it) in k faces, the face at position p among them. The families
// lay out and refine these patches their own way (quad/boundary_sector.hpp,
// triangle/triangle_sector.hpp).
#include <string>

namespace sg {

// What B's own rule is: the boundary curve's vertex rule over its two boundary
// neighbours (a boundary or crease vertex), none (a corner: it stays put), or
// the scheme's smooth rule at valence k (a dart: an infinitely sharp crease
// ends at B, the mesh cut along it makes B a boundary vertex whose two boundary
// neighbours are copies of the crease's next vertex, and B's rule sees it once).
// Cone: the vertex stays put, everything round it follows the smooth rules.
enum class SectorKind : unsigned char { Crease = 0, Corner = 1, Dart = 2, Cone = 3 };
const char* sector_kind_name(SectorKind kind);  // "crease", "corner", "dart", "cone"

struct BoundarySector {
  SectorKind kind = SectorKind::Crease;
  int faces = 1;     // k >= 1 (>= 3 for a dart or a cone: its valence)
  int position = 0;  // p, 0 <= p < k (0 for a cone)

  // "boundary vertex in 3 faces, face 1" / "corner in 2 faces, face 0" / "dart of valence 5, face 2" /
  // "cone point of valence 3"
  std::string name() const;
  bool operator==(const BoundarySector&) const = default;
};

}  // namespace sg
