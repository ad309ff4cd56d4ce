// stencilgen: exact evaluation stencils for stationary subdivision schemes.
// The command line (CLI11) and the error boundary; each command is in its own file.
#include <CLI/CLI.hpp>
#include <iostream>

#include "base/error.hpp"
#include "base/limits.hpp"
#include "cli/commands.hpp"

namespace {

// `--out ""` and the like: an empty value is never meant (the runtime's tools
// refuse it the same way; the two layers share no code).
void check_no_empty_values(const CLI::App& app) {
  for (const CLI::Option* o : app.get_options())
    if (o->get_type_size_max() > 0)
      for (const std::string& value : o->results())
        if (value.empty()) throw CLI::ValidationError(o->get_name() + ": an empty value");
  for (const CLI::App* sub : app.get_subcommands()) check_no_empty_values(*sub);
}

int run(int argc, char** argv) {
  CLI::App app{
      "stencilgen: exact evaluation stencils for stationary subdivision schemes.\n"
      "Solves the scaling relations of a scheme (described as data in schemes/*.json) exactly on the\n"
      "grid (1/n)Z, by two independent routes, verifies the result, and writes exact JSON tables plus a\n"
      "compact binary form.\n\n"
      "Surface schemes (type \"quad\": nonpoly, catmull-clark; type \"triangle\": loop, sqrt3) get tables around\n"
      "extraordinary vertices of the given valences; quad schemes also get, up to the largest valence V, the\n"
      "patches at boundary vertices in 1..V faces, at corners, at darts and at cone points (what a mesh's\n"
      "boundaries and infinitely sharp creases and corners need); Loop likewise gets, in its binary tables and\n"
      "exactly in OUT/loop/sectors.json, the patches at boundary vertices in 1..V faces, at corners, at darts and\n"
      "at cone points. Triangle schemes are exact where their weights are rational (e.g. valences 3, 4, 6) and\n"
      "solved in high precision (80 digits, residual reported or, for Loop's darts, checked below 1e-60) elsewhere.\n\n"
      "  stencilgen --scheme nonpoly --valence 3-8 --n 24 --out tables\n"
      "  stencilgen --scheme sqrt3 --valence 3-8 --n 24 --out tables\n"
      "  stencilgen analyze --scheme nonpoly --valence 3-16\n"
      "  stencilgen --scheme fourpoint --n 24 --out tables     rates 1..24\n"
      "  stencilgen --scheme nubspline3 --n 12-24 --out tables\n"
      "  stencilgen --scheme fourpoint --param w=1/32 --n 3,5,7 --out tables\n"
      "  stencilgen verify tables/fourpoint/n3.json\n"
      "  stencilgen verify tables/loop/sectors.json\n"
      "  stencilgen plot --scheme fourpoint --n 21 --out fourpoint.svg\n"
      "  stencilgen list"};
  app.require_subcommand(0, 1);
  sg::cli::GenerateOptions gen;
  app.add_option("--scheme", gen.scheme, "scheme name (a file in the schemes directory) or path to a scheme .json");
  app.add_option("-n,--n", gen.rates, "rates: N (every rate 1..N), A-B (a range) or a list like 3,5,7");
  app.add_option("--out", gen.out, "output directory; tables go to OUT/<scheme>/n<N>.json and .sgc");
  app.add_option("--param", gen.params, "override a scheme parameter, NAME=RATIONAL (e.g. w=1/32); repeatable");
  app.add_option("--route", gen.route, "curve schemes: solver residue (a), eigen (b) or both, cross-checked (default)")
      ->check(CLI::IsMember({"residue", "eigen", "both"}));
  app.add_flag("-q,--quiet", gen.quiet, "no progress lines on stderr");
  app.add_option("--valence", gen.valences, "surface schemes: valences, e.g. 3-8, 5 or 3,5,6 (default 3-8)");
  app.add_option("--binary-precision", gen.precision, "surface schemes: scalars of the .sgs/.sgt file, double (default) or single")
      ->check(CLI::IsMember({"double", "single"}));
  app.add_option("--binary-layout", gen.layout,
                 "quad schemes: generated (default): the .sgs holds what generates the stencils (patch subdivision, "
                 "regular values, limit stencil) and the runtime expands them when it loads the file (stored instead "
                 "where that would exceed the runtime's limit); stored: every stencil (larger file, no work at load)")
      ->check(CLI::IsMember({"generated", "stored"}));

  CLI::App* analyze = app.add_subcommand("analyze", "smoothness analysis of a surface scheme's extraordinary rules");
  std::string analyze_scheme, analyze_valences = "3-16";
  std::vector<std::string> analyze_params;
  long analyze_samples = 32;
  analyze->add_option("--scheme", analyze_scheme, "surface scheme name or path")->required();
  analyze->add_option("--valence", analyze_valences, "valences, e.g. 3-16 (default)");
  analyze->add_option("--samples", analyze_samples, "characteristic map sampled on the grid 1/S per sector (default 32)")
      ->check(CLI::Range(2L, sg::limits::kMaxAnalysisSamples));
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

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help
    return app.exit(e);
  }
  check_no_empty_values(app);
  if (verify->parsed()) return sg::cli::verify(verify_files, verify_scheme, verify_params);
  if (analyze->parsed()) return sg::cli::analyze(analyze_scheme, analyze_valences, analyze_params, analyze_samples);
  if (plot->parsed()) return sg::cli::plot(plot_scheme, plot_n, plot_out, plot_params);
  if (list->parsed()) return sg::cli::list();
  if (gen.scheme.empty() || gen.rates.empty() || gen.out.empty())
    throw sg::Error("generation needs --scheme, --n and --out (see --help)");
  return sg::cli::generate(gen);
}

// The one error boundary: every failure becomes one line on stderr and exit code 1.
int fail(const std::string& message) {
  std::string line = message;
  for (char& c : line)
    if (c == '\n' || c == '\r') c = ' ';
  std::cerr << "stencilgen: error: " << line << "\n";
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const CLI::ParseError& e) {
    return fail(std::string(e.what()) + " (see --help)");
  } catch (const sg::Error& e) {
    return fail(e.what());
  } catch (const std::bad_alloc&) {
    return fail("out of memory");
  } catch (const std::exception& e) {  // a library's exception that no reading site turned into an sg::Error
    return fail(std::string("unexpected failure: ") + e.what());
  } catch (...) {
    return fail("unexpected failure of an unknown kind");
  }
}
