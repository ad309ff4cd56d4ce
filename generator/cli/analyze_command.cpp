// stencilgen analyze --scheme S [--valence V]: the smoothness analysis of a surface scheme per valence.
#include <iostream>

#include "cli/commands.hpp"
#include "common/rate_spec.hpp"
#include "common/scheme_registry.hpp"
#include "quad/quad_analysis.hpp"
#include "quad/quad_scheme_loader.hpp"
#include "triangle/triangle_analysis.hpp"
#include "triangle/triangle_scheme_loader.hpp"

namespace sg::cli {

int analyze(const std::string& scheme_spec, const std::string& valence_spec, const std::vector<std::string>& params,
            long samples) {
  if (scheme_type(scheme_spec) == "triangle") {
    const TriangleScheme scheme = load_triangle_scheme(scheme_spec, params);
    int failed = 0;
    std::cout << "smoothness analysis of '" << scheme.name << "' (" << scheme.source << ")"
              << (scheme.refinement == TriangleRefinement::Sqrt3
                      ? "; spectra of two composed steps (one step's moduli are their square roots)"
                      : "")
              << "\n";
    for (int v : parse_valence_spec(valence_spec)) {
      const SmoothnessReport r = analyse_triangle_valence(scheme, v, samples);
      if (!r.ok()) ++failed;
      std::cout << format_report(r);
    }
    std::cout << (failed == 0 ? "all valences pass\n" : std::to_string(failed) + " valence(s) FAIL\n");
    return failed == 0 ? 0 : 1;
  }
  const QuadScheme scheme = load_quad_scheme(scheme_spec, params);
  int failed = 0;
  std::cout << "smoothness analysis of '" << scheme.name << "' (" << scheme.source << ")\n";
  for (int v : parse_valence_spec(valence_spec)) {
    scheme.vertex_rule(v);
    const SmoothnessReport r = analyse_quad_valence(scheme, v, samples);
    if (!r.ok()) ++failed;
    std::cout << format_report(r);
  }
  std::cout << (failed == 0 ? "all valences pass\n" : std::to_string(failed) + " valence(s) FAIL\n");
  return failed == 0 ? 0 : 1;
}

}  // namespace sg::cli
