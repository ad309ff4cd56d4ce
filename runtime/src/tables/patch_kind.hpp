#pragma once
// Which patch evaluates a prepared quad face, as one integer "kind": 4 is the
// regular patch, 3..64 (other than 4) the patch round an interior
// extraordinary vertex of that valence, and from kFirstSectorKind on the patch
// of a face at a vertex on a boundary: the vertex in k faces (its sector), the
// face at position p among them, counter-clockwise from the boundary edge
// (docs/table-format.md, "Boundary sectors").
#include <string>

#include "stencil_runtime/limits.hpp"

namespace stencil_runtime {

// A sector's vertex rule: the boundary curve's (a vertex on a boundary or an
// infinitely sharp crease), none (a corner: it stays put), or the smooth rule
// (a dart: the end of an infinitely sharp crease, a boundary vertex of the
// mesh cut along it whose e_0 and e_k are copies of one vertex). A cone point
// (an infinitely sharp vertex inside the mesh on no infinitely sharp edge) is
// no boundary vertex, but its patch is kept as a sector too: the interior
// patch's layout (2v+8 points) with the vertex held, the same for every face
// round it (position 0).
enum class SectorRule : unsigned char { Crease = 0, Corner = 1, Dart = 2, Cone = 3 };

struct SectorKey {
  SectorRule rule = SectorRule::Crease;
  int faces = 1;     // k, 1..kMaxValence (a dart or a cone: its valence, >= 3)
  int position = 0;  // p, 0..k-1 (a cone: 0)
  bool operator==(const SectorKey&) const = default;
  bool valid() const {
    const bool ring = rule == SectorRule::Dart || rule == SectorRule::Cone;
    return faces >= (ring ? 3 : 1) && faces <= limits::kMaxValence && position >= 0 &&
           position < (rule == SectorRule::Cone ? 1 : faces);
  }
  // The patch's control points: the vertex, its k+1 edge neighbours, k face
  // opposites, and the outer points of the face's chart that exist (a cone:
  // the interior patch's 2k+8).
  int points() const {
    if (rule == SectorRule::Cone) return 2 * faces + 8;
    return 2 * faces + 2 + 5 + (position > 0 ? 1 : 0) + (position + 1 < faces ? 1 : 0);
  }
  std::string name() const {
    if (rule == SectorRule::Cone) return "cone point of valence " + std::to_string(faces);
    if (rule == SectorRule::Dart) return "dart of valence " + std::to_string(faces) + ", face " + std::to_string(position);
    return std::string(rule == SectorRule::Corner ? "corner" : "boundary vertex") + " in " + std::to_string(faces) + " face" +
           (faces == 1 ? "" : "s") + ", face " + std::to_string(position);
  }
};

inline constexpr int kFirstSectorKind = 1 << 16;
inline int sector_kind(const SectorKey& s) {
  return kFirstSectorKind + (static_cast<int>(s.rule) * 128 + s.faces) * 128 + s.position;
}
inline bool is_sector_kind(int kind) { return kind >= kFirstSectorKind; }
inline SectorKey sector_of(int kind) {
  const int x = kind - kFirstSectorKind;
  return {static_cast<SectorRule>(x / (128 * 128)), (x / 128) % 128, x % 128};
}
// Control points of a patch of any kind.
inline int patch_points(int kind) {
  if (is_sector_kind(kind)) return sector_of(kind).points();
  return kind == 4 ? 16 : 2 * kind + 8;
}
inline std::string kind_name(int kind) {
  return is_sector_kind(kind) ? sector_of(kind).name() : "valence " + std::to_string(kind);
}

}  // namespace stencil_runtime
