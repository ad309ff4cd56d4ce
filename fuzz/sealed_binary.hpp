#pragma once
// The binary table formats (.sgc, .sgs, .sgt) end in an FNV-1a checksum of
// every preceding byte, which a mutated input almost never matches: the
// loaders would refuse nearly every input before parsing it. The binary fuzz
// targets therefore recompute the checksum, so that mutations reach the
// parser; the checksum test itself is a single comparison (checked by the unit
// tests: test_tables_io, test_surface_tables, test_triangle_runtime).
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

#include "stencil_runtime/binary_format.hpp"

namespace fuzz {

// `bytes` with its last 8 bytes replaced by the checksum of the others
// (unchanged when shorter than magic + checksum).
inline std::string with_valid_checksum(std::string_view bytes) {
  std::string sealed(bytes);
  if (sealed.size() < 16) return sealed;
  const std::uint64_t sum = stencil_runtime::format::fnv1a64(reinterpret_cast<const unsigned char*>(sealed.data()),
                                                             sealed.size() - 8);
  std::memcpy(sealed.data() + sealed.size() - 8, &sum, 8);
  return sealed;
}

}  // namespace fuzz
