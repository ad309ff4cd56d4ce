#include "quad/quad_table_verify.hpp"

#include "base/error.hpp"
#include "base/limits.hpp"
#include "common/hash.hpp"
#include "quad/ev_patch_solver.hpp"
#include "quad/patch_layout.hpp"
#include "quad/quad_table.hpp"
#include "quad/quad_table_json.hpp"

namespace sg {
using ojson = nlohmann::ordered_json;

std::vector<std::string> verify_quad_table(const TableDocument& table, const QuadScheme& scheme) {
  const DocumentReader<ojson> r(table.origin);
  const ojson& doc = table.doc;
  if (table.format != kQuadTableFormat) r.fail("format", "is not \"" + std::string(kQuadTableFormat) + "\"");
  r.integer(r.require(doc, "version", ""), "version", kQuadTableVersion, kQuadTableVersion);
  std::vector<std::string> failures;
  const std::string& hash = r.string(r.require(doc, "scheme_hash", ""), "scheme_hash");
  if (hash != hex64(scheme.hash))
    failures.push_back("scheme hash " + excerpt(hash) + " is not that of '" + scheme.name + "' (" + hex64(scheme.hash) + ")");
  const int v = static_cast<int>(r.integer(r.require(doc, "valence", ""), "valence", scheme.min_valence, scheme.max_valence));
  const long n = r.integer(r.require(doc, "n", ""), "n", 1, limits::kMaxSurfaceRate);
  const std::vector<std::size_t> reflection = PatchLayout(v).reflection();
  const ojson& stored_reflection = r.array(r.require(doc, "reflection", ""), "reflection");
  bool same = stored_reflection.size() == reflection.size();
  for (std::size_t h = 0; same && h < reflection.size(); ++h)
    same = stored_reflection[h].is_number_unsigned() && stored_reflection[h].get<std::uint64_t>() == reflection[h];
  if (!same) failures.push_back("the reflection permutation is wrong");

  const PatchGrid patch = solve_ev_patch(scheme, v, 2 * n);
  const std::size_t expected_count[2] = {static_cast<std::size_t>((n + 1) * (n + 2) / 2),
                                         static_cast<std::size_t>(n * (n + 1) / 2)};
  int kind = 0;
  for (const char* key : {"nodes", "centres"}) {
    const ojson& list = r.array(r.require(doc, key, ""), key);
    if (list.size() != expected_count[kind])
      failures.push_back(std::string(key) + ": " + std::to_string(list.size()) + " entries, expected " +
                         std::to_string(expected_count[kind]));
    for (std::size_t k = 0; k < list.size(); ++k) {
      const std::string field = field_path(key, k);
      const ojson& e = list[k];
      const std::string at_field = field_path(field, "at");
      const ojson& at = r.array(r.require(e, "at", field), at_field);
      if (at.size() != 2) r.fail(at_field, "expected [x, y], got " + json_excerpt(at));
      const Rational x = r.rational_literal(at[0], field_path(at_field, 0)) * 2 * n;
      const Rational y = r.rational_literal(at[1], field_path(at_field, 1)) * 2 * n;
      const std::string where =
          std::string(key) + " at (" + excerpt(at[0].get<std::string>()) + ", " + excerpt(at[1].get<std::string>()) + ")";
      if (denominator(x) != 1 || denominator(y) != 1 || x < 0 || y < 0 || x > 2 * n || y > 2 * n) {
        failures.push_back(where + ": not a point of the grid 1/(2n) in the patch");
        continue;
      }
      const Integer den = r.integer_literal(r.require(e, "denominator", field), field_path(field, "denominator"));
      if (den == 0) r.fail(field_path(field, "denominator"), "is zero");
      const std::string nums_field = field_path(field, "numerators");
      const ojson& nums = r.array(r.require(e, "numerators", field), nums_field);
      std::vector<Rational> w;
      Integer sum = 0;
      for (std::size_t h = 0; h < nums.size(); ++h) {
        const Integer num = r.integer_literal(nums[h], field_path(nums_field, h));
        sum += num;
        w.emplace_back(num, den);
      }
      if (sum != den) failures.push_back(where + ": the weights do not sum to 1");
      if (w != patch.at(numerator(x).convert_to<long>(), numerator(y).convert_to<long>()))
        failures.push_back(where + ": differs from the re-solved stencil");
    }
    ++kind;
  }
  // Everything else (the rules, the point count, exactness, lowest terms):
  // the table made again equals the file's as values.
  if (failures.empty())
    if (const auto d = json_difference(ojson::parse(quad_table_to_json(make_quad_table(scheme, patch))), doc))
      failures.push_back("differs from the table made again at " + *d);
  return failures;
}

}  // namespace sg
