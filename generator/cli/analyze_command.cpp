// stencilgen analyze --scheme S [--valence V]: the smoothness analysis of a surface scheme per valence.
#include <algorithm>
#include <functional>
#include <iostream>

#include "base/error.hpp"
#include "base/limits.hpp"
#include "cli/commands.hpp"
#include "common/rate_spec.hpp"
#include "common/scheme_registry.hpp"
#include "quad/quad_analysis.hpp"
#include "quad/quad_scheme_loader.hpp"
#include "triangle/triangle_analysis.hpp"
#include "triangle/triangle_scheme_loader.hpp"

namespace sg::cli {

namespace {

// Prints the heading and each valence's report; the exit code says whether all pass.
int print_reports(const std::string& heading, const std::vector<int>& valences,
                  const std::function<SmoothnessReport(int)>& analyse) {
  std::cout << heading << "\n";
  int failed = 0;
  for (int v : valences) {
    const SmoothnessReport r = analyse(v);
    if (!r.ok()) ++failed;
    std::cout << format_report(r);
  }
  std::cout << (failed == 0 ? "all valences pass\n" : std::to_string(failed) + " valence(s) FAIL\n");
  return failed == 0 ? 0 : 1;
}

}  // namespace

int analyze(const std::string& scheme_spec, const std::string& valence_spec, const std::vector<std::string>& params,
            long samples) {
  if (samples < 2 || samples > limits::kMaxAnalysisSamples)
    throw Error("analyze --samples " + std::to_string(samples) + " is outside 2.." +
                std::to_string(limits::kMaxAnalysisSamples));
  // Every valence is checked against the limits and the scheme's range before the first is analysed.
  const std::vector<int> valences = parse_valence_spec(valence_spec);
  const std::string type = scheme_type(scheme_spec);
  if (type != "quad" && type != "triangle")
    throw Error("analyze: '" + excerpt(scheme_spec) + "' is a curve scheme (type " + excerpt(type) +
                "); analyze studies the extraordinary vertices of quad and triangle surface schemes (a curve scheme's "
                "convergence and smoothness are reported when its tables are generated)");
  if (type == "triangle") {
    const TriangleScheme scheme = load_triangle_scheme(scheme_spec, params);
    check_valences(valences, scheme.min_valence, scheme.max_valence, scheme.source);
    return print_reports(
        "smoothness analysis of '" + scheme.name + "' (" + scheme.source + ")" +
            (scheme.refinement == TriangleRefinement::Sqrt3
                 ? "; spectra of two composed steps (one step's moduli are their square roots)"
                 : ""),
        valences, [&](int v) { return analyse_triangle_valence(scheme, v, samples); });
  }
  const QuadScheme scheme = load_quad_scheme(scheme_spec, params);
  check_valences(valences, scheme.min_valence, scheme.max_valence, scheme.source);
  const int interior = print_reports("smoothness analysis of '" + scheme.name + "' (" + scheme.source + ")", valences,
                                     [&](int v) { return analyse_quad_valence(scheme, v, samples); });
  // Boundary vertices in 1..max faces (the sectors stencilgen writes with these valences). Informational: the
  // boundary rules are OpenSubdiv's, whatever their spectrum, so they do not change the exit code.
  std::cout << "boundary vertices (the boundary curve's rules along the boundary; informational):\n";
  int without = 0;
  for (int k = 1; k <= *std::max_element(valences.begin(), valences.end()); ++k) {
    if (k == 2) continue;  // the regular boundary
    bool ok = false;
    std::cout << "  " << analyse_quad_boundary(scheme, k, ok);
    without += ok ? 0 : 1;
  }
  std::cout << (without == 0 ? "a tangent plane at every boundary vertex\n"
                             : std::to_string(without) + " boundary configuration(s) without a tangent plane at the vertex "
                               "(no normal there; the surface round it is evaluated exactly all the same)\n");
  return interior;
}

}  // namespace sg::cli
