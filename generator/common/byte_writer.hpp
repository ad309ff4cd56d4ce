#pragma once
// Appending fixed-size values to a byte string, as the binary table writers do
// (little-endian hosts; the formats are little-endian, docs/table-format.md).
#include <cstring>
#include <string>

namespace sg {

template <class T>
void put(std::string& out, T value) {
  char buf[sizeof(T)];
  std::memcpy(buf, &value, sizeof(T));
  out.append(buf, sizeof(T));
}

}  // namespace sg
