// A Loop scheme's sectors.json (the boundary, corner, dart and cone sectors
// as exact JSON): what the binary .sgt holds of them, exact where the rules
// are rational; `stencilgen verify` re-solves it and checks each exact limit
// stencil from the file's own rationals, and fails on a changed weight.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "algebra/rational.hpp"
#include "cli.hpp"
#include "json_files.hpp"
#include "tables/triangle_tables.hpp"

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

namespace {

// A weight as written: "p/q" exact, or 40 digits.
double value(const json& w) {
  const std::string text = w.get<std::string>();
  return text.find('/') != std::string::npos || text.find('e') == std::string::npos ? sg::to_double(sg::parse_rational(text))
                                                                                      : std::stod(text);
}

}  // namespace

TEST_CASE("sectors.json holds Loop's sectors exactly, as the binary tables hold them", "[triangle][sector][tables][verify]") {
  const fs::path dir = scratch_dir("loop-sectors-json");
  REQUIRE(run_stencilgen("--scheme loop --valence 3-8 --n 1-3 -q --out " + dir.string()).status == 0);
  const fs::path file = dir / "loop" / "sectors.json";
  REQUIRE(fs::exists(file));
  const json doc = read_json_file(file);
  CHECK(doc["format"] == "stencilgen-triangle-sectors");
  // Valences up to 8: crease sectors of 1, 2, 4..8 faces, corners of 1..8, darts of valence 3..8, cone points of 3..8.
  const json& sectors = doc["sectors"];
  REQUIRE(sectors.size() == (1 + 2 + 4 + 5 + 6 + 7 + 8) + 36 + (36 - 3) + 6);
  const auto tables = stencil_runtime::TriangleTables::load((dir / "loop" / "loop.sgt").string());
  const char* kinds[] = {"crease", "corner", "dart", "cone"};
  for (const json& s : sectors) {
    const int rule = static_cast<int>(std::find(std::begin(kinds), std::end(kinds), s["kind"].get<std::string>()) - std::begin(kinds));
    REQUIRE(rule < 4);
    const int k = s["faces"], p = s["position"];
    const stencil_runtime::SectorKey key{static_cast<stencil_runtime::SectorRule>(rule), k, p};
    INFO(key.name());
    // Exact where the rules are rational: every kind but darts where Loop's smooth weight is irrational.
    CHECK(s["exact"].get<bool>() == (rule != 2 || k == 3 || k == 4 || k == 6));
    if (!s["exact"].get<bool>()) CHECK(std::stod(s["residual"].get<std::string>()) < 1e-60);
    // The limit stencils known without the solve: the boundary curve's (1/6, 2/3, 1/6) over e_0, B, e_k;
    // a corner and a cone point stay put.
    const json& limit = s["limit"];
    if (rule == 0) {
      for (std::size_t h = 0; h < limit.size(); ++h) {
        const json& at = s["points"][h];
        const bool end = at[2] == 0 && at[1] == 1 && (at[0] == 0 || at[0] == k);
        CHECK(limit[h] == (h == 0 ? "2/3" : end ? "1/6" : "0"));
      }
    } else if (rule == 1 || rule == 3) {
      for (std::size_t h = 0; h < limit.size(); ++h) CHECK(limit[h] == (h == 0 ? "1" : "0"));
    }
    // The binary tables: the same points, the same limit (its node (0, 0)) and tangents, rounded.
    const auto code = tables.sector_code(key);
    REQUIRE(code);
    const auto& layout = tables.layout(*code);
    REQUIRE(layout.size() == s["points"].size());
    REQUIRE(limit.size() == layout.size());
    const double* w = tables.grid(*code, 1).weights(stencil_runtime::TriangleTables::GridPoint::Node, 0, 0);
    for (std::size_t h = 0; h < layout.size(); ++h) {
      CHECK(s["points"][h] == json::array({layout[h].sector, layout[h].a, layout[h].b}));
      CHECK(std::fabs(w[h] - value(limit[h])) < 1e-15);
    }
    const std::vector<double>* u = tables.tangent_u(*code);
    REQUIRE((u != nullptr) == !s["tangents"].is_null());
    if (u)
      for (std::size_t h = 0; h < u->size(); ++h) CHECK(std::fabs((*u)[h] - value(s["tangents"]["u"][h])) < 1e-15);
  }
}

TEST_CASE("stencilgen verify checks sectors.json, and fails on a changed weight", "[triangle][sector][verify]") {
  const fs::path dir = scratch_dir("loop-sectors-verify");
  REQUIRE(run_stencilgen("--scheme loop --valence 3-5 --n 1 -q --out " + dir.string()).status == 0);
  const fs::path file = dir / "loop" / "sectors.json";
  CliResult r = run_stencilgen("verify " + file.string());
  CHECK(r.status == 0);
  CHECK_THAT(r.output, Catch::Contains("OK"));
  const json good = read_json_file(file);
  std::size_t corner = 0;
  while (good["sectors"][corner]["kind"] != "corner") ++corner;

  json bad = good;  // a weight of an exact A0: no longer its fixed point
  bad["sectors"][0]["ev_child"][1][0][1] = "1/3";
  write_json_file(dir / "bad.json", bad);
  r = run_stencilgen("verify " + (dir / "bad.json").string());
  CHECK(r.status == 1);
  CHECK_THAT(r.output, Catch::Contains("not A0's fixed point") && Catch::Contains("differs from the sectors re-solved"));

  bad = good;  // a weight too long to be the generator's: refused by its length, naming it
  bad["sectors"][corner]["limit"][0] = "1/" + std::string(5000, '7');
  write_json_file(dir / "bad.json", bad);
  r = run_stencilgen("verify " + (dir / "bad.json").string());
  CHECK(r.status == 1);
  CHECK_THAT(r.output, Catch::Contains("limit[0]") && Catch::Contains("longer than 4096 characters"));

  bad = good;  // a corner's limit weight
  bad["sectors"][corner]["limit"][0] = "7/8";
  write_json_file(dir / "bad.json", bad);
  r = run_stencilgen("verify " + (dir / "bad.json").string());
  CHECK(r.status == 1);
  CHECK_THAT(r.output, Catch::Contains("sums to 7/8"));

  bad = good;  // one digit of a tangent weight (the 20th significant digit)
  std::string& t = bad["sectors"][0]["tangents"]["u"][1].get_ref<std::string&>();
  const std::size_t digit = t.find('.') + 19;
  REQUIRE(digit < t.size());
  t[digit] = t[digit] == '1' ? '2' : '1';
  write_json_file(dir / "bad.json", bad);
  r = run_stencilgen("verify " + (dir / "bad.json").string());
  CHECK(r.status == 1);
  CHECK_THAT(r.output, Catch::Contains("differs from the sectors re-solved"));

  bad = good;  // regular points taken away with the regular cells: the file's own points are not trusted
  bad["regular_points"] = json::array();
  for (auto& sector : bad["sectors"]) sector["regular_children"] = json::array({json::array(), json::array(), json::array()});
  write_json_file(dir / "bad.json", bad);
  r = run_stencilgen("verify " + (dir / "bad.json").string());
  CHECK(r.status == 1);
  CHECK_THAT(r.output, Catch::Contains("regular_points: not the points of valence 6's patch"));

  bad = good;  // a column out of range is named, not used
  bad["sectors"][0]["ev_child"][0][0][0] = 999;
  write_json_file(dir / "bad.json", bad);
  r = run_stencilgen("verify " + (dir / "bad.json").string());
  CHECK(r.status == 1);
  CHECK_THAT(r.output, Catch::Contains("sectors[0].ev_child[0]"));
}
