// Triangle-scheme tables through the stencilgen command line: exact and
// high-precision valences flagged as such, partition of unity, the regular
// table's lattice symmetries (120-degree rotation and reflection of the patch
// triangle, checked on the stored JSON), the spectra that `analyze` reports
// against closed forms (Loop 1987; Kobbelt 2000), and bad input.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "algebra/rational.hpp"
#include "cli.hpp"
#include "triangle/triangle_analysis.hpp"
#include "triangle/triangle_scheme_loader.hpp"

using nlohmann::json;
using sg::Rational;

namespace {

json read_json(const std::filesystem::path& p) {
  std::ifstream in(p);
  REQUIRE(in);
  return json::parse(in);
}

// Plain lattice coordinates (sector 0's frame) of a regular (valence 6) layout point.
std::pair<long, long> lattice(const json& p) {
  long s = p[0], a = p[1], b = p[2];
  for (; s > 0; --s) std::tie(a, b) = std::make_pair(a - b, a);  // from sector s into sector s-1
  return {a, b};
}

// Stencils of one entry list, keyed by (i, j), as maps from lattice point to weight.
using Stencil = std::map<std::pair<long, long>, Rational>;
std::map<std::pair<long, long>, Stencil> exact_stencils(const json& t, const char* key) {
  std::map<std::pair<long, long>, Stencil> out;
  const long n = t["n"];
  const long offset = std::string(key) == "nodes" ? 0 : std::string(key) == "up_centres" ? 1 : 2;
  for (const json& e : t[key]) {
    const Rational u = sg::parse_rational(e["at"][0].get<std::string>()), v = sg::parse_rational(e["at"][1].get<std::string>());
    const long i = sg::floor_to_long(u * 3 * n - offset) / 3, j = sg::floor_to_long(v * 3 * n - offset) / 3;
    const Rational den(sg::Integer(e["denominator"].get<std::string>()));
    Stencil s;
    for (std::size_t h = 0; h < t["layout"].size(); ++h)
      s[lattice(t["layout"][h])] = Rational(sg::Integer(e["numerators"][h].get<std::string>())) / den;
    out[{i, j}] = s;
  }
  return out;
}

}  // namespace

TEST_CASE("triangle tables: exact where rational, high precision elsewhere, partition of unity", "[triangle][tables]") {
  const auto dir = scratch_dir("triangle-tables");
  const CliResult r = run_stencilgen("--scheme loop --valence 3-5 --n 1-5 --out " + dir.string());
  INFO(r.output);
  REQUIRE(r.status == 0);
  REQUIRE(r.output.find("exact at valences 3 4 6") != std::string::npos);
  REQUIRE(r.output.find("not exact) at 5") != std::string::npos);
  REQUIRE(std::filesystem::file_size(dir / "loop" / "loop.sgt") > 1000);
  for (int v : {3, 4, 5, 6})
    for (long n = 1; n <= 5; ++n) {
      const json t = read_json(dir / "loop" / ("v" + std::to_string(v) + "/n" + std::to_string(n) + ".json"));
      REQUIRE(t["format"] == "stencilgen-triangle-table");
      REQUIRE(t["exact"] == (v != 5));
      REQUIRE(t["nodes"].size() == static_cast<std::size_t>((n + 1) * (n + 2) / 2));
      REQUIRE(t["up_centres"].size() == static_cast<std::size_t>(n * (n + 1) / 2));
      REQUIRE(t["down_centres"].size() == static_cast<std::size_t>(n * (n - 1) / 2));
      for (const char* key : {"nodes", "up_centres", "down_centres"})
        for (const json& e : t[key]) {
          if (t["exact"]) {
            sg::Integer sum = 0;
            for (const json& x : e["numerators"]) sum += sg::Integer(x.get<std::string>());
            REQUIRE(sum == sg::Integer(e["denominator"].get<std::string>()));
          } else {
            double sum = 0;
            for (const json& x : e["weights"]) sum += std::stod(x.get<std::string>());
            REQUIRE(std::fabs(sum - 1) < 1e-14);
          }
        }
      if (!t["exact"]) REQUIRE(std::stod(t["residual"].get<std::string>()) < 1e-70);
    }
  // verify re-solves a table; a changed digit fails it.
  for (const char* file : {"v4/n5.json", "v5/n3.json"}) {
    const auto path = dir / "loop" / file;
    const CliResult ok = run_stencilgen("verify " + path.string());
    INFO(ok.output);
    REQUIRE(ok.status == 0);
    REQUIRE(ok.output.find(": OK (loop triangle table") != std::string::npos);
    std::stringstream text;
    text << std::ifstream(path).rdbuf();
    std::string changed = text.str();
    const auto at = changed.rfind("\"numerators\":[\"") != std::string::npos ? changed.rfind("\"numerators\":[\"")
                                                                          : changed.rfind("\"weights\":[\"");
    const auto digit = changed.find_first_of("123456789", at);
    changed[digit] = changed[digit] == '9' ? '8' : static_cast<char>(changed[digit] + 1);
    std::ofstream(path) << changed;
    const CliResult bad = run_stencilgen("verify " + path.string());
    INFO(bad.output);
    REQUIRE(bad.status != 0);
    REQUIRE(bad.output.find("FAIL: differs from the re-solved table") != std::string::npos);
    CHECK(bad.output.find(") at ") != std::string::npos);  // and says where
    // The same table re-indented, with a newline more: the same values, so it passes.
    std::ofstream(path) << nlohmann::ordered_json::parse(text.str()).dump(2) << "\n\n";
    const CliResult spaced = run_stencilgen("verify " + path.string());
    INFO(spaced.output);
    CHECK(spaced.status == 0);
  }
}

TEST_CASE("the regular triangle tables are invariant under the patch triangle's rotation and reflection", "[triangle][tables]") {
  const auto dir = scratch_dir("triangle-symmetry");
  for (const char* scheme : {"loop", "sqrt3"}) {
    const CliResult r = run_stencilgen(std::string("--scheme ") + scheme + " --valence 6 --n 4,6 --out " + dir.string());
    INFO(r.output);
    REQUIRE(r.status == 0);
    for (long n : {4, 6}) {
      const json t = read_json(dir / scheme / ("v6/n" + std::to_string(n) + ".json"));
      REQUIRE(t["exact"] == true);
      const auto nodes = exact_stencils(t, "nodes");
      // Rotation by 120 degrees about the centroid (2/3, 1/3): corners 0 -> 1 -> 2,
      // lattice point p -> c + R120 (p - c) with R120 (x, y) = (-y, x - y); in thirds to stay integral.
      auto rotate = [](std::pair<long, long> p) {
        const long x = 3 * p.first - 2, y = 3 * p.second - 1;
        return std::make_pair((-y + 2) / 3, (x - y + 1) / 3);
      };
      auto reflect = [](std::pair<long, long> p) { return std::make_pair(p.first, p.first - p.second); };
      long checked = 0;
      for (const auto& [ij, s] : nodes) {
        const auto [i, j] = ij;
        const Stencil& rotated = nodes.at({n - i - j, i});
        const Stencil& reflected = nodes.at({j, i});
        for (const auto& [p, w] : s) {
          INFO(scheme << " n = " << n << " node (" << i << "," << j << ") point (" << p.first << "," << p.second << ")");
          const auto q = rotate(p);
          REQUIRE((rotated.count(q) ? rotated.at(q) : Rational(0)) == w);
          const auto f = reflect(p);
          REQUIRE((reflected.count(f) ? reflected.at(f) : Rational(0)) == w);
          ++checked;
        }
      }
      REQUIRE(checked > 100);
    }
  }
}

TEST_CASE("analyze reports the published subdominant eigenvalues of Loop and sqrt(3), valences 3..12", "[triangle][analysis]") {
  const sg::TriangleScheme loop = sg::load_triangle_scheme("loop"), sqrt3 = sg::load_triangle_scheme("sqrt3");
  for (int v = 3; v <= 12; ++v) {
    INFO("valence " << v);
    const double c = std::cos(2 * M_PI / v);
    const sg::SmoothnessReport a = sg::analyse_triangle_valence(loop, v, 8);
    REQUIRE(a.ok());
    REQUIRE(std::fabs(a.subdominant - (0.375 + c / 4)) < 1e-10);  // Loop: 3/8 + cos(2 pi / v) / 4
    const sg::SmoothnessReport b = sg::analyse_triangle_valence(sqrt3, v, 6);
    REQUIRE(b.ok());
    REQUIRE(std::fabs(b.subdominant - (2 + 2 * c) / 9) < 1e-10);  // Kobbelt, two steps: (2 + 2 cos(2 pi / v)) / 9
  }
  const CliResult r = run_stencilgen("analyze --scheme loop --valence 3-12 --samples 4");
  REQUIRE(r.status == 0);
  REQUIRE(r.output.find("all valences pass") != std::string::npos);
}

TEST_CASE("bad triangle scheme input is refused with the file and field named, nothing written", "[triangle][errors]") {
  const auto dir = scratch_dir("triangle-errors");
  auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return (dir / name).string();
  };
  const std::string head = R"({"format": "stencilgen-scheme", "version": 1, "name": "bad", "type": "triangle", )";
  const std::string no_refinement = write("a.json", head + R"("rules": {"vertex": {"neighbour": "1/16"}}})");
  const std::string bad_edge =
      write("b.json", head + R"("refinement": "loop", "rules": {"edge": {"end": "3/8", "opposite": "1/4"}, "vertex": {"neighbour": "1/16"}}})");
  const std::string irrational_regular =
      write("c.json", head + R"("refinement": "sqrt3", "rules": {"vertex": {"neighbour": "cos2pi(1/7)/v"}}})");
  const std::string negative = write("d.json", head + R"("refinement": "sqrt3", "rules": {"vertex": {"neighbour": "1/(v-5)/18"}}})");
  // Crease curves: looked up next to the scheme file.
  std::filesystem::copy_file(sg::default_schemes_dir() / "fourpoint.json", dir / "fourpoint.json",
                             std::filesystem::copy_options::overwrite_existing);
  write("lopsided.json", R"({"format": "stencilgen-scheme", "version": 1, "name": "lopsided", "type": "curve-uniform", "arity": 2,
                             "mask": {"first": -2, "coefficients": ["1/8", "5/8", "3/4", "3/8", "1/8"]}})");
  const std::string loop_rules = R"("rules": {"edge": {"end": "3/8", "opposite": "1/8"}, "vertex": {"neighbour": "1/16"}}, "valences": {"min": 3, "max": 12}})";
  const std::string sqrt3_crease =
      write("e.json", head + R"("refinement": "sqrt3", "crease_curve": "bspline3", "rules": {"vertex": {"neighbour": "1/18"}}, "valences": {"min": 3, "max": 12}})");
  const std::string wide_crease = write("f.json", head + R"("refinement": "loop", "crease_curve": "fourpoint", )" + loop_rules);
  const std::string lopsided_crease = write("g.json", head + R"("refinement": "loop", "crease_curve": "lopsided", )" + loop_rules);
  const std::string missing_crease = write("h.json", head + R"("refinement": "loop", "crease_curve": "nowhere", )" + loop_rules);
  const std::pair<std::string, std::string> cases[] = {
      {no_refinement, "missing required field 'refinement'"},
      {bad_edge, "rules.edge: 2 * end + 2 * opposite must be 1"},
      {irrational_regular, "must be rational at the regular valence v = 6"},
      {negative, "rules.vertex.neighbour: at v = 3"},
      {sqrt3_crease, "crease_curve: only schemes with Loop's refinement"},
      {wide_crease, "crease_curve: 'fourpoint' has a mask coefficient at -3"},
      {lopsided_crease, "crease_curve: 'lopsided' must have a symmetric mask"},
      {missing_crease, "crease_curve: "}};
  for (const auto& [file, message] : cases) {
    const auto out = dir / "out";
    const CliResult r = run_stencilgen("--scheme " + file + " --valence 3 --n 2 --out " + out.string());
    INFO(r.output);
    REQUIRE(r.status != 0);
    REQUIRE(r.output.find(file) != std::string::npos);
    REQUIRE(r.output.find(message) != std::string::npos);
    REQUIRE(!std::filesystem::exists(out / "bad"));
  }
  const CliResult big = run_stencilgen("--scheme loop --valence 70 --n 2 --out " + (dir / "out").string());
  REQUIRE(big.status != 0);
  REQUIRE(big.output.find("70 is above 64, the largest valence") != std::string::npos);
}
