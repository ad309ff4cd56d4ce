#pragma once
// Plumbing shared by the fuzz targets: a per-process scratch directory for
// APIs that take a path, and the rule that separates a normal outcome from a
// finding. A target's LLVMFuzzerTestOneInput runs its adapter inside
// run_expecting_errors: a thrown std::exception (every library's error types
// derive from it) is the correct answer to bad input; a crash, a sanitizer
// report, a timeout or std::bad_alloc (an allocation sized by the input) is a
// finding.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <new>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unistd.h>

namespace fuzz {

// Source tree locations, compiled in by fuzz/CMakeLists.txt.
inline std::filesystem::path source_dir() { return STENCIL_SOURCE_DIR; }
inline std::filesystem::path fixtures_dir() { return source_dir() / "fuzz" / "fixtures"; }

// $TMPDIR/stencil-fuzz-<pid>: created on first use, removed at normal exit.
inline const std::filesystem::path& scratch_dir() {
  struct Dir {
    std::filesystem::path path;
    Dir() : path(std::filesystem::temp_directory_path() / ("stencil-fuzz-" + std::to_string(::getpid()))) {
      std::filesystem::remove_all(path);
      std::filesystem::create_directories(path);
    }
    ~Dir() {
      std::error_code ignored;
      std::filesystem::remove_all(path, ignored);
    }
  };
  static const Dir dir;
  return dir.path;
}

// A failure of the harness itself (not of the code under test): stop loudly.
[[noreturn]] inline void harness_failure(const std::string& what) {
  std::fprintf(stderr, "fuzz harness: %s\n", what.c_str());
  std::abort();
}

// A fault the sanitizers cannot see (the code under test accepted data that
// breaks a documented promise): reported like a crash, in every build.
[[noreturn]] inline void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz finding: %s\n", what.c_str());
  std::abort();
}

inline void write_file(const std::filesystem::path& path, std::string_view bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) harness_failure("cannot write " + path.string());
}

// Writes the input to scratch_dir()/name and returns the path.
inline std::string write_scratch_file(const std::string& name, std::string_view bytes) {
  const std::filesystem::path path = scratch_dir() / name;
  write_file(path, bytes);
  return path.string();
}

inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// Runs `adapter`; a std::exception is a normal outcome, except std::bad_alloc
// and std::length_error, which are rethrown (libFuzzer and the standalone
// driver then report an uncaught exception). With FUZZ_SHOW_ERRORS=1 in the
// environment each refusal is printed (to see why a seed is refused).
template <class Adapter>
void run_expecting_errors(Adapter&& adapter) {
  static const bool show = std::getenv("FUZZ_SHOW_ERRORS") != nullptr;
  try {
    adapter();
    if (show) std::fprintf(stderr, "accepted\n");
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::length_error&) {
    throw;
  } catch (const std::exception& e) {
    if (show) std::fprintf(stderr, "refused: %s\n", e.what());
  }
}

}  // namespace fuzz
