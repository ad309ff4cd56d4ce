#include "staged_files.hpp"

#include "mesh/file_output.hpp"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace stencil_tools {

namespace fs = std::filesystem;

using stencil_runtime::name_beside;

StagedFiles::~StagedFiles() {
  if (committed_) return;
  for (const auto& [staging, target] : staged_) std::remove(staging.c_str());
}

std::string StagedFiles::stage(const std::string& output) {
  const std::string target = stencil_runtime::output_file(output);  // a link kept, a device refused
  stencil_runtime::sweep_left_by_killed_runs(target);
  staged_.emplace_back(name_beside(target, "staged"), target);
  return staged_.back().first;
}

void StagedFiles::commit() {
  for (const auto& [staging, target] : staged_) {  // what would fail the moves, found before any
    std::error_code ec;
    if (fs::is_directory(target, ec)) throw std::runtime_error(target + ": is a directory, not a file to write");
  }
  struct Moved {
    std::string target, backup;  // backup empty: the target did not exist
  };
  std::vector<Moved> moved;
  auto undo = [&] {
    for (auto it = moved.rbegin(); it != moved.rend(); ++it) {
      std::error_code ec;
      if (it->backup.empty()) fs::remove(it->target, ec);
      else fs::rename(it->backup, it->target, ec);
    }
  };
  for (const auto& [staging, target] : staged_) {
    std::error_code ec;
    Moved m{target, ""};
    if (fs::exists(fs::symlink_status(target, ec))) {
      m.backup = name_beside(target, "previous");
      fs::rename(target, m.backup, ec);
      if (ec) {
        undo();
        throw std::runtime_error(target + ": cannot move the earlier file aside to replace it: " + ec.message());
      }
    }
    fs::rename(staging, target, ec);
    if (ec) {
      if (!m.backup.empty()) fs::rename(m.backup, target, ec);
      undo();
      throw std::runtime_error(target + ": cannot move the finished file into place: " + ec.message());
    }
    moved.push_back(m);
  }
  committed_ = true;
  for (const Moved& m : moved)
    if (!m.backup.empty()) std::remove(m.backup.c_str());
}

}  // namespace stencil_tools
