#include "file_output.hpp"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <vector>

#include "stencil_runtime/error.hpp"

namespace stencil_runtime {

namespace fs = std::filesystem;

namespace {

// The stems a run may write beside a target, in name_beside's form.
constexpr const char* kLeftovers[] = {"partial", "staged", "previous"};

bool process_is_gone(long pid) { return ::kill(static_cast<pid_t>(pid), 0) == -1 && errno == ESRCH; }

}  // namespace

std::string output_file(const std::string& path) {
  fs::path p(path);
  std::error_code ec;
  fs::file_status status = fs::symlink_status(p, ec);
  for (int links = 0; fs::is_symlink(status); ++links) {
    if (links == 40) throw LoadError(path + ": cannot be written: a loop of symbolic links");  // as the kernel's ELOOP
    const fs::path to = fs::read_symlink(p, ec);
    if (ec) throw LoadError(path + ": cannot be written: " + ec.message());
    p = to.is_absolute() ? to : p.parent_path() / to;
    status = fs::symlink_status(p, ec);
  }
  if (fs::is_directory(status)) throw LoadError(path + ": is a directory, not a file to write");
  if (fs::exists(status) && !fs::is_regular_file(status))
    throw LoadError(path + ": is not a regular file (a device, FIFO or socket); outputs are written to regular files only");
  return p.lexically_normal().string();
}

std::string name_beside(const std::string& target, const char* what) {
  const fs::path p(target);
  std::string name(1, '.');  // appended: GCC 12 warns falsely on "." + string
  name += p.stem().string();
  name += '.';
  name += std::to_string(::getpid());
  name += '.';
  name += what;
  name += p.extension().string();
  return (p.parent_path() / name).string();
}

void sweep_left_by_killed_runs(const std::string& target) {
  const fs::path p(target);
  const fs::path parent = p.has_parent_path() ? p.parent_path() : fs::path(".");
  std::string prefix(1, '.');
  prefix += p.stem().string();
  prefix += '.';
  const std::string extension = p.extension().string();
  std::error_code ec;
  std::vector<std::pair<fs::path, bool>> left;  // (path, whether it is the moved-aside target)
  for (const fs::directory_entry& entry : fs::directory_iterator(parent, ec)) {
    const std::string file = entry.path().filename().string();
    if (file.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string rest = file.substr(prefix.size());
    const std::size_t dot = rest.find('.');
    const std::string digits = rest.substr(0, dot);
    if (dot == std::string::npos || digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos)
      continue;
    for (const char* what : kLeftovers) {
      std::string tail(1, '.');
      tail += what;
      tail += extension;
      if (rest.compare(dot, std::string::npos, tail) != 0) continue;
      const long pid = std::stol(digits);
      if (pid != ::getpid() && process_is_gone(pid)) left.emplace_back(entry.path(), std::string(what) == "previous");
    }
  }
  for (const auto& [path, previous] : left) {
    if (previous && !fs::exists(fs::symlink_status(target, ec))) fs::rename(path, target, ec);
    else fs::remove(path, ec);
  }
}

void write_file_atomically(const std::string& path, const std::function<void(std::FILE*)>& write) {
  const std::string target = output_file(path);
  sweep_left_by_killed_runs(target);
  const std::string temp = name_beside(target, "partial");
  std::FILE* f = std::fopen(temp.c_str(), "wb");
  if (!f) throw LoadError(path + ": cannot write");
  try {
    write(f);
  } catch (...) {
    std::fclose(f);
    std::remove(temp.c_str());
    throw;
  }
  const bool ok = std::ferror(f) == 0;
  if (std::fclose(f) != 0 || !ok) {
    std::remove(temp.c_str());
    throw LoadError(path + ": write failed");
  }
  std::error_code ec;
  fs::rename(temp, target, ec);
  if (ec) {
    std::remove(temp.c_str());
    throw LoadError(path + ": cannot move the finished file into place: " + ec.message());
  }
}

}  // namespace stencil_runtime
