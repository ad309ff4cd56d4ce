#include "quad/quad_table_binary.hpp"

#include <map>

#include "base/error.hpp"
#include "common/byte_writer.hpp"
#include "stencil_runtime/binary_format.hpp"

namespace sg {
namespace fmt = stencil_runtime::format;

std::string quad_tables_to_binary(const QuadScheme& scheme, const QuadTableSet& set, BinaryPrecision precision) {
  std::string out(fmt::kSurfaceMagic, sizeof fmt::kSurfaceMagic);
  put<std::uint32_t>(out, fmt::kSurfaceVersion);
  put<std::uint32_t>(out, static_cast<std::uint32_t>(precision));
  put<std::uint64_t>(out, scheme.hash);
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
  put<std::uint32_t>(out, static_cast<std::uint32_t>(set.rates.size()));
  for (long n : set.rates) put<std::uint32_t>(out, static_cast<std::uint32_t>(n));
  for (const CurveSolution& c : set.regular) {
    const TypeValues& phi = c.types.at(0);
    put<std::int32_t>(out, static_cast<std::int32_t>(phi.range.first));
    put<std::uint32_t>(out, static_cast<std::uint32_t>(phi.range.size()));
    for (const Rational& x : phi.values) put_scalar(out, to_double(x), precision);
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
    put<std::uint32_t>(out, static_cast<std::uint32_t>(stencils.size()));
    for (std::size_t h : tables.front().reflection) put<std::uint32_t>(out, static_cast<std::uint32_t>(h));
    for (const ScaledVector* w : stencils)
      for (const Integer& x : w->num) put_scalar(out, to_double(Rational(x, w->den)), precision);
    for (std::size_t r = 0; r < tables.size(); ++r) {
      for (std::uint32_t k : node_index[r]) put<std::uint32_t>(out, k);
      for (std::uint32_t k : centre_index[r]) put<std::uint32_t>(out, k);
    }
  }
  put<std::uint64_t>(out, fmt::fnv1a64(reinterpret_cast<const unsigned char*>(out.data()), out.size()));
  return out;
}

}  // namespace sg
