#include "quad/quad_table_verify.hpp"

#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "common/hash.hpp"
#include "quad/ev_patch_solver.hpp"
#include "quad/patch_layout.hpp"
#include "quad/quad_table_json.hpp"

namespace sg {
using ojson = nlohmann::ordered_json;

std::vector<std::string> verify_quad_table_json(const std::string& text, const std::string& origin,
                                                const QuadScheme& scheme) {
  std::vector<std::string> failures;
  ojson doc;
  try {
    doc = ojson::parse(text);
    if (doc.at("format") != kQuadTableFormat || doc.at("version") != kQuadTableVersion)
      throw Error("not a version " + std::to_string(kQuadTableVersion) + " surface table");
    if (doc.at("scheme_hash") != hex64(scheme.hash))
      failures.push_back("scheme hash " + doc.at("scheme_hash").get<std::string>() + " is not that of '" +
                         scheme.name + "' (" + hex64(scheme.hash) + ")");
    const int v = doc.at("valence").get<int>();
    const long n = doc.at("n").get<long>();
    if (n < 1 || v < 3) throw Error("invalid valence or n");
    const PatchGrid patch = solve_ev_patch(scheme, v, 2 * n);
    if (doc.at("reflection").get<std::vector<std::size_t>>() != PatchLayout(v).reflection())
      failures.push_back("the reflection permutation is wrong");
    std::size_t expected_count[2] = {static_cast<std::size_t>((n + 1) * (n + 2) / 2),
                                     static_cast<std::size_t>(n * (n + 1) / 2)};
    int kind = 0;
    for (const char* key : {"nodes", "centres"}) {
      const ojson& list = doc.at(key);
      if (list.size() != expected_count[kind])
        failures.push_back(std::string(key) + ": " + std::to_string(list.size()) + " entries, expected " +
                           std::to_string(expected_count[kind]));
      for (const ojson& e : list) {
        const Rational x = parse_rational(e.at("at")[0].get<std::string>()) * 2 * n;
        const Rational y = parse_rational(e.at("at")[1].get<std::string>()) * 2 * n;
        const std::string where = std::string(key) + " at (" + e.at("at")[0].get<std::string>() + ", " +
                                  e.at("at")[1].get<std::string>() + ")";
        if (denominator(x) != 1 || denominator(y) != 1 || x < 0 || y < 0 || x > 2 * n || y > 2 * n) {
          failures.push_back(where + ": not a point of the grid 1/(2n) in the patch");
          continue;
        }
        const Integer den(e.at("denominator").get<std::string>());
        std::vector<Rational> w;
        Integer sum = 0;
        for (const ojson& num : e.at("numerators")) {
          const Integer k(num.get<std::string>());
          sum += k;
          w.emplace_back(k, den);
        }
        if (sum != den) failures.push_back(where + ": the weights do not sum to 1");
        if (w != patch.at(static_cast<long>(numerator(x)), static_cast<long>(numerator(y))))
          failures.push_back(where + ": differs from the re-solved stencil");
      }
      ++kind;
    }
  } catch (const Error& e) {
    failures.push_back(origin + ": " + e.what());
  } catch (const std::exception& e) {
    failures.push_back(origin + ": malformed surface table (" + e.what() + ")");
  }
  return failures;
}

}  // namespace sg
