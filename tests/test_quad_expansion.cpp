// The extraordinary patch's stencils recomputed at load time from what
// generates them (A0, the regular children, the regular curve's values and the
// limit stencil) agree with the exact rational stencils of the JSON tables,
// rounded to double, within one unit in the last place, for every valence and
// rate (swapping two regular children breaks it). A .sgs of the generated
// layout (the default) holds only those generators; its stencils are the
// expansion, and it is several times smaller than the stored layout.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>

#include "cli.hpp"
#include "tables/quad_tables.hpp"

using namespace stencil_runtime;
namespace fs = std::filesystem;

namespace {

double largest_difference(const QuadTables& computed, const QuadTables& exact) {
  double worst = 0;
  for (int v : exact.valences()) {
    const QuadTables::Expanded e = computed.expand(v);
    const std::size_t m = static_cast<std::size_t>(QuadTables::points(v));
    std::vector<double> w(m);
    for (std::size_t r = 0; r < exact.rates().size(); ++r) {
      const int n = exact.rates()[r];
      for (int kind = 0; kind < 2; ++kind)
        for (int j = 0; j < (kind == 0 ? n + 1 : n); ++j)
          for (int i = 0; i <= j; ++i) {
            if (kind == 0) exact.node_stencil(v, n, i, j, w.data());
            else exact.centre_stencil(v, n, i, j, w.data());
            const auto& index = kind == 0 ? e.nodes[r] : e.centres[r];
            const double* x = e.weights.data() + index[static_cast<std::size_t>(j * (j + 1) / 2 + i)] * m;
            for (std::size_t h = 0; h < m; ++h) worst = std::max(worst, std::fabs(x[h] - w[h]));
          }
    }
  }
  return worst;
}

// The stencils a loaded table answers with (nodes and centres, both halves of
// the patch), against the exact ones.
double largest_answer_difference(const QuadTables& loaded, const QuadTables& exact) {
  double worst = 0;
  for (int v : exact.valences()) {
    const std::size_t m = static_cast<std::size_t>(QuadTables::points(v));
    std::vector<double> a(m), b(m);
    for (int n : exact.rates())
      for (int kind = 0; kind < 2; ++kind)
        for (int j = 0; j < (kind == 0 ? n + 1 : n); ++j)
          for (int i = 0; i < (kind == 0 ? n + 1 : n); ++i) {
            if (kind == 0) loaded.node_stencil(v, n, i, j, a.data()), exact.node_stencil(v, n, i, j, b.data());
            else loaded.centre_stencil(v, n, i, j, a.data()), exact.centre_stencil(v, n, i, j, b.data());
            for (std::size_t h = 0; h < m; ++h) worst = std::max(worst, std::fabs(a[h] - b[h]));
          }
  }
  return worst;
}

}  // namespace

TEST_CASE("patch stencils recomputed from the patch subdivision equal the exact ones", "[runtime][tables][expansion]") {
  for (const char* scheme : {"nonpoly", "catmull-clark"}) {
    const fs::path dir = scratch_dir(std::string("expansion-") + scheme);
    REQUIRE(run_stencilgen(std::string("--scheme ") + scheme + " --valence 3-8 --n 1-12 --out " + dir.string() + " -q").status == 0);
    const QuadTables binary = QuadTables::load_binary((dir / scheme / (std::string(scheme) + ".sgs")).string());
    const QuadTables exact = QuadTables::load_json_directory((dir / scheme).string());
    INFO(scheme);
    CHECK(largest_difference(binary, exact) <= 2.3e-16);
    fs::remove_all(dir);
  }
}

TEST_CASE("a .sgs of generated layout answers the exact stencils, and the stored layout answers them rounded", "[runtime][tables][expansion]") {
  for (const char* scheme : {"nonpoly", "catmull-clark"}) {
    INFO(scheme);
    const fs::path dir = scratch_dir(std::string("layout-") + scheme);
    const std::string common = std::string("--scheme ") + scheme + " --valence 3,5,7 --n 1-9 -q --out ";
    REQUIRE(run_stencilgen(common + (dir / "generated").string()).status == 0);
    REQUIRE(run_stencilgen(common + (dir / "stored").string() + " --binary-layout stored").status == 0);
    REQUIRE(run_stencilgen(common + (dir / "single").string() + " --binary-precision single").status == 0);
    REQUIRE(run_stencilgen(common + (dir / "single-stored").string() + " --binary-precision single --binary-layout stored").status == 0);
    const std::string file = std::string(scheme) + "/" + scheme + ".sgs";
    const QuadTables exact = QuadTables::load_json_directory((dir / "generated" / scheme).string());
    const QuadTables generated = QuadTables::load_binary((dir / "generated" / file).string());
    const QuadTables stored = QuadTables::load_binary((dir / "stored" / file).string());
    const QuadTables single = QuadTables::load_binary((dir / "single" / file).string());
    const QuadTables single_stored = QuadTables::load_binary((dir / "single-stored" / file).string());
    // Stored weights are the exact ones rounded to nearest: half an ulp of weights below 1.
    CHECK(largest_answer_difference(stored, exact) <= 1.12e-16);
    CHECK(largest_answer_difference(generated, exact) <= 2.3e-16);
    // Single precision: the regular values and the limit stencil are floats, the patch subdivision double.
    const double s = largest_answer_difference(single, exact);
    CHECK(s <= 3e-7);
    CHECK(s > 1e-12);  // it really is single precision
    const double ss = largest_answer_difference(single_stored, exact);
    CHECK(ss <= 6e-8);  // half a float ulp of weights below 1
    CHECK(ss > 1e-12);
    // The boundary sectors are the same in both layouts (always generated): their bytes, from the format, aside.
    std::uintmax_t sectors = 4;
    for (const SectorKey& key : generated.sectors()) {
      const QuadDescent::Valence& d = generated.descent(sector_kind(key));
      const std::uintmax_t points = static_cast<std::uintmax_t>(key.points()), rows = points + 3 * 16;
      std::uintmax_t nonzeros = d.ev_child.weights.size();
      for (const auto& child : d.regular_children) nonzeros += child.weights.size();
      sectors += 13 + 8 * points + 1 + 4 * rows + 12 * nonzeros + 1 + (d.tangent_u.empty() ? 0 : 24 + 16 * points);
    }
    CHECK(fs::file_size(dir / "stored" / file) - sectors > 5 * (fs::file_size(dir / "generated" / file) - sectors));  // 6.6x here, 52x at rates 1..24
    fs::remove_all(dir);
  }
}
