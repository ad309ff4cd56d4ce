#include "quad/quad_descent_verify.hpp"

#include <algorithm>

#include "base/error.hpp"
#include "common/hash.hpp"
#include "common/json_document.hpp"
#include "quad/quad_descent.hpp"
#include "quad/quad_descent_json.hpp"

namespace sg {
using ojson = nlohmann::ordered_json;

namespace {

Real magnitude(const Real& x) { return x < 0 ? Real(-x) : x; }

// Stored rows ([column, "p/q"] pairs) as exact sparse rows.
std::vector<SparseRow> rows_from(const DocumentReader<ojson>& r, const ojson& j, const std::string& field, std::size_t columns) {
  std::vector<SparseRow> out;
  const ojson& rows = r.array(j, field);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const std::string f = field_path(field, k);
    SparseRow row;
    for (std::size_t e = 0; e < r.array(rows[k], f).size(); ++e) {
      const std::string fe = field_path(f, e);
      const ojson& pair = r.array(rows[k][e], fe);
      if (pair.size() != 2) r.fail(fe, "expected [column, weight]");
      const long column = r.integer(pair[0], field_path(fe, 0), 0, static_cast<long>(columns) - 1);
      row.emplace_back(static_cast<std::size_t>(column), r.rational_literal(pair[1], field_path(fe, 1)));
    }
    out.push_back(std::move(row));
  }
  return out;
}

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
  for (std::size_t k = 0; k < valences.size(); ++k) {
    const std::string field = field_path("valences", k);
    const int v = static_cast<int>(r.integer(r.require(valences[k], "valence", field), field_path(field, "valence"),
                                             scheme.min_valence, scheme.max_valence));
    if (v == 4) r.fail(field_path(field, "valence"), "4 is the regular patch, which has no entry");
    const QuadDescent fresh = quad_descent(scheme, {v});
    const QuadDescent::Valence& d = fresh.valences.front();
    const std::size_t points = d.subdivision.extraordinary_child.size();
    const std::string where = "valence " + std::to_string(v);
    const auto a0 = rows_from(r, r.require(valences[k], "ev_child", field), field_path(field, "ev_child"), points);
    if (a0 != d.subdivision.extraordinary_child) failures.push_back(where + ": A0 differs from the re-derived one");
    const ojson& children = r.array(r.require(valences[k], "regular_children", field), field_path(field, "regular_children"));
    if (children.size() != 3) r.fail(field_path(field, "regular_children"), "expected three children");
    for (std::size_t c = 0; c < 3; ++c)
      if (rows_from(r, children[c], field_path(field_path(field, "regular_children"), c), points) !=
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
  return failures;
}

}  // namespace sg
