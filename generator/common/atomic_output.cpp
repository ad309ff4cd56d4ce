#include "common/atomic_output.hpp"

#include <fstream>
#include <unistd.h>

#include "base/error.hpp"

namespace sg {
namespace fs = std::filesystem;

void OutputTransaction::commit() {
  std::error_code ec;
  const fs::path target = target_.lexically_normal();
  const fs::path parent = target.has_parent_path() ? target.parent_path() : fs::path(".");
  fs::create_directories(parent, ec);
  if (ec) throw Error("cannot create output directory " + parent.string() + ": " + ec.message());
  if (fs::exists(target) && !fs::is_directory(target)) throw Error("output path " + target.string() + " exists and is not a directory");
  const fs::path staging = parent / ("." + target.filename().string() + ".staging-" + std::to_string(::getpid()));
  fs::remove_all(staging, ec);
  auto abandon = [&](const std::string& what) {
    std::error_code ignore;
    fs::remove_all(staging, ignore);
    throw Error(what);
  };
  fs::create_directory(staging, ec);
  if (ec) abandon("cannot create staging directory " + staging.string() + ": " + ec.message());
  for (const auto& [name, bytes] : files_) {
    const fs::path file = staging / name;
    fs::create_directories(file.parent_path(), ec);
    if (ec) abandon("cannot create " + file.parent_path().string() + ": " + ec.message());
    std::ofstream out(file, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) abandon("cannot write " + (target / name).string());
  }
  if (!fs::exists(target)) {
    fs::rename(staging, target, ec);  // one atomic step
    if (ec) abandon("cannot move " + staging.string() + " to " + target.string() + ": " + ec.message());
    return;
  }
  // Target exists: move file by file (each rename is atomic; all files are already complete).
  for (const auto& [name, bytes] : files_) {
    fs::create_directories((target / name).parent_path(), ec);
    if (!ec) fs::rename(staging / name, target / name, ec);
    if (ec) abandon("cannot move " + name + " into " + target.string() + ": " + ec.message());
  }
  fs::remove_all(staging, ec);
}

}  // namespace sg
