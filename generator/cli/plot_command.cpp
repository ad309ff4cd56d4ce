// stencilgen plot --scheme S --n N --out FILE.svg: the scaling functions of a curve scheme at rate n.
#include <cctype>
#include <filesystem>
#include <iostream>

#include "base/error.hpp"
#include "base/limits.hpp"
#include "cli/commands.hpp"
#include "common/atomic_output.hpp"
#include "curve/curve_scheme_loader.hpp"
#include "curve/curve_table.hpp"
#include "curve/plot_svg.hpp"
#include "curve/residue_solver.hpp"

namespace sg::cli {

int plot(const std::string& scheme_spec, long n, const std::string& out, const std::vector<std::string>& params) {
  if (n < 1 || n > limits::kMaxCurveRate)
    throw Error("plot --n " + std::to_string(n) + " is outside 1.." + std::to_string(limits::kMaxCurveRate) +
                " (the largest rate for curve schemes)");
  std::string extension = std::filesystem::path(out).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension != ".svg") throw Error(out + ": plot --out must end in .svg (either case)");
  const CurveScheme scheme = load_curve_scheme(scheme_spec, params);
  {
    std::error_code ea, eb;
    if (std::filesystem::weakly_canonical(out, ea) == std::filesystem::weakly_canonical(scheme.source, eb) && !ea && !eb)
      throw Error(out + " is the scheme file and the output; give the output another name");
  }
  const CurveTable table = make_table(scheme, solve_by_residues(scheme, n));
  write_file_atomically(out, plot_table_svg(table));
  std::cout << "wrote " << out << "\n";
  return 0;
}

}  // namespace sg::cli
