#include "quad/quad_descent_json.hpp"

#include <nlohmann/json.hpp>

#include "common/exact_rows.hpp"
#include "common/hash.hpp"
#include "common/parameters_json.hpp"

namespace sg {

using ojson = nlohmann::ordered_json;

namespace {

// A0 ("ev_child") and the three regular children.
void put_subdivision(ojson& entry, const PatchSubdivision& s) {
  const auto text = [](const Rational& w) { return to_string(w); };
  entry["ev_child"] = exact_rows_json(s.extraordinary_child, text);
  ojson children = ojson::array();
  for (const auto& child : s.regular_children) children.push_back(exact_rows_json(child, text));
  entry["regular_children"] = children;
}

// The tangent stencils, or null; `both`: with the second eigenvalue (boundary sectors).
ojson tangents_json(const std::optional<EvTangents>& tangents, bool both) {
  if (!tangents) return nullptr;
  ojson t;
  t["eigenvalue"] = to_string(tangents->eigenvalue, 40);
  if (both) t["second_eigenvalue"] = to_string(tangents->second_eigenvalue, 40);
  t["residual"] = to_string(tangents->residual, 3);
  for (const char* which : {"u", "v"}) {
    ojson w = ojson::array();
    for (const Real& x : (which[0] == 'u' ? tangents->u : tangents->v)) w.push_back(to_string(x, 40));
    t[which] = w;
  }
  return t;
}

}  // namespace

std::string quad_descent_to_json(const QuadScheme& scheme, const QuadDescent& d) {
  ojson doc;
  doc["format"] = kQuadDescentFormat;
  doc["version"] = kQuadDescentVersion;
  doc["scheme"] = scheme.name;
  doc["scheme_hash"] = hex64(scheme.hash);
  doc["parameters"] = parameters_json<ojson>(scheme.parameters);  // so that `stencilgen verify` re-derives it
  doc["meaning"] =
      "The scheme's own subdivision of a patch, for evaluation at any parameter (docs/runtime.md). mask: the regular "
      "curve's a_i from i = first (p'_k = sum_j a_{k-2j} p_j); polynomial_basis: phi(t - p) on [0,1] for p = -1..2, "
      "coefficients of t^0.. (null: not polynomial); per valence: A0 (ev_child, 2v+8 rows) and the regular children at "
      "offsets (1,0), (0,1), (1,1) (16 rows each), rows as [column, weight] pairs over the patch's 2v+8 points; tangents: "
      "two stencils over the same points whose combinations of the control points span the tangent plane at the "
      "extraordinary vertex (left eigenvectors of A0 for its subdominant eigenvalue, along the patch's u and v edges; "
      "not parametric derivatives), 40 digits, with the residual max |t A0 - eigenvalue t| (null: none, no_tangents says why); "
      "sectors: the patches of the faces at a vertex on a boundary or infinitely sharp crease (kind crease: the vertex "
      "follows the boundary curve; corner: it stays put; dart: the end of a crease, the smooth rule at valence k), k faces, the face at position p, over the sector's points (docs/table-format.md), with the "
      "vertex's exact limit stencil; their tangents: u along the patch's u edge, v towards its corner (1,1), eigenvalues "
      "of the two eigenvectors that span the plane.";
  ojson mask;
  mask["first"] = d.mask_first;
  ojson coefficients = ojson::array();
  for (const Rational& a : d.mask) coefficients.push_back(to_string(a));
  mask["coefficients"] = coefficients;
  doc["mask"] = mask;
  doc["mask_nonnegative"] = d.mask_nonnegative;
  doc["derivative_nonnegative"] = d.derivative_nonnegative;
  if (d.pieces) {
    ojson basis = ojson::array();
    for (int p = -1; p <= 2; ++p) {
      ojson piece = ojson::array();
      for (int e = 0; e <= d.pieces->degree; ++e) {
        const long m = -p;
        const bool inside = m >= d.pieces->first && m < d.pieces->first + static_cast<long>(d.pieces->pieces.size());
        piece.push_back(inside ? to_string(d.pieces->pieces[static_cast<std::size_t>(m - d.pieces->first)][static_cast<std::size_t>(e)])
                               : std::string("0"));
      }
      basis.push_back(piece);
    }
    doc["polynomial_basis"] = {{"degree", d.pieces->degree}, {"pieces", basis}};
  } else {
    doc["polynomial_basis"] = nullptr;
  }
  ojson valences = ojson::array();
  for (const QuadDescent::Valence& v : d.valences) {
    ojson entry;
    entry["valence"] = v.valence;
    entry["nonnegative"] = v.nonnegative;
    put_subdivision(entry, v.subdivision);
    // Version 2: the tangent stencils at the vertex, in 40 significant digits
    // (lambda is irrational in general), with the residual max |t A0 - lambda t|.
    entry["tangents"] = tangents_json(v.tangents, false);
    if (!v.tangents) entry["no_tangents"] = v.no_tangents;
    valences.push_back(entry);
  }
  doc["valences"] = valences;
  // Version 3: the boundary sectors.
  ojson sectors = ojson::array();
  for (const QuadDescent::Sector& sec : d.sectors) {
    ojson entry;
    entry["kind"] = sector_kind_name(sec.sector.kind);
    entry["faces"] = sec.sector.faces;
    entry["position"] = sec.sector.position;
    entry["points"] = sec.subdivision.points;
    entry["nonnegative"] = sec.nonnegative;
    ojson limit = ojson::array();
    for (const Rational& x : sec.limit) limit.push_back(to_string(x));
    entry["limit"] = limit;
    put_subdivision(entry, sec.subdivision);
    entry["tangents"] = tangents_json(sec.tangents, true);
    if (!sec.tangents) entry["no_tangents"] = sec.no_tangents;
    sectors.push_back(entry);
  }
  doc["sectors"] = sectors;
  return doc.dump() + "\n";
}

}  // namespace sg
