// `stencilgen verify` on a quad scheme's descent.json: it passes as written,
// and fails when a subdivision weight or a digit of a tangent stencil is
// changed (the tangent checks use the file's own exact A0 and a fresh solve).
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "json_files.hpp"

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

TEST_CASE("stencilgen verify checks descent.json: subdivision matrices exactly, tangent stencils by their eigen-relation",
          "[verify][derivatives]") {
  const fs::path dir = scratch_dir("descent-verify");
  for (const char* scheme : {"catmull-clark", "nonpoly"}) {
    INFO(scheme);
    REQUIRE(run_stencilgen(std::string("--scheme ") + scheme + " --valence 3,5 --n 2 -q --out " + dir.string()).status == 0);
    const fs::path file = dir / scheme / "descent.json";
    CliResult r = run_stencilgen("verify " + file.string());
    CHECK(r.status == 0);
    CHECK_THAT(r.output, Catch::Contains("OK"));
    const json good = read_json_file(file);

    json bad = good;  // one digit of a tangent weight (the 20th significant digit)
    std::string& w = bad["valences"][0]["tangents"]["u"][1].get_ref<std::string&>();
    const std::size_t digit = w.find('.') + 19;
    REQUIRE(digit < w.size());
    w[digit] = w[digit] == '1' ? '2' : '1';
    write_json_file(dir / "bad.json", bad);
    r = run_stencilgen("verify " + (dir / "bad.json").string());
    CHECK(r.status == 1);
    CHECK_THAT(r.output, Catch::Contains("tangent stencil u") && Catch::Contains("not a left eigenvector"));

    bad = good;  // the eigenvalue
    std::string& lambda = bad["valences"][1]["tangents"]["eigenvalue"].get_ref<std::string&>();
    lambda[lambda.find('.') + 25] = lambda[lambda.find('.') + 25] == '3' ? '4' : '3';
    write_json_file(dir / "bad.json", bad);
    r = run_stencilgen("verify " + (dir / "bad.json").string());
    CHECK(r.status == 1);
    CHECK_THAT(r.output, Catch::Contains("valence 5: the eigenvalue differs"));

    bad = good;  // a weight of A0
    bad["valences"][0]["ev_child"][0][0][1] = "1/3";
    write_json_file(dir / "bad.json", bad);
    r = run_stencilgen("verify " + (dir / "bad.json").string());
    CHECK(r.status == 1);
    CHECK_THAT(r.output, Catch::Contains("valence 3: A0 differs"));

    bad = good;  // tangents removed
    bad["valences"][0]["tangents"] = nullptr;
    write_json_file(dir / "bad.json", bad);
    r = run_stencilgen("verify " + (dir / "bad.json").string());
    CHECK(r.status == 1);
    CHECK_THAT(r.output, Catch::Contains("no tangent stencils, but the scheme has them"));

    // Fields no stencil check reads: the regular curve's basis and mask, the
    // nonnegativity flags (they decide whether bounds are claimed), a deleted
    // sector; re-indenting the file is no change.
    for (const char* field : {"polynomial_basis", "mask", "mask_nonnegative", "sectors"}) {
      bad = good;
      if (std::string(field) == "polynomial_basis" && !good[field].is_null()) bad[field]["pieces"][0][0] = "1/5";
      else if (std::string(field) == "polynomial_basis") bad[field] = json::object({{"degree", 3}});
      else if (std::string(field) == "mask") bad[field]["coefficients"][0] = "1/3";
      else if (std::string(field) == "mask_nonnegative") bad[field] = !good[field].get<bool>();
      else bad[field].erase(3);
      write_json_file(dir / "bad.json", bad);
      r = run_stencilgen("verify " + (dir / "bad.json").string());
      INFO(field << ": " << r.output);
      CHECK(r.status == 1);
      CHECK_THAT(r.output, Catch::Contains(std::string(field) + ": "));
    }
    std::ofstream(dir / "indented.json") << good.dump(3) << "\n";
    r = run_stencilgen("verify " + (dir / "indented.json").string());
    CHECK(r.status == 0);

    // Boundary sectors: valences up to 5 give the crease sectors of 1, 3, 4 and 5 faces, the corners of 2..5,
    // the darts of valence 3..5, and the cone points of valence 3..5 (one patch each).
    REQUIRE(good["sectors"].size() == (1 + 3 + 4 + 5) + (2 + 3 + 4 + 5) + (3 + 4 + 5) + 3);
    {
      std::size_t cone = 0;
      while (good["sectors"][cone]["kind"] != "cone") ++cone;
      CHECK(good["sectors"][cone]["points"] == 2 * good["sectors"][cone]["faces"].get<int>() + 8);
      CHECK(good["sectors"][cone]["tangents"].is_null());
      bad = good;  // the cone point's own row of A0 is the identity: the smooth rule's weight there is caught
      bad["sectors"][cone]["ev_child"][0][0][1] = "1/2";
      write_json_file(dir / "bad.json", bad);
      r = run_stencilgen("verify " + (dir / "bad.json").string());
      CHECK(r.status == 1);
      CHECK_THAT(r.output, Catch::Contains("cone point of valence 3: A0 differs"));
    }
    std::size_t three = 0;  // the first sector of three faces (which has tangents)
    while (good["sectors"][three]["faces"] != 3) ++three;
    bad = good;  // a weight of a sector's A0 (its vertex's row: the boundary curve's rule)
    bad["sectors"][three]["ev_child"][0][0][1] = "1/3";
    write_json_file(dir / "bad.json", bad);
    r = run_stencilgen("verify " + (dir / "bad.json").string());
    CHECK(r.status == 1);
    CHECK_THAT(r.output, Catch::Contains("boundary vertex in 3 faces, face 0: A0 differs"));
    bad = good;  // a weight of its limit stencil
    bad["sectors"][three]["limit"][0] = "1/2";
    write_json_file(dir / "bad.json", bad);
    r = run_stencilgen("verify " + (dir / "bad.json").string());
    CHECK(r.status == 1);
    CHECK_THAT(r.output, Catch::Contains("boundary vertex in 3 faces, face 0: the limit stencil differs") &&
                             Catch::Contains("not A0's fixed point"));
    bad = good;  // a digit of a tangent weight: the plane is no longer one A0 keeps
    std::string& t = bad["sectors"][three]["tangents"]["v"][0].get_ref<std::string&>();
    const std::size_t at = t.find('.') + 19;
    REQUIRE(at < t.size());
    t[at] = t[at] == '1' ? '2' : '1';
    write_json_file(dir / "bad.json", bad);
    r = run_stencilgen("verify " + (dir / "bad.json").string());
    CHECK(r.status == 1);
    CHECK_THAT(r.output, Catch::Contains("do not span a plane that A0 keeps"));
  }
  fs::remove_all(dir);
}
