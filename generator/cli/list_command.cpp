// stencilgen list: the schemes in the schemes directory, by family.
#include <iostream>

#include "cli/commands.hpp"
#include "common/scheme_registry.hpp"

namespace sg::cli {

int list() {
  const auto dir = default_schemes_dir();
  std::cout << "schemes in " << dir.string() << ":\n";
  for (const auto& name : available_schemes(dir, SchemeFamily::Curve)) std::cout << "  " << name << " (curve)\n";
  for (const auto& name : available_schemes(dir, SchemeFamily::Quad)) std::cout << "  " << name << " (quad surface)\n";
  for (const auto& name : available_schemes(dir, SchemeFamily::Triangle))
    std::cout << "  " << name << " (triangle surface)\n";
  return 0;
}

}  // namespace sg::cli
