// Surface stencils: partition of unity, symmetry, the regular case against the
// tensor product and against Cox-de Boor, the recursion against the paper's
// full system, the smoothness analysis, and the binary tables via the runtime.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <filesystem>
#include <fstream>

#include "cli.hpp"
#include "curve/residue_solver.hpp"
#include "independent.hpp"
#include "quad/direct_patch_solver.hpp"
#include "quad/ev_patch_solver.hpp"
#include "quad/patch_layout.hpp"
#include "quad/quad_analysis.hpp"
#include "quad/quad_scheme_loader.hpp"
#include "tables/quad_tables.hpp"

using independent::Q;

TEST_CASE("surface stencils sum to 1 exactly and are symmetric under (x,y) -> (y,x)", "[surface]") {
  for (const char* name : {"nonpoly", "catmull-clark"}) {
    const sg::QuadScheme s = sg::load_quad_scheme(name);
    for (int v : {3, 5, 8, 13}) {
      const sg::PatchLayout layout(v);
      const auto reflect = layout.reflection();
      for (long g : {7L, 12L, 16L}) {
        const sg::PatchGrid p = sg::solve_ev_patch(s, v, g);
        for (long j = 0; j <= g; ++j)
          for (long i = 0; i <= g; ++i) {
            INFO(name << " v = " << v << " g = " << g << " (" << i << "," << j << ")");
            Q sum = 0;
            for (const auto& w : p.at(i, j)) sum += w;
            REQUIRE(sum == 1);
            // The solver computes i <= j and mirrors; on the diagonal the
            // computed stencil itself must be mirror-symmetric.
            if (i == j)
              for (std::size_t h = 0; h < layout.size(); ++h) REQUIRE(p.at(i, i)[reflect[h]] == p.at(i, i)[h]);
          }
      }
    }
  }
}

TEST_CASE("valence 4 stencils are the tensor product of the curve values", "[surface]") {
  for (const char* name : {"nonpoly", "catmull-clark"}) {
    const sg::QuadScheme s = sg::load_quad_scheme(name);
    const sg::PatchLayout layout(4);
    for (long g = 1; g <= 12; ++g) {
      const sg::CurveSolution c = sg::solve_by_residues(s.curve, g);
      const sg::PatchGrid p = sg::solve_ev_patch(s, 4, g, c);
      for (long j = 0; j <= g; ++j)
        for (long i = 0; i <= g; ++i)
          for (int b = -1; b <= 2; ++b)
            for (int a = -1; a <= 2; ++a) {
              INFO(name << " g = " << g << " (" << i << "," << j << ") point (" << a << "," << b << ")");
              REQUIRE(p.at(i, j)[*layout.chart(a, b)] == c.types[0].at(i - a * g) * c.types[0].at(j - b * g));
            }
    }
  }
}

TEST_CASE("Catmull-Clark regular stencils are bicubic B-spline values (Cox-de Boor)", "[surface]") {
  const sg::QuadScheme s = sg::load_quad_scheme("catmull-clark");
  const sg::PatchLayout layout(4);
  auto knot = [](long k) { return Q(k - 2); };  // the cubic basis of point 0 has knots -2..2
  for (long g : {1L, 3L, 5L, 8L, 11L, 24L}) {
    const sg::PatchGrid p = sg::solve_ev_patch(s, 4, g);
    for (long j = 0; j <= g; ++j)
      for (long i = 0; i <= g; ++i)
        for (int b = -1; b <= 2; ++b)
          for (int a = -1; a <= 2; ++a) {
            const Q want = independent::cox_de_boor(knot, 0, 3, Q(i, g) - a) *
                           independent::cox_de_boor(knot, 0, 3, Q(j, g) - b);
            INFO("g = " << g << " (" << i << "," << j << ") point (" << a << "," << b << ")");
            REQUIRE(p.at(i, j)[*layout.chart(a, b)] == want);
          }
  }
}

TEST_CASE("the recursion equals a direct solve of the full system of scaling relations", "[surface]") {
  struct Case {
    const char* scheme;
    int valence;
    long n;
  };
  for (const Case& c : {Case{"nonpoly", 5, 3}, Case{"nonpoly", 6, 3}, Case{"nonpoly", 3, 4}, Case{"catmull-clark", 5, 3},
                        Case{"catmull-clark", 6, 3}, Case{"catmull-clark", 7, 2}}) {
    const sg::QuadScheme s = sg::load_quad_scheme(c.scheme);
    const sg::PatchGrid recursive = sg::solve_ev_patch(s, c.valence, c.n);
    const sg::PatchGrid direct = sg::solve_ev_patch_directly(s, c.valence, c.n);
    for (long j = 0; j <= c.n; ++j)
      for (long i = 0; i <= c.n; ++i) {
        INFO(c.scheme << " v = " << c.valence << " n = " << c.n << " (" << i << "," << j << ")");
        REQUIRE(recursive.at(i, j) == direct.at(i, j));
      }
  }
}

TEST_CASE("the shipped extraordinary rules pass the smoothness analysis at valences 3..16", "[surface][analysis]") {
  for (const char* name : {"nonpoly", "catmull-clark"}) {
    const sg::QuadScheme s = sg::load_quad_scheme(name);
    for (int v = 3; v <= 16; ++v) {
      const sg::SmoothnessReport r = sg::analyse_quad_valence(s, v, 16);
      INFO(sg::format_report(r));
      REQUIRE(r.ok());
      REQUIRE(r.eigenvalues.size() == static_cast<std::size_t>(6 * v + 1));
    }
  }
  // Known Catmull-Clark subdominant eigenvalues (Reif; Peters-Reif): valence 3 and 5.
  const sg::QuadScheme cc = sg::load_quad_scheme("catmull-clark");
  REQUIRE(sg::analyse_quad_valence(cc, 3, 4).subdominant == Approx(0.410097).margin(1e-6));
  REQUIRE(sg::analyse_quad_valence(cc, 5, 4).subdominant == Approx(0.549988).margin(1e-6));
  // nonpoly: the first Fourier block has trace 7/12 + cos(2 pi/v)/6 and determinant 1/24.
  const sg::QuadScheme np = sg::load_quad_scheme("nonpoly");
  for (int v = 3; v <= 16; ++v) {
    const double t = 7.0 / 12 + std::cos(2 * M_PI / v) / 6;
    REQUIRE(sg::analyse_quad_valence(np, v, 4).subdominant == Approx((t + std::sqrt(t * t - 1.0 / 6)) / 2).margin(1e-9));
  }
}

namespace {
// nonpoly with a vertex rule that is the tensor product at v = 4 but whose
// rotation-invariant eigenvalue overtakes the subdominant one at v = 8.
std::filesystem::path write_bad_scheme(const std::filesystem::path& dir, const std::string& vertex) {
  std::filesystem::copy_file(sg::default_schemes_dir() / "nonpoly-curve.json", dir / "nonpoly-curve.json",
                             std::filesystem::copy_options::overwrite_existing);
  const auto path = dir / "bad.json";
  std::ofstream(path) << R"J({"format": "stencilgen-scheme", "version": 1, "name": "bad", "type": "quad",
    "regular_curve": "nonpoly-curve",
    "rules": {"face": {"corner": "1/4"}, "edge": {"end": "1/3", "wing": "1/12"}, "vertex": )J"
                      << vertex << "}}";
  return path;
}
}  // namespace

TEST_CASE("rules that fail the analysis are reported, and tables are still exact", "[surface][analysis]") {
  const auto dir = scratch_dir("bad-rules");
  const auto path = write_bad_scheme(dir, R"J({"centre": "4/9 + (v-4)/6", "edge": "4/(9*v) - (v-4)/(6*v)", "face": "1/(9*v)"})J");
  const CliResult r = run_stencilgen("analyze --scheme " + path.string() + " --valence 3,5,8");
  CHECK(r.status == 1);
  CHECK(r.output.find("valence 8: FAILS") != std::string::npos);
  CHECK(r.output.find("valence 5: OK") != std::string::npos);
  const CliResult g = run_stencilgen("--scheme " + path.string() + " --valence 8 --n 2 --out " + (dir / "out").string());
  CHECK(g.status == 0);
  CHECK(g.output.find("warning: 'bad' fails the smoothness analysis at valence 8") != std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST_CASE("bad quad scheme input is refused with the file and field named, nothing written", "[surface][errors]") {
  const auto dir = scratch_dir("bad-quad");
  const auto out = dir / "out";
  struct Bad {
    std::string vertex, expect;
  };
  for (const Bad& b : {Bad{R"J({"centre": "1/2", "edge": "1/(4*v)", "face": "1/(4*v)"})J", "rules.vertex.centre: at valence 4"},
                       Bad{R"J({"centre": "4/9", "edge": "4/(9*v)", "face": "1/(9*w)"})J", "unknown name 'w'"},
                       Bad{R"J({"centre": "4/9", "edge": "4/(9*v)", "face": "2/(9*v)"})J", "the weights sum to"}}) {
    const auto path = write_bad_scheme(dir, b.vertex);
    const CliResult r = run_stencilgen("--scheme " + path.string() + " --valence 3-5 --n 4 --out " + out.string());
    INFO(r.output);
    CHECK(r.status == 1);
    CHECK(r.output.find(path.string()) != std::string::npos);
    CHECK(r.output.find(b.expect) != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(out));
  }
  {  // polygon rules that do not reproduce the quad rules on quads
    std::ofstream(dir / "poly.json") << R"J({"format": "stencilgen-scheme", "version": 1, "name": "poly", "type": "quad",
      "regular_curve": "nonpoly-curve",
      "rules": {"face": {"corner": "1/4"}, "edge": {"end": "1/3", "wing": "1/12"}, "vertex": {"centre": "4/9", "edge": "4/(9*v)", "face": "1/(9*v)"}},
      "polygon_rules": {"edge": {"end": "1/6", "face_point": "1/3"}, "vertex": {"centre": "1/9", "edge_midpoint": "5/9", "face_point": "3/9"}}})J";
    const CliResult r = run_stencilgen("analyze --scheme " + (dir / "poly.json").string() + " --valence 3");
    CHECK(r.status == 1);
    CHECK(r.output.find("polygon_rules.vertex: on quads at valence 3 it gives") != std::string::npos);
  }
  const CliResult low = run_stencilgen("--scheme nonpoly --valence 2-5 --n 4 --out " + out.string());
  CHECK(low.status == 1);
  CHECK(low.output.find("valences start at 3") != std::string::npos);
  const CliResult high = run_stencilgen("--scheme nonpoly --valence 65 --n 4 --out " + out.string());
  CHECK(high.status == 1);
  CHECK(high.output.find("65 is above 64, the largest valence") != std::string::npos);
  const CliResult curve = run_stencilgen("--scheme fourpoint --valence 3 --n 4 --out " + out.string());
  CHECK(curve.status == 1);
  CHECK(curve.output.find("--valence applies to surface schemes") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(out));
  std::filesystem::remove_all(dir);
}

TEST_CASE("binary surface tables load in the runtime and hold the exact stencils rounded", "[surface][tables]") {
  // Stored layout: the exact stencils correctly rounded; generated layout (the
  // default): the reader's expansion, within two units of 1e-16.
  const bool stored_layout = GENERATE(true, false);
  INFO((stored_layout ? "stored layout" : "generated layout"));
  const auto dir = scratch_dir("surface-io");
  const CliResult r = run_stencilgen("--scheme nonpoly --valence 3-5 --n 1-6 --out " + dir.string() + " -q" +
                                     (stored_layout ? " --binary-layout stored" : ""));
  REQUIRE(r.status == 0);
  const auto file = (dir / "nonpoly" / "nonpoly.sgs").string();
  const sg::QuadScheme s = sg::load_quad_scheme("nonpoly");
  const auto t = stencil_runtime::QuadTables::load_binary(file, s.hash);
  REQUIRE(t.rates() == std::vector<int>{1, 2, 3, 4, 5, 6});
  REQUIRE(t.valences() == std::vector<int>{3, 5});  // 4 is the regular patch
  for (int v : {3, 4, 5}) {
    const sg::PatchLayout layout(v);
    for (int n = 1; n <= 6; ++n) {
      const sg::PatchGrid exact = sg::solve_ev_patch(s, v, 2 * n);
      std::vector<double> w(static_cast<std::size_t>(stencil_runtime::QuadTables::points(v)));
      auto expect = [&](long a, long b) {
        for (std::size_t h = 0; h < layout.size(); ++h) {
          // The regular patch is stored in row order; map it to the EV layout for v = 4.
          const std::size_t stored = v == 4 ? [&] {
            const auto pos = *layout.position(h);
            return sg::regular_index(pos.first, pos.second);
          }() : h;
          INFO("v = " << v << " n = " << n << " at (" << a << "," << b << ")/" << 2 * n << " point " << h);
          const double margin = v == 4 ? 1e-300 : stored_layout ? 0 : 2.3e-16;
          REQUIRE(w[stored] == Approx(sg::to_double(exact.at(a, b)[h])).epsilon(v == 4 ? 1e-15 : 0).margin(margin));
        }
      };
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
          t.node_stencil(v, n, i, j, w.data());
          expect(2 * i, 2 * j);
          if (i < n && j < n) {
            t.centre_stencil(v, n, i, j, w.data());
            expect(2 * i + 1, 2 * j + 1);
          }
        }
    }
  }
  CHECK_THROWS_AS(stencil_runtime::QuadTables::load_binary(file, s.hash + 1), stencil_runtime::LoadError);
  {
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(100);
    f.put('\x7f');
  }
  CHECK_THROWS_WITH(stencil_runtime::QuadTables::load_binary(file), Catch::Contains("checksum mismatch"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("valence 16 at rate 64 works end to end, with progress output", "[surface][scale]") {
  const auto dir = scratch_dir("surface-scale");
  const CliResult r = run_stencilgen("--scheme nonpoly --valence 3,16 --n 63,64 --out " + dir.string());
  INFO(r.output);
  REQUIRE(r.status == 0);
  CHECK(r.output.find("nonpoly: valence 16 solved and checked for 2 rates") != std::string::npos);
  const auto t = stencil_runtime::QuadTables::load_binary((dir / "nonpoly" / "nonpoly.sgs").string());
  REQUIRE(t.valences() == std::vector<int>{3, 16});
  for (int v : {3, 4, 16})
    for (int n : {63, 64}) {
      std::vector<double> w(static_cast<std::size_t>(stencil_runtime::QuadTables::points(v)));
      for (int j = 0; j <= n; j += 7)
        for (int i = 0; i <= n; i += 5) {
          t.node_stencil(v, n, i, j, w.data());
          double sum = 0;
          for (double x : w) sum += x;
          REQUIRE(sum == Approx(1).epsilon(1e-14));
        }
    }
  std::filesystem::remove_all(dir);
}

TEST_CASE("verify re-solves surface JSON tables and rejects a changed weight", "[surface][tables]") {
  const auto dir = scratch_dir("surface-verify");
  REQUIRE(run_stencilgen("--scheme catmull-clark --valence 5 --n 4 --out " + dir.string() + " -q").status == 0);
  const auto file = dir / "catmull-clark" / "v5" / "n4.json";
  const CliResult ok = run_stencilgen("verify " + file.string());
  INFO(ok.output);
  CHECK(ok.status == 0);
  CHECK(ok.output.find(": OK (catmull-clark surface") != std::string::npos);
  // Move weight between two entries of one stencil: the sum stays 1, the stencil is wrong.
  std::string text;
  {
    std::ifstream in(file);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  const std::string original = text;
  const auto at = text.find("\"at\":[\"1/4\",\"1/2\"]");
  REQUIRE(at != std::string::npos);
  const auto nums = text.find("\"numerators\":[\"", at) + 15;
  const auto end = text.find('"', nums);
  const long first = std::stol(text.substr(nums, end - nums));
  text.replace(nums, end - nums, std::to_string(first + 1));
  const auto second = text.find("\",\"", nums) + 3;
  const auto second_end = text.find('"', second);
  text.replace(second, second_end - second, std::to_string(std::stol(text.substr(second, second_end - second)) - 1));
  std::ofstream(file) << text;
  const CliResult bad = run_stencilgen("verify " + file.string());
  CHECK(bad.status == 1);
  CHECK(bad.output.find("nodes at (1/4, 1/2): differs from the re-solved stencil") != std::string::npos);
  // Fields no stencil check reads: the rules recorded beside the stencils, and the exactness flag.
  std::ofstream(file) << original;
  for (const char* field : {"rules", "exact"}) {
    nlohmann::ordered_json doc = nlohmann::ordered_json::parse(original);
    if (std::string(field) == "exact") doc[field] = !doc[field].get<bool>();
    else doc[field]["edge_end"] = "1/3";
    std::ofstream(file) << doc.dump();
    const CliResult changed = run_stencilgen("verify " + file.string());
    INFO(field << ": " << changed.output);
    CHECK(changed.status == 1);
    CHECK(changed.output.find("differs from the table made again at " + std::string(field)) != std::string::npos);
  }
  std::filesystem::remove_all(dir);
}
