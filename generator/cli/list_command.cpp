// stencilgen list: the schemes in the schemes directory, by family, and the
// files there that cannot be used, with the reason (the same test `--scheme`
// applies, so every name listed as a scheme loads).
#include <iostream>

#include "cli/commands.hpp"
#include "common/scheme_registry.hpp"

namespace sg::cli {

int list() {
  const auto dir = default_schemes_dir();
  const std::vector<SchemeEntry> entries = scheme_catalogue(dir);
  std::cout << "schemes in " << dir.string() << ":\n";
  const std::pair<SchemeFamily, const char*> families[] = {
      {SchemeFamily::Curve, "curve"}, {SchemeFamily::Quad, "quad surface"}, {SchemeFamily::Triangle, "triangle surface"}};
  for (const auto& [family, what] : families)
    for (const SchemeEntry& e : entries)
      if (e.problem.empty() && e.family == family) std::cout << "  " << e.name << " (" << what << ")\n";
  bool header = false;
  for (const SchemeEntry& e : entries) {
    if (e.problem.empty()) continue;
    if (!header) std::cout << "files there that are not usable schemes:\n";
    header = true;
    std::cout << "  " << e.name << ".json: " << e.problem << "\n";
  }
  return 0;
}

}  // namespace sg::cli
