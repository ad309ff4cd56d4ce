#pragma once
// Layout constants of the compact binary curve table (docs/table-format.md).
// Shared by the generator's writer and the runtime's reader.
#include <cstdint>

namespace stencil_runtime::format {

inline constexpr char kCurveMagic[8] = {'S', 'G', 'C', 'U', 'R', 'V', 'E', '\0'};
inline constexpr std::uint32_t kCurveVersion = 1;

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
inline constexpr std::uint32_t kSurfaceVersion = 6;  // 2: subdivision rules after the hash; 3: polygon rules; 4: scheme name, patch subdivision; 5: phi' of the regular curve; 6: tangent stencils at the extraordinary vertex

}  // namespace stencil_runtime::format

namespace stencil_runtime::format {

// Compact binary triangle tables (*.sgt): every valence and rate of one triangle scheme.
inline constexpr char kTriangleMagic[8] = {'S', 'G', 'T', 'R', 'I', '\0', '\0', '\0'};
inline constexpr std::uint32_t kTriangleVersion = 4;  // 2: regions per valence (sqrt(3) band); 3: children, regular polynomial; 4: tangent stencils at the extraordinary vertex

}  // namespace stencil_runtime::format
