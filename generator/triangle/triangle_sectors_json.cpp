#include "triangle/triangle_sectors_json.hpp"

#include <tbb/parallel_for.h>

#include "algebra/real.hpp"
#include "base/error.hpp"
#include "common/exact_rows.hpp"
#include "common/hash.hpp"
#include "common/tenths_progress.hpp"
#include "common/parameters_json.hpp"
#include "triangle/triangle_table_binary.hpp"

namespace sg {

using ojson = nlohmann::ordered_json;

namespace {

// Upper bounds a file's counts are checked against before use (the
// generator's own reach is far below: the second ring, k + 7 points).
constexpr long kMaxPoints = 4096;
constexpr long kMaxCoordinate = 1024;

ojson point_json(int sector, long a, long b) { return ojson::array({sector, a, b}); }

// Rows as lists of [column, weight] pairs.
ojson rows_json(const SectorRows& rows) {
  return exact_rows_json(rows, [](const SectorWeight& w) { return w.text; });
}

ojson tangents_json(const TangentStencils& t) {
  ojson out;
  out["eigenvalue"] = to_string(t.eigenvalue, 40);
  out["second_eigenvalue"] = to_string(t.second_eigenvalue, 40);
  out["residual"] = to_string(t.residual, 3);
  for (const char* which : {"u", "v"}) {
    ojson w = ojson::array();
    for (const Real& x : (which[0] == 'u' ? t.u : t.v)) w.push_back(to_string(x, 40));
    out[which] = w;
  }
  return out;
}

}  // namespace

TriangleSectorSet solve_triangle_sectors(const TriangleScheme& scheme, int max_faces, const std::vector<SectorPoint>& regular_layout,
                                         const std::function<void(const std::string&)>& progress) {
  TriangleSectorSet set;
  set.max_faces = max_faces;
  set.regular_layout = regular_layout;
  if (scheme.refinement != TriangleRefinement::Loop || !scheme.has_crease) return set;
  const std::vector<BoundarySector> sectors = triangle_sectors(max_faces, true);
  set.sectors.resize(sectors.size());
  TenthsProgress sectors_done(progress, scheme.name + ": boundary, crease, corner, dart and cone sectors", sectors.size());
  sg::prepare_real_limits();  // before threads first use Real (algebra/real.hpp)
  tbb::parallel_for(std::size_t(0), sectors.size(), [&](std::size_t s) {
    set.sectors[s] = triangle_sector_descent(scheme, sectors[s], regular_layout);
    sectors_done.done();
  });
  return set;
}

std::string triangle_sectors_to_json(const TriangleScheme& scheme, const TriangleSectorSet& set) {
  ojson doc;
  doc["format"] = kTriangleSectorsFormat;
  doc["version"] = kTriangleSectorsVersion;
  doc["scheme"] = scheme.name;
  doc["scheme_hash"] = hex64(scheme.hash);
  doc["parameters"] = parameters_json<ojson>(scheme.parameters);  // so that `stencilgen verify` re-derives it
  doc["meaning"] =
      "The patches of the faces at a vertex B of a Loop mesh on a boundary or infinitely sharp crease in k faces "
      "(k other than 3), a corner, a dart or a cone point (docs/table-format.md, \"Loop boundary sectors\"): kind "
      "crease (B follows the boundary curve), corner (B stays put), dart (the end of a crease, B on the smooth rule at "
      "valence k) or cone (B held, the closed ring); the face at position p. points: the sector's points as "
      "[wedge, a, b] (B first); limit: B's limit stencil W(0) over them; ev_child: A0, the child at B (rows over the "
      "points, in the points' order), so that W(x) = W(2x) A0 for u + v <= 1/2; regular_children: the regular cells up "
      "(1, 0), up (0, 1) and down (0, 0) of one step, per point of regular_points (valence 6's layout) its row over the "
      "points; weights exact (\"p/q\") where exact is true, else 40 significant digits of an 80-digit solve whose "
      "residual max |W(0) A0 - W(0)| is given; tangents: two stencils spanning the tangent plane at B (left "
      "eigenvectors of A0, 40 digits, null for corners and cone points, no_tangents says why).";
  doc["max_faces"] = set.max_faces;
  ojson regular = ojson::array();
  for (const SectorPoint& p : set.regular_layout) regular.push_back(point_json(p.sector, p.a, p.b));
  doc["regular_points"] = regular;
  ojson sectors = ojson::array();
  for (const TriangleSectorDescent& d : set.sectors) {
    ojson entry;
    entry["kind"] = sector_kind_name(d.sector.kind);
    entry["faces"] = d.sector.faces;
    entry["position"] = d.sector.position;
    entry["exact"] = d.exact;
    entry["residual"] = d.exact ? std::string("0") : to_string(d.eigen_residual, 3);
    ojson points = ojson::array();
    for (const WedgePoint& p : d.layout) points.push_back(point_json(p.sector, p.a, p.b));
    entry["points"] = points;
    ojson limit = ojson::array();
    for (const SectorWeight& w : d.limit) limit.push_back(w.text);
    entry["limit"] = limit;
    entry["ev_child"] = rows_json(d.child_at_vertex);
    ojson children = ojson::array();
    for (const SectorRows& child : d.regular_children) children.push_back(rows_json(child));
    entry["regular_children"] = children;
    if (d.tangents) {
      entry["tangents"] = tangents_json(*d.tangents);
    } else {
      entry["tangents"] = nullptr;
      entry["no_tangents"] = d.no_tangents;
    }
    sectors.push_back(entry);
  }
  doc["sectors"] = sectors;
  return doc.dump() + "\n";
}

std::vector<std::string> verify_triangle_sectors(const TableDocument& table, const TriangleScheme& scheme) {
  const DocumentReader<ojson> r(table.origin);
  if (table.format != kTriangleSectorsFormat) r.fail("format", "is not \"" + std::string(kTriangleSectorsFormat) + "\"");
  if (r.integer(r.require(table.doc, "version", ""), "version", 1, kTriangleSectorsVersion) != kTriangleSectorsVersion)
    r.fail("version", "is not " + std::to_string(kTriangleSectorsVersion));
  const int max_faces = static_cast<int>(r.integer(r.require(table.doc, "max_faces", ""), "max_faces", 1, scheme.max_valence));
  const ojson& regular = r.array(r.require(table.doc, "regular_points", ""), "regular_points");
  if (regular.size() > static_cast<std::size_t>(kMaxPoints)) r.fail("regular_points", "has more than " + std::to_string(kMaxPoints) + " points");
  std::vector<SectorPoint> layout;
  for (std::size_t i = 0; i < regular.size(); ++i) {
    const std::string field = field_path("regular_points", i);
    const ojson& p = r.array(regular[i], field);
    if (p.size() != 3) r.fail(field, "is not [wedge, a, b]");
    layout.push_back({static_cast<int>(r.integer(p[0], field, -kMaxCoordinate, kMaxCoordinate)),
                      r.integer(p[1], field, -kMaxCoordinate, kMaxCoordinate), r.integer(p[2], field, -kMaxCoordinate, kMaxCoordinate)});
  }
  std::vector<std::string> failures;
  // Valence 6's layout is the scheme's, whatever rates the tables had: made
  // here again, not taken from the file.
  TriangleTableSet six;
  six.rates = {1};
  six.valences = {6};
  six.tables = {{solve_triangle_table(scheme, 6, 1, solve_regular(scheme, 3))}};
  const std::vector<SectorPoint> regular_layout = regular_points(scheme, six);
  if (layout != regular_layout) failures.push_back("regular_points: not the points of valence 6's patch");
  // The limit stencils' exactness, from the file's own rationals.
  const ojson& sectors = r.array(r.require(table.doc, "sectors", ""), "sectors");
  for (std::size_t s = 0; s < sectors.size(); ++s) {
    const std::string field = field_path("sectors", s);
    const ojson& entry = r.object(sectors[s], field);
    const ojson& exact = r.require(entry, "exact", field);
    if (!exact.is_boolean()) r.fail(field_path(field, "exact"), "is not true or false");
    if (!exact.get<bool>()) continue;
    const ojson& limit_json = r.array(r.require(entry, "limit", field), field_path(field, "limit"));
    const std::size_t n = limit_json.size();
    if (n == 0 || n > static_cast<std::size_t>(kMaxPoints)) r.fail(field_path(field, "limit"), "has no weights or too many");
    std::vector<Rational> limit;
    for (std::size_t i = 0; i < n; ++i) limit.push_back(exact_weight(r, limit_json[i], field_path(field_path(field, "limit"), i)));
    const std::string rows_field = field_path(field, "ev_child");
    const std::vector<ExactRow> a0 = exact_rows(r, r.require(entry, "ev_child", field), rows_field, n);
    if (a0.size() != n) r.fail(rows_field, "does not have a row per point");
    const std::string name = field + " (" + (entry.contains("kind") && entry["kind"].is_string() ? entry["kind"].get<std::string>() : "?") + ")";
    for (const std::string& fault : limit_stencil_faults(limit, a0)) failures.push_back(name + ": " + fault);
  }
  // Everything else: the re-solved sectors, written again, are the file.
  if (const auto difference = json_difference(ojson::parse(triangle_sectors_to_json(scheme, solve_triangle_sectors(scheme, max_faces, regular_layout))),
                                              table.doc))  // as values: spacing is no difference
    failures.push_back("differs from the sectors re-solved from scheme '" + scheme.name + "' at " + *difference);
  return failures;
}

}  // namespace sg
