#include "quad/quad_descent_verify.hpp"

#include <algorithm>

#include "base/error.hpp"
#include "common/exact_rows.hpp"
#include "common/hash.hpp"
#include "common/json_document.hpp"
#include "quad/quad_descent.hpp"
#include "quad/boundary_sector.hpp"
#include "quad/quad_descent_json.hpp"

namespace sg {
using ojson = nlohmann::ordered_json;

namespace {

Real magnitude(const Real& x) { return x < 0 ? Real(-x) : x; }

Real decimal(const DocumentReader<ojson>& r, const ojson& j, const std::string& field) {
  const std::string& text = r.string(j, field);
  try {
    Real x(text);
    if (!boost::multiprecision::isfinite(x)) r.fail(field, "not a finite decimal number");
    return x;
  } catch (const std::runtime_error&) {
    r.fail(field, "not a decimal number: " + excerpt(text));
  }
}

// Which boundary sectors the file lists (version 3), each entry's kind, faces
// and position checked: read before anything is solved, so that one solve of
// the listed valences and sectors serves every comparison.
std::vector<BoundarySector> listed_sectors(const DocumentReader<ojson>& r, const ojson& sectors, const QuadScheme& scheme) {
  std::vector<BoundarySector> listed;
  for (std::size_t k = 0; k < sectors.size(); ++k) {
    const std::string field = field_path("sectors", k);
    const ojson& e = sectors[k];
    const std::string& kind = r.string(r.require(e, "kind", field), field_path(field, "kind"));
    BoundarySector sector;
    if (kind == "corner") sector.kind = SectorKind::Corner;
    else if (kind == "dart") sector.kind = SectorKind::Dart;
    else if (kind == "cone") sector.kind = SectorKind::Cone;
    else if (kind != "crease") r.fail(field_path(field, "kind"), "expected \"crease\", \"corner\", \"dart\" or \"cone\"");
    const bool ring = sector.kind == SectorKind::Dart || sector.kind == SectorKind::Cone;
    sector.faces = static_cast<int>(r.integer(r.require(e, "faces", field), field_path(field, "faces"), ring ? 3 : 1, scheme.max_valence));
    sector.position = static_cast<int>(r.integer(r.require(e, "position", field), field_path(field, "position"), 0,
                                                 sector.kind == SectorKind::Cone ? 0 : sector.faces - 1));
    listed.push_back(sector);
  }
  return listed;
}

// The boundary sectors: rows and the limit stencil compared exactly with
// `fresh` (the same sectors solved anew, in the file's order), the limit
// checked as a fixed point of the file's own A0, the tangent stencils compared
// with the fresh ones and checked to span a plane that the file's A0 maps into
// itself (their combinations are left eigenvectors).
void verify_sectors(const DocumentReader<ojson>& r, const ojson& sectors, const std::vector<BoundarySector>& listed,
                    const std::vector<QuadDescent::Sector>& fresh, std::vector<std::string>& failures) {
  for (std::size_t k = 0; k < sectors.size(); ++k) {
    const std::string field = field_path("sectors", k);
    const ojson& e = sectors[k];
    const BoundarySector& sector = listed[k];
    const QuadDescent::Sector& d = fresh[k];
    const std::size_t points = d.subdivision.points;
    const std::string where = sector.name();
    if (r.integer(r.require(e, "points", field), field_path(field, "points"), 1, 1 << 20) != static_cast<long>(points))
      failures.push_back(where + ": " + std::to_string(points) + " points expected");
    const auto a0 = exact_rows(r, r.require(e, "ev_child", field), field_path(field, "ev_child"), points);
    if (a0 != d.subdivision.extraordinary_child) failures.push_back(where + ": A0 differs from the re-derived one");
    const ojson& children = r.array(r.require(e, "regular_children", field), field_path(field, "regular_children"));
    if (children.size() != 3) r.fail(field_path(field, "regular_children"), "expected three children");
    for (std::size_t c = 0; c < 3; ++c)
      if (exact_rows(r, children[c], field_path(field_path(field, "regular_children"), c), points) != d.subdivision.regular_children[c])
        failures.push_back(where + ": regular child " + std::to_string(c) + " differs from the re-derived one");
    const ojson& limit_json = r.array(r.require(e, "limit", field), field_path(field, "limit"));
    if (limit_json.size() != points) r.fail(field_path(field, "limit"), "expected " + std::to_string(points) + " weights");
    std::vector<Rational> limit;
    for (std::size_t h = 0; h < points; ++h) limit.push_back(exact_weight(r, limit_json[h], field_path(field_path(field, "limit"), h)));
    if (limit != d.limit) failures.push_back(where + ": the limit stencil differs from the re-derived one");
    for (const std::string& fault : limit_stencil_faults(limit, a0)) failures.push_back(where + ": " + fault);
    const ojson& t = r.require(e, "tangents", field);
    if (t.is_null() != !d.tangents) {
      failures.push_back(where + (t.is_null() ? ": no tangent stencils, but the scheme has them" : ": tangent stencils, but the scheme has none"));
      continue;
    }
    if (t.is_null()) continue;
    const std::string tf = field_path(field, "tangents");
    for (const char* name : {"eigenvalue", "second_eigenvalue"}) {
      const Real lambda = decimal(r, r.require(t, name, tf), field_path(tf, name));
      if (magnitude(lambda - (name[0] == 'e' ? d.tangents->eigenvalue : d.tangents->second_eigenvalue)) > Real("1e-35"))
        failures.push_back(where + ": the " + std::string(name) + " differs from the recomputed one");
    }
    std::vector<Real> stored[2];
    for (int w = 0; w < 2; ++w) {
      const char* which = w == 0 ? "u" : "v";
      const std::string wf = field_path(tf, which);
      const ojson& arr = r.array(r.require(t, which, tf), wf);
      if (arr.size() != points) r.fail(wf, "expected " + std::to_string(points) + " weights");
      for (std::size_t h = 0; h < points; ++h) stored[w].push_back(decimal(r, arr[h], field_path(wf, h)));
      const std::vector<Real>& recomputed = w == 0 ? d.tangents->u : d.tangents->v;
      Real difference = 0;
      for (std::size_t h = 0; h < points; ++h) difference = std::max(difference, magnitude(stored[w][h] - recomputed[h]));
      if (difference > Real("1e-35"))
        failures.push_back(where + ": tangent stencil " + which + " differs from the recomputed one by " + to_string(difference, 3));
    }
    // t A0 for each stored t, projected on span(t_u, t_v) by least squares: the rest must vanish.
    Real uu = 0, uv = 0, vv = 0;
    for (std::size_t h = 0; h < points; ++h) uu += stored[0][h] * stored[0][h], uv += stored[0][h] * stored[1][h], vv += stored[1][h] * stored[1][h];
    const Real det = uu * vv - uv * uv;
    for (int w = 0; w < 2; ++w) {
      std::vector<Real> product(points, Real(0));
      for (std::size_t row = 0; row < points && row < a0.size(); ++row)
        for (const auto& [column, weight] : a0[row]) product[column] += stored[w][row] * to_real(weight);
      if (sector.kind == SectorKind::Dart) {  // e_k is e_0 again: the plane is kept by A0 with the slit folded shut
        const SectorLayout layout(sector);
        product[layout.edge(0)] += product[layout.edge(sector.faces)];
        product[layout.edge(sector.faces)] = 0;
      }
      Real pu = 0, pv = 0;
      for (std::size_t h = 0; h < points; ++h) pu += product[h] * stored[0][h], pv += product[h] * stored[1][h];
      const Real a = det == 0 ? Real(0) : (pu * vv - pv * uv) / det, b = det == 0 ? Real(0) : (pv * uu - pu * uv) / det;
      Real residual = 0;
      for (std::size_t h = 0; h < points; ++h) residual = std::max(residual, magnitude(product[h] - a * stored[0][h] - b * stored[1][h]));
      if (det == 0 || residual > Real("1e-30"))
        failures.push_back(where + ": the tangent stencils do not span a plane that A0 keeps (residual " + to_string(residual, 3) + ")");
    }
  }
}

}  // namespace

std::vector<std::string> verify_quad_descent(const TableDocument& table, const QuadScheme& scheme) {
  const DocumentReader<ojson> r(table.origin);
  const ojson& doc = table.doc;
  if (table.format != kQuadDescentFormat) r.fail("format", "is not \"" + std::string(kQuadDescentFormat) + "\"");
  const long version = r.integer(r.require(doc, "version", ""), "version", 1, kQuadDescentVersion);
  std::vector<std::string> failures;
  if (version < 2) failures.push_back("version 1: no tangent stencils (regenerate the tables with this stencilgen)");
  const std::string& hash = r.string(r.require(doc, "scheme_hash", ""), "scheme_hash");
  if (hash != hex64(scheme.hash))
    failures.push_back("scheme hash " + excerpt(hash) + " is not that of '" + scheme.name + "' (" + hex64(scheme.hash) + ")");
  const ojson& valences = r.array(r.require(doc, "valences", ""), "valences");
  std::vector<int> listed;
  for (std::size_t k = 0; k < valences.size(); ++k) {
    const std::string field = field_path("valences", k);
    const int v = static_cast<int>(r.integer(r.require(valences[k], "valence", field), field_path(field, "valence"),
                                             scheme.min_valence, scheme.max_valence));
    if (v == 4) r.fail(field_path(field, "valence"), "4 is the regular patch, which has no entry");
    listed.push_back(v);
  }
  const ojson* sectors_json = version < kQuadDescentVersion ? nullptr : &r.array(r.require(doc, "sectors", ""), "sectors");
  const std::vector<BoundarySector> sectors = sectors_json ? listed_sectors(r, *sectors_json, scheme) : std::vector<BoundarySector>{};
  // One solve of everything the file lists: each entry is compared with its
  // solution, and the whole re-derived document with the file's.
  const QuadDescent fresh = quad_descent(scheme, listed, sectors);
  for (std::size_t k = 0; k < valences.size(); ++k) {
    const std::string field = field_path("valences", k);
    const int v = listed[k];
    const QuadDescent::Valence& d = fresh.valences[k];
    const std::size_t points = d.subdivision.extraordinary_child.size();
    const std::string where = "valence " + std::to_string(v);
    const auto a0 = exact_rows(r, r.require(valences[k], "ev_child", field), field_path(field, "ev_child"), points);
    if (a0 != d.subdivision.extraordinary_child) failures.push_back(where + ": A0 differs from the re-derived one");
    const ojson& children = r.array(r.require(valences[k], "regular_children", field), field_path(field, "regular_children"));
    if (children.size() != 3) r.fail(field_path(field, "regular_children"), "expected three children");
    for (std::size_t c = 0; c < 3; ++c)
      if (exact_rows(r, children[c], field_path(field_path(field, "regular_children"), c), points) !=
          d.subdivision.regular_children[c])
        failures.push_back(where + ": regular child " + std::to_string(c) + " differs from the re-derived one");
    if (version < 2) continue;
    const ojson& t = r.require(valences[k], "tangents", field);
    if (t.is_null() != !d.tangents) {
      failures.push_back(where + (t.is_null() ? ": no tangent stencils, but the scheme has them"
                                              : ": tangent stencils, but the scheme's spectrum gives none"));
      continue;
    }
    if (t.is_null()) continue;
    const std::string tf = field_path(field, "tangents");
    const Real lambda = decimal(r, r.require(t, "eigenvalue", tf), field_path(tf, "eigenvalue"));
    if (magnitude(lambda - d.tangents->eigenvalue) > Real("1e-35"))
      failures.push_back(where + ": the eigenvalue differs from the recomputed one");
    for (const char* which : {"u", "v"}) {
      const std::string wf = field_path(tf, which);
      const ojson& w = r.array(r.require(t, which, tf), wf);
      if (w.size() != points) r.fail(wf, "expected " + std::to_string(points) + " weights");
      std::vector<Real> stored;
      for (std::size_t h = 0; h < points; ++h) stored.push_back(decimal(r, w[h], field_path(wf, h)));
      const std::vector<Real>& recomputed = which[0] == 'u' ? d.tangents->u : d.tangents->v;
      Real difference = 0, residual = 0;
      for (std::size_t h = 0; h < points; ++h) difference = std::max(difference, magnitude(stored[h] - recomputed[h]));
      // t A0 - lambda t with the file's own exact A0.
      std::vector<Real> product(points, Real(0));
      for (std::size_t row = 0; row < points; ++row)
        for (const auto& [column, weight] : a0[row]) product[column] += stored[row] * to_real(weight);
      for (std::size_t h = 0; h < points; ++h) residual = std::max(residual, magnitude(product[h] - lambda * stored[h]));
      if (difference > Real("1e-35"))
        failures.push_back(where + ": tangent stencil " + which + " differs from the recomputed one by " + to_string(difference, 3));
      if (residual > Real("1e-30"))
        failures.push_back(where + ": tangent stencil " + which + " is not a left eigenvector of A0 (residual " +
                           to_string(residual, 3) + ")");
    }
  }
  if (!sectors_json) return failures;
  verify_sectors(r, *sectors_json, sectors, fresh.sectors, failures);
  // The sectors are those of boundary vertices in 1..F faces (with corners, darts and cones), none left out.
  int faces = 0;
  for (const BoundarySector& s : sectors) faces = std::max(faces, s.faces);
  const std::vector<BoundarySector> expected = faces > 0 ? boundary_sectors(faces, true) : std::vector<BoundarySector>{};
  if (sectors != expected)
    failures.push_back("sectors: not the full set of the boundary, crease, corner, dart and cone sectors in 1.." +
                       std::to_string(faces) + " faces, in the generator's order");
  // Everything else (mask, polynomial basis, nonnegativity flags, counts,
  // what no check above reads): the document re-derived for the same valences
  // and sectors equals the file's, field by field, as values (so that
  // reformatting the file is no difference).
  const ojson again = ojson::parse(quad_descent_to_json(scheme, fresh));
  for (const auto& [key, value] : again.items())
    if (!doc.contains(key) || doc[key] != value) failures.push_back(key + ": differs from the re-derived document");
  for (const auto& [key, value] : doc.items())
    if (!again.contains(key)) failures.push_back(key + ": is no field of a descent document");
  return failures;
}

}  // namespace sg
