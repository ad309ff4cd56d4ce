#pragma once
// Bounds-checked little-endian reader over a byte buffer.
#include <cstdint>
#include <cstring>
#include <string>

#include "stencil_runtime/curve_table.hpp"

namespace stencil_runtime::detail {

class BinaryReader {
 public:
  BinaryReader(const std::string& bytes, std::string origin) : bytes_(bytes), origin_(std::move(origin)) {}
  template <class T>
  T get() {
    need(sizeof(T));
    T v;
    std::memcpy(&v, bytes_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return v;
  }
  std::string get_string(std::size_t size) {
    need(size);
    std::string s = bytes_.substr(pos_, size);
    pos_ += size;
    return s;
  }
  std::size_t position() const { return pos_; }
  [[noreturn]] void fail(const std::string& what) const { throw LoadError(origin_ + ": " + what); }

 private:
  void need(std::size_t size) const {
    if (bytes_.size() - pos_ < size) fail("truncated (needs more than its " + std::to_string(bytes_.size()) + " bytes)");
  }
  const std::string& bytes_;
  std::string origin_;
  std::size_t pos_ = 0;
};

}  // namespace stencil_runtime::detail
