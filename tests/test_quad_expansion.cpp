// The extraordinary patch's stencils recomputed at load time from what
// generates them (A0, the regular children, the regular curve's values and the
// limit stencil) agree with the exact rational stencils of the JSON tables,
// rounded to double, within one unit in the last place, for every valence and
// rate (swapping two regular children breaks it).
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
