#include "common/hash.hpp"

#include <cstdio>

#include "stencil_runtime/binary_format.hpp"

namespace sg {

std::uint64_t fnv1a64(std::string_view bytes) {
  // One definition shared with the runtime's table checksum.
  return stencil_runtime::format::fnv1a64(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size());
}

std::string hex64(std::uint64_t value) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(value));
  return buf;
}

}  // namespace sg
