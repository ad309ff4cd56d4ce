// Replays fuzz inputs without libFuzzer: each argument is a file, or a
// directory whose regular files (recursively, in sorted order) are run one by
// one through the target's LLVMFuzzerTestOneInput. This is how the committed
// corpus and the regression inputs (fuzz/regressions/<target>/) run in the
// ordinary build's test suite (ctest label fuzz-corpus). A finding crashes
// the process (or trips a sanitizer in the STENCIL_SANITIZE build); a missing
// path is an error, so that a misspelt directory does not pass silently.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

namespace fs = std::filesystem;

std::vector<fs::path> inputs_under(const fs::path& arg) {
  if (fs::is_regular_file(arg)) return {arg};
  if (!fs::is_directory(arg)) throw std::runtime_error(arg.string() + ": no such file or directory");
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(arg))
    if (entry.is_regular_file()) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

void run_one(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error(file.string() + ": cannot open");
  const std::vector<char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  // Announced first, so that the file at fault is the last line before a crash report.
  std::fprintf(stderr, "running %s (%zu bytes)\n", file.string().c_str(), bytes.size());
  // libFuzzer never passes a null pointer; an empty input gets a valid one too.
  static const std::uint8_t empty = 0;
  LLVMFuzzerTestOneInput(bytes.empty() ? &empty : reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc < 2) throw std::runtime_error("usage: " + std::string(argv[0]) + " FILE|DIR...");
    std::size_t count = 0;
    for (int k = 1; k < argc; ++k)
      for (const fs::path& file : inputs_under(argv[k])) {
        run_one(file);
        ++count;
      }
    std::printf("%zu inputs ran without a finding\n", count);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: error: %s\n", argv[0], e.what());
    return 1;
  }
}
