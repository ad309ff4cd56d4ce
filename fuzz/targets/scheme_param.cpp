// Fuzz target: stencilgen's --param NAME=VALUE overrides, applied to a bundled
// scheme. Input: the scheme's name on the first line (letters, digits and '-'
// only; "fourpoint" otherwise), then one override per line. The scheme is
// loaded by the loader of its type, as stencilgen dispatches.
#include <algorithm>
#include <sstream>
#include <vector>

#include "fuzz_support.hpp"
#include "quad/quad_scheme_loader.hpp"
#include "common/scheme_registry.hpp"
#include "curve/curve_scheme_loader.hpp"
#include "triangle/triangle_scheme_loader.hpp"

namespace {

// Adapter: the entry points under test.
void load(const std::string& name, const std::vector<std::string>& overrides) {
  const std::filesystem::path dir = fuzz::source_dir() / "schemes";
  const std::string type = sg::scheme_type(name, dir);
  if (type == "quad") sg::load_quad_scheme(name, overrides, dir);
  else if (type == "triangle") sg::load_triangle_scheme(name, overrides, dir);
  else sg::load_curve_scheme(name, overrides, dir);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in{std::string(fuzz::as_text(data, size))};
  std::string name, line;
  std::getline(in, name);
  const bool plain = !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-';
  });
  if (!plain) name = "fourpoint";
  std::vector<std::string> overrides;
  while (std::getline(in, line)) overrides.push_back(line);
  fuzz::run_expecting_errors([&] { load(name, overrides); });
  return 0;
}
