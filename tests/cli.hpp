#pragma once
// Runs the stencilgen executable and captures its exit code and output.
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <system_error>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

struct CliResult {
  int status;
  std::string output;  // stdout and stderr together
};

inline CliResult run_command(const std::string& exe, const std::string& args) {
  const std::string cmd = exe + " " + args + " 2>&1";
  CliResult r{0, ""};
  FILE* pipe = popen(cmd.c_str(), "r");
  std::array<char, 4096> buf{};
  while (std::size_t got = std::fread(buf.data(), 1, buf.size(), pipe)) r.output.append(buf.data(), got);
  const int raw = pclose(pipe);
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return r;
}

// The stencilgen under test: this build's, unless $STENCILGEN_UNDER_TEST names
// another binary (to show that a new test fails on an older build).
inline std::string stencilgen_exe() {
  const char* other = std::getenv("STENCILGEN_UNDER_TEST");
  return other && *other ? other : STENCILGEN_EXE;
}
inline CliResult run_stencilgen(const std::string& args) { return run_command(stencilgen_exe(), args); }
// The same, killed after `seconds` (status 137): for inputs that must be refused before any long work.
inline CliResult run_stencilgen_within(int seconds, const std::string& args) {
  return run_command("timeout -s KILL " + std::to_string(seconds) + " " + stencilgen_exe(), args);
}
#ifdef STENCILEVAL_EXE
inline CliResult run_stencileval(const std::string& args) { return run_command(STENCILEVAL_EXE, args); }
inline CliResult run_stenciltess(const std::string& args) { return run_command(STENCILTESS_EXE, args); }
#endif
#ifdef STENCILFIT_EXE
inline CliResult run_stencilfit(const std::string& args) { return run_command(STENCILFIT_EXE, args); }
#endif

// Every scratch directory a test process made, removed when the process ends:
// ctest runs each test case in its own process, and each generates its tables,
// so directories left behind fill the disk (tens of GB over a CI run).
struct ScratchDirs {
  std::vector<std::filesystem::path> dirs;
  ~ScratchDirs() {
    for (const auto& dir : dirs) {
      std::error_code ignored;
      std::filesystem::remove_all(dir, ignored);
    }
  }
};
inline ScratchDirs& scratch_dirs() {
  static ScratchDirs all;
  return all;
}

// A fresh empty directory under the system temp dir, removed at exit.
inline std::filesystem::path scratch_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("stencilgen-test-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  scratch_dirs().dirs.push_back(dir);
  return dir;
}

// The binary table file stencilgen writes for `scheme` with `options` (e.g.
// "--valence 3-8 --n 24"): <dir>/<scheme>/<scheme>.<extension>, generated once
// per test process for each scheme and options.
inline std::filesystem::path generated_table(const std::string& scheme, const std::string& options,
                                             const std::string& extension) {
  static std::map<std::string, std::filesystem::path> made;
  const std::string key = scheme + " " + options;
  if (!made.count(key)) {
    const std::filesystem::path dir = scratch_dir("tables-" + scheme + "-" + std::to_string(made.size()));
    const CliResult r = run_stencilgen("--scheme " + scheme + " " + options + " --out " + dir.string() + " -q");
    if (r.status != 0) throw std::runtime_error(r.output);
    made[key] = dir / scheme / (scheme + "." + extension);
  }
  return made[key];
}
