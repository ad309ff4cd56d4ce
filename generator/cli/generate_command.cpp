// stencilgen --scheme S --n RATES [--valence V] --out DIR: curve, quad or triangle tables.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>

#include "base/error.hpp"
#include "base/limits.hpp"
#include "cli/cli_helpers.hpp"
#include "cli/commands.hpp"
#include "common/atomic_output.hpp"
#include "common/rate_spec.hpp"
#include "common/scheme_registry.hpp"
#include "curve/difference_scheme.hpp"
#include "curve/curve_scheme_loader.hpp"
#include "curve/generate_curve.hpp"
#include "quad/generate_quad.hpp"
#include "quad/quad_analysis.hpp"
#include "quad/quad_scheme_loader.hpp"
#include "triangle/generate_triangle.hpp"
#include "triangle/triangle_scheme_loader.hpp"

namespace sg::cli {
namespace {

const char* const kSurfaceRateLimit = "the largest rate for surface schemes";

// The run replaces OUT/<name> whole: a scheme file inside it would be lost.
void check_scheme_outside_output(const std::string& source, const std::string& name, const std::string& out) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path folder = fs::weakly_canonical(fs::path(out) / name, ec);
  if (ec || source.empty()) return;
  const fs::path file = fs::weakly_canonical(source, ec);
  if (ec) return;
  auto f = folder.begin(), p = file.begin();
  for (; f != folder.end() && !f->empty(); ++f, ++p)
    if (p == file.end() || *p != *f) return;
  throw Error("the scheme file " + source + " is inside " + (fs::path(out) / name).string() +
              ", which the run replaces whole; move the scheme file elsewhere or choose another --out");
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

int generate_curve(const GenerateOptions& o) {
  const auto rates = parse_rate_spec(o.rates, limits::kMaxCurveRate, "the largest rate for curve schemes");
  const CurveScheme scheme = load_curve_scheme(o.scheme, o.params);
  check_scheme_outside_output(scheme.source, scheme.name, o.out);
  const RouteChoice choice = o.route == "residue" ? RouteChoice::Residue
                             : o.route == "eigen" ? RouteChoice::Eigen
                                                  : RouteChoice::Both;
  const auto start = std::chrono::steady_clock::now();
  const auto tables = generate_curve_tables(scheme, rates, choice, progress_lines(o.quiet));
  write_curve_tables(scheme, tables, o.out);
  std::cout << "wrote " << tables.size() << " exact tables (JSON + binary) for '" << scheme.name << "' to "
            << (std::filesystem::path(o.out) / scheme.name).string() << " in " << seconds_since(start) << " s\n";
  // Said even with -q: tables of a scheme that may not converge describe no curve.
  if (const std::string doubt = convergence_doubt(scheme); !doubt.empty())
    std::cerr << "stencilgen: warning: scheme '" << scheme.name << "' is not shown to converge (" << doubt
              << "): its tables are the exact solution of the scaling relations, which need not be the values of any "
                 "limit function\n";
  return 0;
}

int generate_quad(const GenerateOptions& o, const std::string& valence_spec) {
  const auto rates = parse_rate_spec(o.rates, limits::kMaxSurfaceRate, kSurfaceRateLimit);
  const auto valences = parse_valence_spec(valence_spec);
  const QuadScheme scheme = load_quad_scheme(o.scheme, o.params);
  check_scheme_outside_output(scheme.source, scheme.name, o.out);
  check_valences(valences, scheme.min_valence, scheme.max_valence, scheme.source);
  const auto start = std::chrono::steady_clock::now();
  for (int v : valences) {
    const SmoothnessReport report = analyse_quad_valence(scheme, v, 16);
    if (!report.ok())
      std::cerr << "stencilgen: warning: '" << scheme.name << "' fails the smoothness analysis at valence " << v
                << " (tables are still exact; see `stencilgen analyze`):\n"
                << format_report(report);
  }
  const auto set = generate_quad_tables(scheme, valences, rates, progress_lines(o.quiet));
  const bool asked_generated = o.layout != "stored";
  const bool generated = asked_generated && generated_layout_fits(set);
  if (asked_generated && !generated)
    std::cerr << "stencilgen: note: these rates and valences are too large for the runtime to expand at load time; "
                 "the .sgs stores every stencil\n";
  const std::size_t bytes = write_quad_tables(scheme, set, o.out, binary_precision(o.precision),
                                              generated ? BinaryLayout::Generated : BinaryLayout::Stored);
  std::cout << "wrote exact surface tables for '" << scheme.name << "' (valences " << valence_spec << ", rates "
            << rates.front() << ".." << rates.back() << ", " << rates.size() * valences.size() << " tables) to "
            << (std::filesystem::path(o.out) / scheme.name).string() << " in " << seconds_since(start)
            << " s; binary " << scheme.name << ".sgs: " << bytes << " bytes (" << o.precision << " precision, "
            << (generated ? "generated" : "stored") << " stencils)\n";
  return 0;
}

int generate_triangle(const GenerateOptions& o, const std::string& valence_spec) {
  const auto rates = parse_rate_spec(o.rates, limits::kMaxSurfaceRate, kSurfaceRateLimit);
  auto valences = parse_valence_spec(valence_spec);
  const TriangleScheme scheme = load_triangle_scheme(o.scheme, o.params);
  check_scheme_outside_output(scheme.source, scheme.name, o.out);
  check_valences(valences, scheme.min_valence, scheme.max_valence, scheme.source);
  // Valence 6 is the regular patch, which the runtime needs for every ordinary triangle.
  if (std::find(valences.begin(), valences.end(), 6) == valences.end()) valences.push_back(6);
  std::sort(valences.begin(), valences.end());
  const auto start = std::chrono::steady_clock::now();
  const auto set = generate_triangle_tables(scheme, valences, rates, progress_lines(o.quiet));
  const std::size_t bytes = write_triangle_tables(scheme, set, o.out, binary_precision(o.precision), progress_lines(o.quiet));
  std::string exact, approx;
  for (int v : valences) (scheme.exact_neighbour_weight(v) ? exact : approx) += (std::to_string(v) + " ");
  std::cout << "wrote triangle tables for '" << scheme.name << "' (valences " << valence_spec << " and 6, rates "
            << rates.front() << ".." << rates.back() << ", " << rates.size() * valences.size() << " tables) to "
            << (std::filesystem::path(o.out) / scheme.name).string() << " in " << seconds_since(start)
            << " s; exact at valences " << (exact.empty() ? "none " : exact) << "; high precision (" << kRealDigits
            << " digits, not exact) at " << (approx.empty() ? "none " : approx) << "; binary " << scheme.name
            << ".sgt: " << bytes << " bytes (" << o.precision << " precision)"
            << (scheme.refinement == TriangleRefinement::Loop && scheme.has_crease ? "; Loop's sectors exactly in sectors.json" : "")
            << "\n";
  return 0;
}

}  // namespace

int generate(const GenerateOptions& o) {
  check_output_parent(o.out);  // before the work, not after it
  const std::string type = scheme_type(o.scheme);
  const std::string valences = o.valences.empty() ? "3-8" : o.valences;
  // An option that would change nothing is refused, not ignored (route stays "both" unless given).
  const bool curve = type != "quad" && type != "triangle";  // curve-uniform, curve-columns, curve-knots
  if (!curve && o.route != "both")
    throw Error("--route applies to curve schemes; '" + o.scheme + "' is a " + type + " scheme");
  if (curve && o.precision != "double")
    throw Error("--binary-precision applies to surface schemes; '" + o.scheme + "' is a curve scheme (its .sgc holds doubles)");
  if (type == "quad") return generate_quad(o, valences);
  if (o.layout != "generated")
    throw Error("--binary-layout applies to quad schemes; '" + o.scheme + "' is a " + type + " scheme");
  if (type == "triangle") return generate_triangle(o, valences);
  if (!o.valences.empty()) throw Error("--valence applies to surface schemes; '" + o.scheme + "' is a curve scheme");
  return generate_curve(o);
}

}  // namespace sg::cli
