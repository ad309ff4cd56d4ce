#include "common/sector_kind.hpp"

namespace sg {

const char* sector_kind_name(SectorKind kind) {
  switch (kind) {
    case SectorKind::Crease: return "crease";
    case SectorKind::Corner: return "corner";
    case SectorKind::Cone: return "cone";
    default: return "dart";
  }
}

std::string BoundarySector::name() const {
  if (kind == SectorKind::Cone) return "cone point of valence " + std::to_string(faces);
  if (kind == SectorKind::Dart) return "dart of valence " + std::to_string(faces) + ", face " + std::to_string(position);
  return std::string(kind == SectorKind::Corner ? "corner" : "boundary vertex") + " in " + std::to_string(faces) + " face" +
         (faces == 1 ? "" : "s") + ", face " + std::to_string(position);
}

}  // namespace sg
