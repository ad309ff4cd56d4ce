// Exact JSON round trip, and the binary form through the runtime's loader.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <cmath>
#include <iterator>
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

TEST_CASE("binary curve tables carry the exact derivatives rounded, as many orders as the JSON") {
  const fs::path dir = scratch_dir("binary-derivatives");
  // Orders: bspline3 and dd6 two, fourpoint, nonpoly-curve and the non-uniform nubspline3 (five functions) one, bspline1 none.
  for (const std::string name : {"bspline3", "dd6", "fourpoint", "nonpoly-curve", "bspline1", "nubspline3"}) {
    INFO(name);
    REQUIRE(run_stencilgen("--scheme " + name + " --n 6 --out " + dir.string() + " -q").status == 0);
    const fs::path stem = dir / name / "n6";
    std::ifstream in(stem.string() + ".json");
    const sg::CurveTable exact = sg::curve_table_from_json(std::string(std::istreambuf_iterator<char>(in), {}), "n6.json");
    const auto loaded = stencil_runtime::load_curve_table(stem.string() + ".sgc");
    REQUIRE(loaded.derivative_orders == static_cast<std::uint32_t>(exact.derivative_orders));
    CHECK(loaded.derivative_orders == (name == "bspline3" || name == "dd6" ? 2u : name == "bspline1" ? 0u : 1u));
    for (std::size_t h = 0; h < exact.functions.size(); ++h)
      for (int r = 1; r <= exact.derivative_orders; ++r) {
        const auto& d = exact.functions[h].derivatives[static_cast<std::size_t>(r - 1)];
        for (long k = -60; k <= 60; ++k) {
          const auto it = d.find(k);
          REQUIRE(loaded.functions[h].derivatives[static_cast<std::size_t>(r - 1)].at(k) ==
                  (it == d.end() ? 0.0 : sg::to_double(it->second)));
        }
      }
  }
  fs::remove_all(dir);
}

TEST_CASE("a runtime curve derivative from binary tables is the derivative of the reproduced polynomial") {
  const fs::path dir = scratch_dir("evalcurve-derivative");
  // DD6 reproduces x^5 from p_j = j^5: the derivatives of its limit are 5 x^4 and 20 x^3.
  REQUIRE(run_stencilgen("--scheme dd6 --n 5 --out " + dir.string() + " -q").status == 0);
  const auto table = stencil_runtime::load_curve_table((dir / "dd6" / "n5.sgc").string());
  std::vector<double> points;
  for (int j = 0; j <= 20; ++j) points.push_back(std::pow(j, 5));
  for (long k = 30; k <= 70; ++k) {
    const double x = static_cast<double>(k) / 5.0;
    CHECK(stencil_runtime::evaluate_uniform_curve_derivative(table, points, k, 1) == Approx(5 * std::pow(x, 4)).epsilon(1e-12));
    CHECK(stencil_runtime::evaluate_uniform_curve_derivative(table, points, k, 2) == Approx(20 * std::pow(x, 3)).epsilon(1e-11));
  }
  // The four-point scheme is C1 only: no second derivative.
  REQUIRE(run_stencilgen("--scheme fourpoint --n 5 --out " + dir.string() + " -q").status == 0);
  const auto four = stencil_runtime::load_curve_table((dir / "fourpoint" / "n5.sgc").string());
  CHECK_THROWS_WITH(stencil_runtime::evaluate_uniform_curve_derivative(four, points, 40, 2),
                    Catch::Contains("derivatives of order 1..1 only, not 2"));
  fs::remove_all(dir);
}

TEST_CASE("verify refuses a curve table whose functions are placed elsewhere than the scheme's") {
  // A non-uniform table with a function moved or its placement swapped still
  // satisfies its own relations; it describes another curve all the same.
  const fs::path dir = scratch_dir("curve-placement");
  REQUIRE(run_stencilgen("-q --scheme nubspline3 --n 3 --out " + dir.string()).status == 0);
  const fs::path file = dir / "nubspline3" / "n3.json";
  std::ifstream in(file);
  const nlohmann::ordered_json good = nlohmann::ordered_json::parse(in);
  REQUIRE(run_stencilgen("verify " + file.string()).status == 0);
  for (int change = 0; change < 2; ++change) {
    nlohmann::ordered_json bad = good;
    if (change == 0) bad["functions"][3]["position"] = 5;
    else std::swap(bad["functions"][0]["placement"], bad["functions"][1]["placement"]);
    std::ofstream(dir / "bad.json") << bad.dump();
    const CliResult r = run_stencilgen("verify " + (dir / "bad.json").string());
    INFO(r.output);
    CHECK(r.status == 1);
    CHECK(r.output.find(change == 0 ? "functions[3].position" : "functions[0].placement") != std::string::npos);
  }
  fs::remove_all(dir);
}
