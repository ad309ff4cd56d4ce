#include "triangle/triangle_table_verify.hpp"

#include "base/limits.hpp"
#include "triangle/triangle_children.hpp"

namespace sg {
using ojson = nlohmann::ordered_json;

TriangleTableCheck verify_triangle_table(const TableDocument& table, const TriangleScheme& scheme) {
  const DocumentReader<ojson> r(table.origin);
  if (table.format != kTriangleTableFormat) r.fail("format", "is not \"" + std::string(kTriangleTableFormat) + "\"");
  const int v = static_cast<int>(r.integer(r.require(table.doc, "valence", ""), "valence", scheme.min_valence, scheme.max_valence));
  const long n = r.integer(r.require(table.doc, "n", ""), "n", 1, limits::kMaxSurfaceRate);
  TriangleTableCheck check;
  // The regular table (valence 6) carries the derivative stencils (version 3).
  if (v == 6 && !regular_basis_is_polynomial(scheme)) {
    const auto [regular, gradient] = solve_regular_with_gradient(scheme, 3 * n);
    check.fresh = solve_triangle_table(scheme, v, n, regular, &gradient);
  } else {
    check.fresh = solve_triangle_table(scheme, v, n, solve_regular(scheme, 3 * n));
  }
  // As values: spacing and key order are no difference.
  check.difference = json_difference(ojson::parse(triangle_table_to_json(check.fresh)), table.doc);
  check.same = !check.difference;
  return check;
}

}  // namespace sg
