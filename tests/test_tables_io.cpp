// Exact JSON round trip, and the binary form through the runtime's loader.
#include <catch2/catch.hpp>
#include <fstream>
#include <sys/wait.h>
#include <unistd.h>

#include "cli.hpp"
#include "curve/curve_scheme_loader.hpp"
#include "curve/curve_table.hpp"
#include "curve/curve_table_binary.hpp"
#include "curve/curve_table_json.hpp"
#include "curve/residue_solver.hpp"
#include "stencil_runtime/curve_table.hpp"

namespace fs = std::filesystem;

namespace {
// Solves `s` at rate n exactly and writes its binary table to `file`; returns the exact table.
sg::CurveTable write_binary_table(const sg::CurveScheme& s, long n, const fs::path& file) {
  sg::CurveTable t = sg::make_table(s, sg::solve_by_residues(s, n));
  std::ofstream(file, std::ios::binary) << sg::curve_table_to_binary(t, s.hash);
  return t;
}
}  // namespace

TEST_CASE("JSON tables round-trip exactly, for uniform and non-uniform schemes") {
  for (const std::string name : {"fourpoint", "nubspline3", "ternary-dd4"}) {
    const sg::CurveScheme s = sg::load_curve_scheme(name);
    const sg::CurveTable t = sg::make_table(s, sg::solve_by_residues(s, 7));
    const sg::CurveTable back = sg::curve_table_from_json(sg::curve_table_to_json(t), "memory");
    REQUIRE(back.functions.size() == t.functions.size());
    CHECK(sg::table_to_solution(back, s) == sg::table_to_solution(t, s));
    CHECK(back.scheme_hash == t.scheme_hash);
  }
}

TEST_CASE("the runtime loads binary tables whose values are the exact ones rounded to double") {
  const fs::path dir = scratch_dir("binary");
  const sg::CurveScheme s = sg::load_curve_scheme("nubspline3");
  const fs::path file = dir / "n24.sgc";
  const sg::CurveTable t = write_binary_table(s, 24, file);

  const auto loaded = stencil_runtime::load_curve_table(file.string(), s.hash);
  CHECK(loaded.n == 24);
  CHECK(loaded.arity == 2);
  REQUIRE(loaded.functions.size() == t.functions.size());
  for (std::size_t h = 0; h < t.functions.size(); ++h) {
    CHECK(loaded.functions[h].name == t.functions[h].name);
    for (long k = -200; k <= 200; ++k) {
      const auto it = t.functions[h].values.find(k);
      const double expected = it == t.functions[h].values.end() ? 0.0 : sg::to_double(it->second);
      REQUIRE(loaded.functions[h].at(k) == expected);
    }
  }

  // Damage: a flipped byte, a truncation, another scheme's hash, a missing file.
  std::string bytes;
  {
    std::ifstream in(file, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  std::string flipped = bytes;
  flipped[40] ^= 0x10;
  std::ofstream(dir / "flipped.sgc", std::ios::binary) << flipped;
  CHECK_THROWS_WITH(stencil_runtime::load_curve_table((dir / "flipped.sgc").string()), Catch::Contains("checksum"));
  std::ofstream(dir / "short.sgc", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  CHECK_THROWS_WITH(stencil_runtime::load_curve_table((dir / "short.sgc").string()), Catch::Contains("short.sgc"));
  std::ofstream(dir / "tiny.sgc", std::ios::binary) << bytes.substr(0, 5);
  CHECK_THROWS_WITH(stencil_runtime::load_curve_table((dir / "tiny.sgc").string()), Catch::Contains("truncated"));
  CHECK_THROWS_WITH(stencil_runtime::load_curve_table(file.string(), s.hash ^ 1), Catch::Contains("different scheme"));
  CHECK_THROWS_WITH(stencil_runtime::load_curve_table((dir / "none.sgc").string()), Catch::Contains("cannot open"));
  fs::remove_all(dir);
}

TEST_CASE("a runtime curve evaluation from binary tables reproduces the exact limit point") {
  const fs::path dir = scratch_dir("evalcurve");
  const sg::CurveScheme s = sg::load_curve_scheme("dd6");
  const fs::path file = dir / "n5.sgc";
  write_binary_table(s, 5, file);
  const auto table = stencil_runtime::load_curve_table(file.string());
  // Control points p_j = j^5 are reproduced by DD6 (degree-5 exactness): the limit at x is x^5.
  std::vector<double> points;
  for (int j = 0; j <= 20; ++j) points.push_back(std::pow(j, 5));
  for (long k = 30; k <= 70; ++k) {  // away from the ends of the finite control polygon
    const double x = static_cast<double>(k) / 5.0;
    CHECK(stencil_runtime::evaluate_uniform_curve(table, points, k) == Approx(std::pow(x, 5)).epsilon(1e-12));
  }
  fs::remove_all(dir);
}
