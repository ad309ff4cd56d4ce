// stencilgen verify TABLE.json...: re-checks curve, quad and triangle tables (and a quad scheme's descent.json,
// a Loop scheme's sectors.json)
// exactly against their scheme.
#include <iostream>

#include "base/error.hpp"
#include "base/limits.hpp"
#include "cli/commands.hpp"
#include "common/read_file.hpp"
#include "common/table_document.hpp"
#include "curve/curve_scheme_loader.hpp"
#include "curve/curve_table_json.hpp"
#include "curve/curve_table_verify.hpp"
#include "curve/generate_curve.hpp"
#include "quad/quad_descent_format.hpp"
#include "quad/quad_descent_verify.hpp"
#include "quad/quad_scheme_loader.hpp"
#include "quad/quad_table_json.hpp"
#include "quad/quad_table_verify.hpp"
#include "triangle/triangle_scheme_loader.hpp"
#include "triangle/triangle_table.hpp"
#include "triangle/triangle_sectors_json.hpp"
#include "triangle/triangle_table_verify.hpp"

namespace sg::cli {
namespace {

// Prints the file's verdict; returns whether it passed.
bool verify_file(const std::string& file, const std::string& scheme_spec, const std::vector<std::string>& params) {
  const std::string text = read_file(file, limits::kMaxTableFileBytes, "table");
  if (text.find('\0') != std::string::npos)
    throw Error(file + ": a binary file; verify checks exact JSON tables (the .json files, descent.json and sectors.json beside it)");
  const TableDocument table = parse_table_document(text, file);
  // The scheme and parameters the table records, unless given on the command line.
  const std::string& spec = scheme_spec.empty() ? table.scheme : scheme_spec;
  const std::vector<std::string>& overrides = params.empty() ? table.parameters : params;

  if (table.format == kTriangleTableFormat) {
    const TriangleScheme scheme = load_triangle_scheme(spec, overrides);
    const TriangleTableCheck check = verify_triangle_table(table, scheme);
    const TriangleTable& t = check.fresh;
    if (check.same)
      std::cout << file << ": OK (" << scheme.name << " triangle table, valence " << t.valence << ", n = " << t.n
                << "; " << (t.exact ? "exact" : "high precision") << "; equal to the re-solved table in every digit)\n";
    else
      std::cout << file << ": FAIL: differs from the re-solved table (scheme '" << scheme.name << "', valence "
                << t.valence << ", n = " << t.n << ") at " << *check.difference << "\n";
    return check.same;
  }
  if (table.format == kTriangleSectorsFormat) {
    const TriangleScheme scheme = load_triangle_scheme(spec, overrides);
    const auto failures = verify_triangle_sectors(table, scheme);
    if (failures.empty())
      std::cout << file << ": OK (" << scheme.name
                << " sectors: equal to the re-solved ones in every digit; every exact limit stencil sums to 1 and is A0's "
                   "fixed point, from the file's own rationals)\n";
    for (const auto& f : failures) std::cout << file << ": FAIL: " << f << "\n";
    return failures.empty();
  }
  if (table.format == kQuadTableFormat) {
    const QuadScheme scheme = load_quad_scheme(spec, overrides);
    const auto failures = verify_quad_table(table, scheme);
    if (failures.empty())
      std::cout << file << ": OK (" << scheme.name << " surface; every stencil equals the re-solved one exactly)\n";
    for (const auto& f : failures) std::cout << file << ": FAIL: " << f << "\n";
    return failures.empty();
  }
  if (table.format == kQuadDescentFormat) {
    const QuadScheme scheme = load_quad_scheme(spec, overrides);
    const auto failures = verify_quad_descent(table, scheme);
    if (failures.empty())
      std::cout << file << ": OK (" << scheme.name
                << " patch subdivision: every matrix and boundary sector limit stencil equals the re-derived one exactly; "
                   "the tangent stencils are left eigenvectors of A0 (boundary sectors: span a plane A0 keeps, at darts with "
                   "the slit folded shut) to 1e-30 "
                   "and equal the recomputed ones to 1e-35; every other field equals the re-derived document's)\n";
    for (const auto& f : failures) std::cout << file << ": FAIL: " << f << "\n";
    return failures.empty();
  }
  if (table.format != kCurveTableFormat)
    throw Error(file + ": format: unknown table format '" + excerpt(table.format) + "' (expected " + kCurveTableFormat +
                ", " + kQuadTableFormat + ", " + kQuadDescentFormat + ", " + kTriangleTableFormat + " or " + kTriangleSectorsFormat + ")");
  const CurveTable curve = curve_table_from_document(table);
  const CurveScheme scheme = load_curve_scheme(spec, overrides);
  auto failures = verify_curve_table(curve, scheme);
  // What the relations above do not fix (which function is where, key
  // spelling, lowest terms): the table generated again equals the file's as values.
  if (failures.empty())
    if (const auto d = json_difference(nlohmann::ordered_json::parse(curve_table_to_json(
                                           generate_curve_tables(scheme, {curve.n}, RouteChoice::Residue, nullptr).front())),
                                       table.doc))
      failures.push_back("differs from the table generated again at " + *d);
  if (failures.empty()) {
    std::size_t values = 0;
    for (const auto& f : curve.functions) values += f.values.size();
    std::cout << file << ": OK (" << curve.scheme << ", n = " << curve.n << ", " << values
              << " exact values; scaling relations, partition of unity and symmetry hold exactly"
              << (curve.derivative_orders == 0 ? std::string(", no derivatives")
                                               : "; derivatives of order 1" + std::string(curve.derivative_orders > 1 ? " and 2" : "") +
                                                     (scheme.is_uniform()
                                                          ? ": scaled scaling relations and polynomial moments hold exactly"
                                                          : ": scaled scaling relations, zero sum and the slope at 0 hold exactly"))
              << ")\n";
  }
  for (const auto& f : failures) std::cout << file << ": FAIL: " << f << "\n";
  return failures.empty();
}

}  // namespace

int verify(const std::vector<std::string>& files, const std::string& scheme_spec, const std::vector<std::string>& params) {
  int bad = 0;
  for (const std::string& file : files)
    if (!verify_file(file, scheme_spec, params)) ++bad;
  return bad == 0 ? 0 : 1;
}

}  // namespace sg::cli
