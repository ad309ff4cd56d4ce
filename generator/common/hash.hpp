#pragma once
#include <cstdint>
#include <string>
#include <string_view>

namespace sg {

// 64-bit FNV-1a. Identifies a scheme's canonical content in tables so that the
// runtime can refuse a table made from a different scheme; not a security hash.
std::uint64_t fnv1a64(std::string_view bytes);
std::string hex64(std::uint64_t value);

}  // namespace sg
