#pragma once
// Bounds-checked little-endian reader over a byte buffer, and the checked
// reading of a whole table file.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "stencil_runtime/binary_format.hpp"
#include "stencil_runtime/error.hpp"
#include "stencil_runtime/limits.hpp"

namespace stencil_runtime::detail {

class BinaryReader {
 public:
  BinaryReader(const std::string& bytes, std::string origin)
      : bytes_(bytes), origin_(std::move(origin)), end_(bytes.size()) {}
  // Reads stop at `end` (the payload's end, before the checksum).
  void end_at(std::size_t end) { end_ = std::min(end, bytes_.size()); }
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
    if (pos_ > end_ || end_ - pos_ < size) fail("truncated (needs more than its " + std::to_string(bytes_.size()) + " bytes)");
  }
  const std::string& bytes_;
  std::string origin_;
  std::size_t end_;
  std::size_t pos_ = 0;
};

// A whole regular file of at most limits::kMaxTableFileBytes; LoadError naming
// the path when it cannot be read.
inline std::string read_table_file(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) throw LoadError(path + ": cannot open (no such file)");
  if (!fs::is_regular_file(status)) throw LoadError(path + ": not a regular file");
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) throw LoadError(path + ": cannot read its size: " + ec.message());
  if (size > limits::kMaxTableFileBytes)
    throw LoadError(path + ": " + std::to_string(size) + " bytes; table files are limited to " +
                    std::to_string(limits::kMaxTableFileBytes) + " bytes");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw LoadError(path + ": cannot open");
  std::string bytes(static_cast<std::size_t>(size), '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(size));
  if (static_cast<std::uintmax_t>(in.gcount()) != size) throw LoadError(path + ": read failed");
  return bytes;
}
inline std::string read_binary_file(const std::string& path) { return read_table_file(path); }

// Checks the leading magic and the trailing FNV-1a checksum, and leaves the
// reader just past the magic.
inline void check_envelope(const std::string& bytes, BinaryReader& r, const char (&magic)[8], const char* what) {
  if (bytes.size() < sizeof magic + 8) r.fail("truncated (only " + std::to_string(bytes.size()) + " bytes)");
  if (r.get_string(sizeof magic) != std::string(magic, sizeof magic))
    r.fail(std::string("not a stencilgen ") + what + " (bad magic)");
  std::uint64_t stored;
  std::memcpy(&stored, bytes.data() + bytes.size() - 8, 8);
  if (stored != format::fnv1a64(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size() - 8))
    r.fail("checksum mismatch: the file is corrupt or truncated");
  r.end_at(bytes.size() - 8);  // the payload: nothing may read the checksum as data
}

}  // namespace stencil_runtime::detail
