#pragma once
// Layout constants of the compact binary curve table (docs/table-format.md).
// Shared by the generator's writer and the runtime's reader.
#include <cstdint>

namespace stencil_runtime::format {

inline constexpr char kCurveMagic[8] = {'S', 'G', 'C', 'U', 'R', 'V', 'E', '\0'};
inline constexpr std::uint32_t kCurveVersion = 2;  // 2: derivatives of the scaling functions
inline constexpr std::uint32_t kMaxCurveDerivativeOrder = 2;

enum class Placement : std::uint8_t { Everywhere = 0, AtMost = 1, AtLeast = 2, Single = 3 };

// 64-bit FNV-1a, used for the trailing checksum.
inline std::uint64_t fnv1a64(const unsigned char* data, std::uint64_t size) {
  std::uint64_t h = 14695981039346656037ull;
  for (std::uint64_t i = 0; i < size; ++i) {
    h ^= data[i];
    h *= 1099511628211ull;
  }
  return h;
}

}  // namespace stencil_runtime::format

namespace stencil_runtime::format {

// Compact binary surface tables (*.sgs): every valence and rate of one quad scheme.
inline constexpr char kSurfaceMagic[8] = {'S', 'G', 'S', 'U', 'R', 'F', '\0', '\0'};
inline constexpr std::uint32_t kSurfaceVersion = 9;  // 2: subdivision rules after the hash; 3: polygon rules; 4: scheme name, patch subdivision; 5: phi' of the regular curve; 6: tangent stencils at the extraordinary vertex; 7: the layout byte (generated stencils); 8: boundary sectors; 9: cone points (sector rule 3)

// How a .sgs file holds the extraordinary patches' stencils (version 7).
// Stored: every stencil. Generated: only what generates them (the patch
// subdivision, the regular curve's values and the limit stencil), expanded by
// the reader with the patch recursion W(x) = W(2x) A0 (docs/table-format.md).
enum class SurfaceLayout : std::uint8_t { Stored = 0, Generated = 1 };

// The reader expands a generated valence on the grid 1/(2N) of each rate in
// long double: (2N+1)^2 * points entries, each cell one sparse row-vector
// product with A0 or a regular child. These limits bound its memory (the grid
// of one rate: 64 MiB; the stencils kept: at most a quarter of all entries,
// in double) and its time (multiply-adds: cells times the nonzeros of A0 plus
// those of the densest regular child); a writer stores the stencils instead
// where a set would exceed them.
inline constexpr std::uint64_t kMaxExpansionGridEntries = std::uint64_t{1} << 22;  // one rate of one valence
inline constexpr std::uint64_t kMaxExpansionEntries = std::uint64_t{1} << 24;      // the whole file
inline constexpr std::uint64_t kMaxExpansionWork = std::uint64_t{1} << 28;         // the whole file
inline constexpr std::uint64_t expansion_grid_entries(std::uint64_t rate, std::uint64_t points) {
  return (2 * rate + 1) * (2 * rate + 1) * points;  // rate <= 2^12 and points <= 2^8: no overflow
}
// `nonzeros`: of A0 plus of the densest regular child (each at most 2^16 here).
inline constexpr std::uint64_t expansion_work(std::uint64_t rate, std::uint64_t nonzeros) {
  return (2 * rate + 1) * (2 * rate + 1) * nonzeros;
}

}  // namespace stencil_runtime::format

namespace stencil_runtime::format {

// Compact binary triangle tables (*.sgt): every valence and rate of one triangle scheme.
inline constexpr char kTriangleMagic[8] = {'S', 'G', 'T', 'R', 'I', '\0', '\0', '\0'};
inline constexpr std::uint32_t kTriangleVersion = 7;  // 2: regions per valence (sqrt(3) band); 3: children, regular polynomial; 4: tangent stencils at the extraordinary vertex; 5: the crease rule; 6: the regular patch's derivative stencils (sqrt(3)); 7: Loop boundary sectors
// A child that is a boundary sector's own patch again names it by this code plus the sector's position in the file.
inline constexpr std::uint32_t kTriangleSectorCode = 1u << 16;

}  // namespace stencil_runtime::format
