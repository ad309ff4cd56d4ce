// stencilgen: exact evaluation stencils for stationary subdivision schemes.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <iostream>
#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "common/atomic_output.hpp"
#include "common/rate_spec.hpp"
#include "common/read_file.hpp"
#include "common/scheme_registry.hpp"
#include "common/table_encoding.hpp"
#include "curve/curve_scheme_loader.hpp"
#include "curve/curve_table_json.hpp"
#include "curve/curve_table_verify.hpp"
#include "curve/generate_curve.hpp"
#include "curve/plot_svg.hpp"
#include "curve/residue_solver.hpp"
#include "quad/generate_quad.hpp"
#include "quad/quad_analysis.hpp"
#include "quad/quad_scheme_loader.hpp"
#include "quad/quad_table_json.hpp"
#include "quad/quad_table_verify.hpp"
#include "triangle/generate_triangle.hpp"
#include "triangle/triangle_analysis.hpp"
#include "triangle/triangle_scheme_loader.hpp"
#include "triangle/triangle_table.hpp"

namespace {

int run_generate(const std::string& scheme_spec, const std::string& rates_spec, const std::string& out,
                 const std::vector<std::string>& params, const std::string& route, bool quiet) {
  const auto rates = sg::parse_rate_spec(rates_spec);
  const sg::CurveScheme scheme = sg::load_curve_scheme(scheme_spec, params);
  const sg::RouteChoice choice = route == "residue" ? sg::RouteChoice::Residue
                                 : route == "eigen"  ? sg::RouteChoice::Eigen
                                                     : sg::RouteChoice::Both;
  const auto start = std::chrono::steady_clock::now();
  auto progress = [&](const std::string& line) {
    if (!quiet) std::cerr << line << "\n";
  };
  const auto tables = sg::generate_curve_tables(scheme, rates, choice, progress);
  sg::write_curve_tables(scheme, tables, out);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "wrote " << tables.size() << " exact tables (JSON + binary) for '" << scheme.name << "' to "
            << (std::filesystem::path(out) / scheme.name).string() << " in " << secs << " s\n";
  return 0;
}

std::vector<int> parse_valences(const std::string& spec) {
  // Unlike --n, a single number means that one valence, not 1..N.
  const bool single = !spec.empty() && spec.find_first_not_of("0123456789") == std::string::npos;
  std::vector<int> valences;
  for (long v : sg::parse_rate_spec(single ? spec + "," + spec : spec, "--valence")) {
    if (v < 3) throw sg::Error("--valence: valences start at 3, got " + std::to_string(v));
    valences.push_back(static_cast<int>(v));
  }
  return valences;
}

int run_generate_quad(const std::string& scheme_spec, const std::string& rates_spec, const std::string& valence_spec,
                         const std::string& out, const std::vector<std::string>& params, const std::string& precision,
                         bool quiet) {
  const auto rates = sg::parse_rate_spec(rates_spec);
  const auto valences = parse_valences(valence_spec);
  const sg::QuadScheme scheme = sg::load_quad_scheme(scheme_spec, params);
  const auto start = std::chrono::steady_clock::now();
  for (int v : valences) {
    scheme.vertex_rule(v);
    const sg::SmoothnessReport report = sg::analyse_quad_valence(scheme, v, 16);
    if (!report.ok())
      std::cerr << "stencilgen: warning: '" << scheme.name << "' fails the smoothness analysis at valence " << v
                << " (tables are still exact; see `stencilgen analyze`):\n"
                << sg::format_report(report);
  }
  auto progress = [&](const std::string& line) {
    if (!quiet) std::cerr << line << "\n";
  };
  const auto set = sg::generate_quad_tables(scheme, valences, rates, progress);
  const std::size_t bytes = sg::write_quad_tables(
      scheme, set, out, precision == "single" ? sg::BinaryPrecision::Single : sg::BinaryPrecision::Double);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "wrote exact surface tables for '" << scheme.name << "' (valences " << valence_spec << ", rates "
            << rates.front() << ".." << rates.back() << ", " << rates.size() * valences.size() << " tables) to "
            << (std::filesystem::path(out) / scheme.name).string() << " in " << secs << " s; binary "
            << scheme.name << ".sgs: " << bytes << " bytes (" << precision << " precision)\n";
  return 0;
}

int run_generate_triangle(const std::string& scheme_spec, const std::string& rates_spec, const std::string& valence_spec,
                          const std::string& out, const std::vector<std::string>& params, const std::string& precision,
                          bool quiet) {
  const auto rates = sg::parse_rate_spec(rates_spec);
  auto valences = parse_valences(valence_spec);
  const sg::TriangleScheme scheme = sg::load_triangle_scheme(scheme_spec, params);
  // Valence 6 is the regular patch, which the runtime needs for every ordinary triangle.
  if (std::find(valences.begin(), valences.end(), 6) == valences.end()) valences.push_back(6);
  std::sort(valences.begin(), valences.end());
  const auto start = std::chrono::steady_clock::now();
  auto progress = [&](const std::string& line) {
    if (!quiet) std::cerr << line << "\n";
  };
  const auto set = sg::generate_triangle_tables(scheme, valences, rates, progress);
  const std::size_t bytes = sg::write_triangle_tables(
      scheme, set, out, precision == "single" ? sg::BinaryPrecision::Single : sg::BinaryPrecision::Double);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::string exact, approx;
  for (int v : valences) (scheme.exact_neighbour_weight(v) ? exact : approx) += (std::to_string(v) + " ");
  std::cout << "wrote triangle tables for '" << scheme.name << "' (valences " << valence_spec << " and 6, rates "
            << rates.front() << ".." << rates.back() << ", " << rates.size() * valences.size() << " tables) to "
            << (std::filesystem::path(out) / scheme.name).string() << " in " << secs << " s; exact at valences "
            << (exact.empty() ? "none " : exact) << "; high precision (" << sg::kRealDigits << " digits, not exact) at "
            << (approx.empty() ? "none " : approx) << "; binary " << scheme.name << ".sgt: " << bytes << " bytes ("
            << precision << " precision)\n";
  return 0;
}

int run_analyze(const std::string& scheme_spec, const std::string& valence_spec, const std::vector<std::string>& params,
                long samples) {
  if (sg::scheme_type(scheme_spec) == "triangle") {
    const sg::TriangleScheme scheme = sg::load_triangle_scheme(scheme_spec, params);
    int failed = 0;
    std::cout << "smoothness analysis of '" << scheme.name << "' (" << scheme.source << ")"
              << (scheme.refinement == sg::TriangleRefinement::Sqrt3
                      ? "; spectra of two composed steps (one step's moduli are their square roots)"
                      : "")
              << "\n";
    for (int v : parse_valences(valence_spec)) {
      const sg::SmoothnessReport r = sg::analyse_triangle_valence(scheme, v, samples);
      if (!r.ok()) ++failed;
      std::cout << sg::format_report(r);
    }
    std::cout << (failed == 0 ? "all valences pass\n" : std::to_string(failed) + " valence(s) FAIL\n");
    return failed == 0 ? 0 : 1;
  }
  const sg::QuadScheme scheme = sg::load_quad_scheme(scheme_spec, params);
  int failed = 0;
  std::cout << "smoothness analysis of '" << scheme.name << "' (" << scheme.source << ")\n";
  for (int v : parse_valences(valence_spec)) {
    scheme.vertex_rule(v);
    const sg::SmoothnessReport r = sg::analyse_quad_valence(scheme, v, samples);
    if (!r.ok()) ++failed;
    std::cout << sg::format_report(r);
  }
  std::cout << (failed == 0 ? "all valences pass\n" : std::to_string(failed) + " valence(s) FAIL\n");
  return failed == 0 ? 0 : 1;
}

int run_verify(const std::vector<std::string>& files, const std::string& scheme_spec,
               const std::vector<std::string>& params) {
  int bad = 0;
  for (const std::string& file : files) {
    const std::string text = sg::read_file(file);
    if (sg::table_format(text) == sg::kTriangleTableFormat) {
      // Re-solve the table and compare the serialised result byte for byte.
      const nlohmann::json doc = nlohmann::json::parse(text);
      std::vector<std::string> overrides = params;
      if (overrides.empty())
        for (const auto& [k, v] : doc.at("parameters").items()) overrides.push_back(k + "=" + v.get<std::string>());
      const sg::TriangleScheme scheme =
          sg::load_triangle_scheme(scheme_spec.empty() ? doc.at("scheme").get<std::string>() : scheme_spec, overrides);
      const int v = doc.at("valence").get<int>();
      const long n = doc.at("n").get<long>();
      const sg::TriangleTable fresh = sg::solve_triangle_table(scheme, v, n, sg::solve_regular(scheme, 3 * n));
      if (sg::triangle_table_to_json(fresh) == text) {
        std::cout << file << ": OK (" << scheme.name << " triangle table, valence " << v << ", n = " << n << "; "
                  << (fresh.exact ? "exact" : "high precision") << "; equal to the re-solved table in every digit)\n";
      } else {
        ++bad;
        std::cout << file << ": FAIL: differs from the re-solved table (scheme '" << scheme.name << "', valence " << v
                  << ", n = " << n << ")\n";
      }
      continue;
    }
    if (sg::table_format(text) == sg::kQuadTableFormat) {
      const std::string name = nlohmann::json::parse(text).value("scheme", "");
      std::vector<std::string> overrides = params;
      if (overrides.empty())
        for (const auto& [k, v] : nlohmann::json::parse(text).at("parameters").items())
          overrides.push_back(k + "=" + v.get<std::string>());
      const sg::QuadScheme scheme = sg::load_quad_scheme(scheme_spec.empty() ? name : scheme_spec, overrides);
      const auto failures = sg::verify_quad_table_json(text, file, scheme);
      if (failures.empty())
        std::cout << file << ": OK (" << scheme.name << " surface; every stencil equals the re-solved one exactly)\n";
      else
        ++bad;
      for (const auto& f : failures) std::cout << file << ": FAIL: " << f << "\n";
      continue;
    }
    const sg::CurveTable table = sg::curve_table_from_json(text, file);
    std::vector<std::string> overrides = params;
    if (overrides.empty())
      for (const auto& [k, v] : table.parameters) overrides.push_back(k + "=" + sg::to_string(v));
    const sg::CurveScheme scheme = sg::load_curve_scheme(scheme_spec.empty() ? table.scheme : scheme_spec, overrides);
    const auto failures = sg::verify_curve_table(table, scheme);
    if (failures.empty()) {
      std::size_t values = 0;
      for (const auto& f : table.functions) values += f.values.size();
      std::cout << file << ": OK (" << table.scheme << ", n = " << table.n << ", " << values
                << " exact values; scaling relations, partition of unity and symmetry hold exactly)\n";
    } else {
      ++bad;
      for (const auto& f : failures) std::cout << file << ": FAIL: " << f << "\n";
    }
  }
  return bad == 0 ? 0 : 1;
}

int run_plot(const std::string& scheme_spec, long n, const std::string& out, const std::vector<std::string>& params) {
  if (n < 1) throw sg::Error("--n must be at least 1, got " + std::to_string(n));
  const sg::CurveScheme scheme = sg::load_curve_scheme(scheme_spec, params);
  const sg::CurveTable table = sg::make_table(scheme, sg::solve_by_residues(scheme, n));
  const std::filesystem::path path(out);
  sg::OutputTransaction tx(path.has_parent_path() ? path.parent_path() : std::filesystem::path("."));
  tx.add(path.filename().string(), sg::plot_table_svg(table));
  tx.commit();
  std::cout << "wrote " << out << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "stencilgen: exact evaluation stencils for stationary subdivision schemes.\n"
      "Solves the scaling relations of a scheme (described as data in schemes/*.json) exactly on the\n"
      "grid (1/n)Z, by two independent routes, verifies the result, and writes exact JSON tables plus a\n"
      "compact binary form.\n\n"
      "Surface schemes (type \"quad\": nonpoly, catmull-clark; type \"triangle\": loop, sqrt3) get tables around\n"
      "extraordinary vertices of the given valences. Triangle schemes are exact where their weights are rational\n"
      "(e.g. valences 3, 4, 6) and solved in high precision (80 digits, residual reported) elsewhere.\n\n"
      "  stencilgen --scheme nonpoly --valence 3-8 --n 24 --out tables\n"
      "  stencilgen --scheme sqrt3 --valence 3-8 --n 24 --out tables\n"
      "  stencilgen analyze --scheme nonpoly --valence 3-16\n"
      "  stencilgen --scheme fourpoint --n 24 --out tables     rates 1..24\n"
      "  stencilgen --scheme nubspline3 --n 12-24 --out tables\n"
      "  stencilgen --scheme fourpoint --param w=1/32 --n 3,5,7 --out tables\n"
      "  stencilgen verify tables/fourpoint/n3.json\n"
      "  stencilgen plot --scheme fourpoint --n 21 --out fourpoint.svg\n"
      "  stencilgen list"};
  app.require_subcommand(0, 1);
  std::string scheme, rates, out, route = "both";
  std::vector<std::string> params;
  bool quiet = false;
  app.add_option("--scheme", scheme, "scheme name (a file in the schemes directory) or path to a scheme .json");
  app.add_option("-n,--n", rates, "rates: N (every rate 1..N), A-B (a range) or a list like 3,5,7");
  app.add_option("--out", out, "output directory; tables go to OUT/<scheme>/n<N>.json and .sgc");
  app.add_option("--param", params, "override a scheme parameter, NAME=RATIONAL (e.g. w=1/32); repeatable");
  app.add_option("--route", route, "solver: residue (a), eigen (b) or both, cross-checked (default)")
      ->check(CLI::IsMember({"residue", "eigen", "both"}));
  app.add_flag("-q,--quiet", quiet, "no progress lines on stderr");
  std::string valences, precision = "double";
  app.add_option("--valence", valences, "surface schemes: valences, e.g. 3-8, 5 or 3,5,6 (default 3-8)");
  app.add_option("--binary-precision", precision, "surface schemes: scalars of the .sgs/.sgt file, double (default) or single")
      ->check(CLI::IsMember({"double", "single"}));

  CLI::App* analyze = app.add_subcommand("analyze", "smoothness analysis of a surface scheme's extraordinary rules");
  std::string analyze_scheme, analyze_valences = "3-16";
  std::vector<std::string> analyze_params;
  long analyze_samples = 32;
  analyze->add_option("--scheme", analyze_scheme, "surface scheme name or path")->required();
  analyze->add_option("--valence", analyze_valences, "valences, e.g. 3-16 (default)");
  analyze->add_option("--samples", analyze_samples, "characteristic map sampled on the grid 1/S per sector (default 32)")
      ->check(CLI::Range(2, 512));
  analyze->add_option("--param", analyze_params, "parameter overrides NAME=RATIONAL");

  CLI::App* verify = app.add_subcommand("verify", "re-check curve or surface tables from disk exactly against their scheme");
  std::vector<std::string> verify_files;
  std::string verify_scheme;
  std::vector<std::string> verify_params;
  verify->add_option("tables", verify_files, "JSON table files")->required();
  verify->add_option("--scheme", verify_scheme, "scheme to check against (default: the one named in the table)");
  verify->add_option("--param", verify_params, "parameter overrides (default: those recorded in the table)");

  CLI::App* plot = app.add_subcommand("plot", "draw the scaling functions of a scheme at rate n as SVG");
  std::string plot_scheme, plot_out;
  long plot_n = 0;
  std::vector<std::string> plot_params;
  plot->add_option("--scheme", plot_scheme, "scheme name or path")->required();
  plot->add_option("-n,--n", plot_n, "rate n (one value)")->required();
  plot->add_option("--out", plot_out, "output .svg file")->required();
  plot->add_option("--param", plot_params, "parameter overrides NAME=RATIONAL");

  CLI::App* list = app.add_subcommand("list", "list the schemes in the schemes directory");

  CLI11_PARSE(app, argc, argv);
  try {
    if (verify->parsed()) return run_verify(verify_files, verify_scheme, verify_params);
    if (analyze->parsed()) return run_analyze(analyze_scheme, analyze_valences, analyze_params, analyze_samples);
    if (plot->parsed()) return run_plot(plot_scheme, plot_n, plot_out, plot_params);
    if (list->parsed()) {
      std::cout << "schemes in " << sg::default_schemes_dir().string() << ":\n";
      for (const auto& name : sg::available_schemes(sg::default_schemes_dir(), sg::SchemeFamily::Curve))
        std::cout << "  " << name << " (curve)\n";
      for (const auto& name : sg::available_schemes(sg::default_schemes_dir(), sg::SchemeFamily::Quad))
        std::cout << "  " << name << " (quad surface)\n";
      for (const auto& name : sg::available_schemes(sg::default_schemes_dir(), sg::SchemeFamily::Triangle))
        std::cout << "  " << name << " (triangle surface)\n";
      return 0;
    }
    if (scheme.empty() || rates.empty() || out.empty()) {
      std::cerr << "stencilgen: error: generation needs --scheme, --n and --out (see --help)\n";
      return 2;
    }
    const std::string type = sg::scheme_type(scheme);
    if (type == "quad")
      return run_generate_quad(scheme, rates, valences.empty() ? "3-8" : valences, out, params, precision, quiet);
    if (type == "triangle")
      return run_generate_triangle(scheme, rates, valences.empty() ? "3-8" : valences, out, params, precision, quiet);
    if (!valences.empty()) throw sg::Error("--valence applies to surface schemes; '" + scheme + "' is a curve scheme");
    return run_generate(scheme, rates, out, params, route, quiet);
  } catch (const sg::Error& e) {
    std::cerr << "stencilgen: error: " << e.what() << "\n";
    return 1;
  }
}
