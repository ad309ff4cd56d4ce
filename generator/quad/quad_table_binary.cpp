#include "quad/quad_table_binary.hpp"

#include <algorithm>
#include <map>

#include "base/error.hpp"
#include "common/byte_writer.hpp"
#include "quad/quad_descent.hpp"
#include "stencil_runtime/binary_format.hpp"

namespace sg {
namespace fmt = stencil_runtime::format;

namespace {

// Sparse rows: per row its entry count, then (column, weight) pairs.
void put_rows(std::string& out, const std::vector<SparseRow>& rows) {
  for (const SparseRow& row : rows) {
    put<std::uint32_t>(out, static_cast<std::uint32_t>(row.size()));
    for (const auto& [column, weight] : row) {
      put<std::uint32_t>(out, static_cast<std::uint32_t>(column));
      put<double>(out, to_double(weight));
    }
  }
}

// The regular curve's mask, the sign flags and the polynomial pieces (version 4).
void put_regular_descent(std::string& out, const QuadDescent& d) {
  put<std::int32_t>(out, static_cast<std::int32_t>(d.mask_first));
  put<std::uint32_t>(out, static_cast<std::uint32_t>(d.mask.size()));
  for (const Rational& a : d.mask) put<double>(out, to_double(a));
  put<std::uint8_t>(out, static_cast<std::uint8_t>((d.mask_nonnegative ? 1 : 0) | (d.derivative_nonnegative ? 2 : 0)));
  put<std::uint32_t>(out, d.pieces ? static_cast<std::uint32_t>(d.pieces->degree) : 0);
  if (d.pieces) {
    // The basis of point p = -1..2 on [0, 1]: phi(t - p), the piece m = -p.
    for (int p = -1; p <= 2; ++p)
      for (int e = 0; e <= d.pieces->degree; ++e) {
        const long m = -p;
        const bool inside = m >= d.pieces->first && m < d.pieces->first + static_cast<long>(d.pieces->pieces.size());
        put<double>(out, inside ? to_double(d.pieces->pieces[static_cast<std::size_t>(m - d.pieces->first)][static_cast<std::size_t>(e)]) : 0.0);
      }
  }
}

// The flag, then the eigenvalue (and, for a boundary sector, the second one), the residual and the two stencils.
void put_tangents(std::string& out, const std::optional<EvTangents>& t, bool second) {
  put<std::uint8_t>(out, t ? 1 : 0);
  if (!t) return;
  put<double>(out, to_double(t->eigenvalue));
  if (second) put<double>(out, to_double(t->second_eigenvalue));
  put<double>(out, to_double(t->residual));
  for (const Real& w : t->u) put<double>(out, to_double(w));
  for (const Real& w : t->v) put<double>(out, to_double(w));
}

std::uint64_t nonzeros(const std::vector<SparseRow>& rows) {
  std::uint64_t n = 0;
  for (const SparseRow& r : rows) n += r.size();
  return n;
}

}  // namespace

bool generated_layout_fits(const QuadTableSet& set) {
  std::uint64_t total = 0, work = 0;
  for (std::size_t vi = 0; vi < set.valences.size(); ++vi) {
    if (set.valences[vi] == 4) continue;
    const std::uint64_t points = set.tables[vi].front().points;
    const auto& d = *std::find_if(set.descent->valences.begin(), set.descent->valences.end(),
                                  [&](const QuadDescent::Valence& x) { return x.valence == set.valences[vi]; });
    std::uint64_t densest_child = 0;
    for (const auto& child : d.subdivision.regular_children) densest_child = std::max(densest_child, nonzeros(child));
    const std::uint64_t cell_cost = nonzeros(d.subdivision.extraordinary_child) + densest_child;
    for (long n : set.rates) {
      const std::uint64_t grid = fmt::expansion_grid_entries(static_cast<std::uint64_t>(n), points);
      if (grid > fmt::kMaxExpansionGridEntries) return false;
      total += grid;
      work += fmt::expansion_work(static_cast<std::uint64_t>(n), cell_cost);
    }
  }
  return total <= fmt::kMaxExpansionEntries && work <= fmt::kMaxExpansionWork;
}

std::string quad_tables_to_binary(const QuadScheme& scheme, const QuadTableSet& set, BinaryPrecision precision,
                                  BinaryLayout layout) {
  const bool generated = layout == BinaryLayout::Generated && generated_layout_fits(set);
  std::string out(fmt::kSurfaceMagic, sizeof fmt::kSurfaceMagic);
  put<std::uint32_t>(out, fmt::kSurfaceVersion);
  put<std::uint32_t>(out, static_cast<std::uint32_t>(precision));
  // Version 7: stored stencils or generated ones (binary_format.hpp).
  put<std::uint8_t>(out, static_cast<std::uint8_t>(generated ? fmt::SurfaceLayout::Generated : fmt::SurfaceLayout::Stored));
  put<std::uint64_t>(out, scheme.hash);
  put<std::uint32_t>(out, static_cast<std::uint32_t>(scheme.name.size()));
  out += scheme.name;
  // The subdivision rules, so that the runtime can refine a mesh with the
  // scheme's own step (isolating extraordinary vertices) without the scheme file.
  put<double>(out, to_double(scheme.face_corner));
  put<double>(out, to_double(scheme.edge_end));
  put<double>(out, to_double(scheme.edge_wing));
  std::vector<int> rule_valences{4};
  for (int v : set.valences)
    if (v != 4) rule_valences.push_back(v);
  put<std::uint32_t>(out, static_cast<std::uint32_t>(rule_valences.size()));
  for (int v : rule_valences) {
    const VertexRule r = scheme.vertex_rule(v);
    put<std::uint32_t>(out, static_cast<std::uint32_t>(v));
    put<double>(out, to_double(r.centre));
    put<double>(out, to_double(r.edge));
    put<double>(out, to_double(r.face));
  }
  // Optional polygon rules (one step on a mesh with non-quad faces), same valences.
  put<std::uint8_t>(out, scheme.polygon.present ? 1 : 0);
  if (scheme.polygon.present) {
    put<double>(out, to_double(scheme.polygon.edge_end));
    put<double>(out, to_double(scheme.polygon.edge_face));
    for (int v : rule_valences) {
      const auto r = scheme.polygon_vertex_rule(v);
      put<double>(out, to_double(r.centre));
      put<double>(out, to_double(r.midpoint));
      put<double>(out, to_double(r.face));
    }
  }
  put_regular_descent(out, *set.descent);
  put<std::uint32_t>(out, static_cast<std::uint32_t>(set.rates.size()));
  for (long n : set.rates) put<std::uint32_t>(out, static_cast<std::uint32_t>(n));
  for (const CurveSolution& c : set.regular) {
    const TypeValues& phi = c.types.at(0);
    put<std::int32_t>(out, static_cast<std::int32_t>(phi.range.first));
    put<std::uint32_t>(out, static_cast<std::uint32_t>(phi.range.size()));
    for (const Rational& x : phi.values) put_scalar(out, to_double(x), precision);
  }
  // Version 5: phi' of the regular curve per rate, dense from its first nonzero
  // grid index (count 0 where the curve has no continuous derivative).
  for (const CurveTable& t : set.regular_tables) {
    const auto& f = t.functions.at(0);
    const std::map<long, Rational> none;
    const auto& d = f.derivatives.empty() ? none : f.derivatives[0];
    const long first = d.empty() ? 0 : d.begin()->first, last = d.empty() ? -1 : d.rbegin()->first;
    put<std::int32_t>(out, static_cast<std::int32_t>(first));
    put<std::uint32_t>(out, static_cast<std::uint32_t>(last - first + 1));
    for (long k = first; k <= last; ++k) {
      const auto it = d.find(k);
      put_scalar(out, it == d.end() ? 0.0 : to_double(it->second), precision);
    }
  }
  // Valence 4 is the regular patch, evaluated from the curve values above.
  std::vector<std::size_t> stored;
  for (std::size_t vi = 0; vi < set.valences.size(); ++vi)
    if (set.valences[vi] != 4) stored.push_back(vi);
  put<std::uint32_t>(out, static_cast<std::uint32_t>(stored.size()));
  for (std::size_t vi : stored) {
    const auto& tables = set.tables[vi];
    using Key = std::pair<std::pair<long, long>, std::pair<long, long>>;
    std::map<Key, std::uint32_t> slot;
    std::vector<const ScaledVector*> stencils;
    std::vector<std::vector<std::uint32_t>> node_index(tables.size()), centre_index(tables.size());
    auto intern = [&](const QuadTable::Entry& e, long num_i, long num_j, long den) {
      const Key key{reduced_fraction(num_i, den), reduced_fraction(num_j, den)};
      auto [it, fresh] = slot.emplace(key, static_cast<std::uint32_t>(stencils.size()));
      if (fresh) stencils.push_back(&e.weights);
      return it->second;
    };
    for (std::size_t r = 0; r < tables.size(); ++r) {
      const QuadTable& t = tables[r];
      for (const auto& e : t.nodes) node_index[r].push_back(intern(e, e.i, e.j, t.n));
      for (const auto& e : t.centres) centre_index[r].push_back(intern(e, 2 * e.i + 1, 2 * e.j + 1, 2 * t.n));
    }
    const std::size_t points = tables.front().points;
    put<std::uint32_t>(out, static_cast<std::uint32_t>(set.valences[vi]));
    put<std::uint32_t>(out, static_cast<std::uint32_t>(points));
    for (std::size_t h : tables.front().reflection) put<std::uint32_t>(out, static_cast<std::uint32_t>(h));
    if (generated) {
      // The limit stencil W(0): the node (0, 0), first of every rate's nodes.
      const QuadTable::Entry& origin = tables.front().nodes.front();
      if (origin.i != 0 || origin.j != 0) throw Error("internal: the first node of a quad table is not (0, 0)");
      const ScaledVector& w = origin.weights;
      for (const Integer& x : w.num) put_scalar(out, to_double(Rational(x, w.den)), precision);
    } else {
      put<std::uint32_t>(out, static_cast<std::uint32_t>(stencils.size()));
      for (const ScaledVector* w : stencils)
        for (const Integer& x : w->num) put_scalar(out, to_double(Rational(x, w->den)), precision);
      for (std::size_t r = 0; r < tables.size(); ++r) {
        for (std::uint32_t k : node_index[r]) put<std::uint32_t>(out, k);
        for (std::uint32_t k : centre_index[r]) put<std::uint32_t>(out, k);
      }
    }
    // The patch's one-step subdivision: A0 (2V+8 rows), then the three regular children (16 rows each).
    const auto& descent = *std::find_if(set.descent->valences.begin(), set.descent->valences.end(),
                                        [&](const QuadDescent::Valence& d) { return d.valence == set.valences[vi]; });
    put<std::uint8_t>(out, descent.nonnegative ? 1 : 0);
    put_rows(out, descent.subdivision.extraordinary_child);
    for (const auto& child : descent.subdivision.regular_children) put_rows(out, child);
    // Version 6: the tangent stencils at the vertex (ev_tangents.hpp), in double whatever the precision.
    put_tangents(out, descent.tangents, false);
  }
  // Version 8: the boundary sectors (always generated: the reader expands each on first use).
  put<std::uint32_t>(out, static_cast<std::uint32_t>(set.descent->sectors.size()));
  for (const QuadDescent::Sector& sec : set.descent->sectors) {
    put<std::uint8_t>(out, static_cast<std::uint8_t>(sec.sector.kind));
    put<std::uint32_t>(out, static_cast<std::uint32_t>(sec.sector.faces));
    put<std::uint32_t>(out, static_cast<std::uint32_t>(sec.sector.position));
    put<std::uint32_t>(out, static_cast<std::uint32_t>(sec.subdivision.points));
    for (const Rational& x : sec.limit) put_scalar(out, to_double(x), precision);
    put<std::uint8_t>(out, sec.nonnegative ? 1 : 0);
    put_rows(out, sec.subdivision.extraordinary_child);
    for (const auto& child : sec.subdivision.regular_children) put_rows(out, child);
    put_tangents(out, sec.tangents, true);
  }
  put<std::uint64_t>(out, fmt::fnv1a64(reinterpret_cast<const unsigned char*>(out.data()), out.size()));
  return out;
}

}  // namespace sg
