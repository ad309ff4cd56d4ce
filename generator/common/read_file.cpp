#include "common/read_file.hpp"

#include <fstream>

#include "base/error.hpp"

namespace sg {

std::string read_file(const std::filesystem::path& path, long max_bytes, const std::string& kind) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw Error(path.string() + ": is a directory, not a " + kind + " file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path.string() + ": cannot open");
  std::string bytes;
  char buffer[1 << 16];
  while (in) {
    in.read(buffer, sizeof buffer);
    bytes.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (static_cast<long>(bytes.size()) > max_bytes)
      throw Error(path.string() + ": larger than " + std::to_string(max_bytes) + " bytes, the limit for " + kind + " files");
  }
  if (in.bad()) throw Error(path.string() + ": read error");
  return bytes;
}

}  // namespace sg
