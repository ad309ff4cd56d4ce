#include "triangle/triangle_table_binary.hpp"

#include <map>
#include <optional>
#include <set>
#include <algorithm>
#include <tuple>
#include <tbb/parallel_for.h>

#include "base/error.hpp"
#include "common/byte_writer.hpp"
#include "stencil_runtime/binary_format.hpp"
#include "triangle/triangle_children.hpp"
#include "triangle/triangle_sector.hpp"
#include "triangle/triangle_sectors_json.hpp"
#include "triangle/triangle_tangents.hpp"

namespace sg {
namespace fmt = stencil_runtime::format;

namespace {

// The stencil's weights over the region's layout (the union of the rates' layouts).
std::vector<double> weights_over(const TriangleTable& t, const TriangleTable::Region& region, const TriangleTable::Entry& e,
                                 const std::map<std::tuple<int, long, long>, std::size_t>& position, std::size_t size) {
  std::vector<double> w(size, 0.0);
  for (std::size_t h = 0; h < region.layout.size(); ++h) {
    const SectorPoint& p = region.layout[h];
    const std::size_t at = position.at({p.sector, p.a, p.b});
    w[at] = t.exact ? to_double(Rational(e.exact.num[h], e.exact.den)) : to_double(e.approx[h]);
  }
  return w;
}

// An exact stencil (a derivative's) over the region's layout.
std::vector<double> exact_over(const TriangleTable::Region& region, const ScaledVector& e,
                               const std::map<std::tuple<int, long, long>, std::size_t>& position, std::size_t size) {
  std::vector<double> w(size, 0.0);
  for (std::size_t h = 0; h < region.layout.size(); ++h) {
    const SectorPoint& p = region.layout[h];
    w[position.at({p.sector, p.a, p.b})] = to_double(Rational(e.num[h], e.den));
  }
  return w;
}

// The union of the rates' layouts of each valence and region, in chart order
// (ring a, then sector, then b), with the points the children need besides.
TriangleLayouts union_layouts(const TriangleScheme& scheme, const TriangleTableSet& set) {
  TriangleLayouts out;
  for (std::size_t vi = 0; vi < set.valences.size(); ++vi) {
    const auto& tables = set.tables[vi];
    std::vector<std::vector<SectorPoint>> regions;
    for (std::size_t g = 0; g < tables.front().regions.size(); ++g) {
      std::set<std::tuple<long, int, long>> chart_order;
      for (const TriangleTable& t : tables)
        for (const SectorPoint& p : t.regions.at(g).layout) chart_order.emplace(p.a, p.sector, p.b);
      std::vector<SectorPoint> layout;
      for (const auto& [a, s, b] : chart_order) layout.push_back({s, a, b});
      regions.push_back(std::move(layout));
    }
    out.emplace_back(set.valences[vi], std::move(regions));
  }
  close_layouts(scheme, out);
  return out;
}

}  // namespace

std::vector<SectorPoint> regular_points(const TriangleScheme& scheme, const TriangleTableSet& set) {
  const TriangleLayouts layouts = union_layouts(scheme, set);
  for (const auto& [v, regions] : layouts)
    if (v == 6) return regions.front();
  throw Error("internal: the tables hold no regular patch (valence 6)");
}

namespace {

void put_children(std::string& out, const std::vector<TriangleChild>& children) {
  put<std::uint32_t>(out, static_cast<std::uint32_t>(children.size()));
  for (const TriangleChild& c : children) {
    put<std::uint32_t>(out, static_cast<std::uint32_t>(c.valence));
    put<std::uint32_t>(out, static_cast<std::uint32_t>(c.region));
    put<std::uint32_t>(out, static_cast<std::uint32_t>(c.rotation));
    std::size_t entries = 0;
    for (const auto& row : c.rows) entries += row.size();
    put<std::uint32_t>(out, static_cast<std::uint32_t>(entries));
    for (std::size_t r = 0; r < c.rows.size(); ++r)
      for (const auto& [column, w] : c.rows[r]) {
        put<std::uint32_t>(out, static_cast<std::uint32_t>(r));
        put<std::uint32_t>(out, static_cast<std::uint32_t>(column));
        put<double>(out, w);
      }
  }
}

// The sectors' layouts, limit stencils, cells and tangents (docs/table-format.md,
// "Loop boundary sectors"); none for sqrt(3) or a scheme without a crease curve.
void put_sectors(std::string& out, const TriangleScheme& scheme, const std::vector<TriangleSectorDescent>& data) {
  put<std::uint32_t>(out, static_cast<std::uint32_t>(data.size()));
  for (std::size_t s = 0; s < data.size(); ++s) {
    const TriangleSectorDescent& d = data[s];
    if (!d.exact && !(d.eigen_residual < Real("1e-60")))  // as the tables' own high-precision patches
      throw Error("scheme '" + scheme.name + "', " + d.sector.name() + ": the high-precision residual " +
                  to_string(d.eigen_residual, 3) + " is too large");
    put<std::uint8_t>(out, static_cast<std::uint8_t>(d.sector.kind));
    put<std::uint32_t>(out, static_cast<std::uint32_t>(d.sector.faces));
    put<std::uint32_t>(out, static_cast<std::uint32_t>(d.sector.position));
    put<std::uint32_t>(out, static_cast<std::uint32_t>(d.layout.size()));
    for (const WedgePoint& p : d.layout) {
      put<std::int32_t>(out, p.sector);
      put<std::int32_t>(out, static_cast<std::int32_t>(p.a));
      put<std::int32_t>(out, static_cast<std::int32_t>(p.b));
    }
    for (const SectorWeight& w : d.limit) put<double>(out, to_double(w.value));
    auto rows = [](const SectorRows& exact) {
      std::vector<std::vector<std::pair<std::size_t, double>>> r;
      for (const auto& row : exact) {
        r.emplace_back();
        for (const auto& [c, w] : row) r.back().emplace_back(c, to_double(w.value));
      }
      return r;
    };
    std::vector<TriangleChild> cells(4);
    cells[0].valence = static_cast<int>(fmt::kTriangleSectorCode + s);
    cells[0].rows = rows(d.child_at_vertex);
    for (std::size_t c = 0; c < 3; ++c) cells[c + 1].valence = 6, cells[c + 1].rows = rows(d.regular_children[c]);
    put_children(out, cells);
    put<std::uint8_t>(out, d.tangents ? 1 : 0);
    if (d.tangents) {
      put<double>(out, to_double(d.tangents->eigenvalue));
      put<double>(out, to_double(d.tangents->residual));
      for (const Real& w : d.tangents->u) put<double>(out, to_double(w));
      for (const Real& w : d.tangents->v) put<double>(out, to_double(w));
    }
  }
}

}  // namespace

std::string triangle_tables_to_binary(const TriangleScheme& scheme, const TriangleTableSet& set, BinaryPrecision precision,
                                      TriangleSectorSet* sectors_out,
                                      const std::function<void(const std::string&)>& progress) {
  const TriangleLayouts layouts = union_layouts(scheme, set);
  std::string out(fmt::kTriangleMagic, sizeof fmt::kTriangleMagic);
  put<std::uint32_t>(out, fmt::kTriangleVersion);
  put<std::uint32_t>(out, static_cast<std::uint32_t>(precision));
  put<std::uint64_t>(out, scheme.hash);
  put<std::uint8_t>(out, scheme.refinement == TriangleRefinement::Loop ? 0 : 1);
  put<double>(out, to_double(scheme.edge_end));
  put<double>(out, to_double(scheme.edge_opposite));
  put<double>(out, to_double(*scheme.exact_neighbour_weight(6)));
  put<std::uint8_t>(out, scheme.has_crease ? 1 : 0);  // then the crease rule's centre and neighbour (0 without one)
  put<double>(out, scheme.has_crease ? to_double(scheme.crease_centre) : 0.0);
  put<double>(out, scheme.has_crease ? to_double(scheme.crease_neighbour) : 0.0);
  put<std::uint32_t>(out, static_cast<std::uint32_t>(set.rates.size()));
  for (long n : set.rates) put<std::uint32_t>(out, static_cast<std::uint32_t>(n));
  put<std::uint32_t>(out, static_cast<std::uint32_t>(set.valences.size()));
  // Version 6: the regular patch's derivative stencils, parallel to its
  // stencils, where its basis is not a polynomial (sqrt(3)); Loop's polynomial serves.
  const std::vector<SectorPoint>* regular_layout = nullptr;
  for (const auto& [v, regions] : layouts)
    if (v == 6) regular_layout = &regions.front();
  if (!regular_layout) throw Error("internal: the tables hold no regular patch (valence 6)");
  const RegularPolynomial poly = regular_polynomial(scheme, *regular_layout);
  const bool regular_derivatives = poly.degree == 0;
  std::vector<std::vector<double>> regular_du, regular_dv;
  for (std::size_t vi = 0; vi < set.valences.size(); ++vi) {
    const auto& tables = set.tables[vi];
    const int v = set.valences[vi];
    bool exact = true;
    Real residual = 0;
    for (const TriangleTable& t : tables) exact = exact && t.exact, residual = std::max(residual, t.residual);
    put<std::uint32_t>(out, static_cast<std::uint32_t>(v));
    put<std::uint8_t>(out, exact ? 1 : 0);
    put<double>(out, to_double(residual));
    put<double>(out, to_double(scheme.real_neighbour_weight(v)));
    const std::size_t regions = tables.front().regions.size();
    std::vector<TriangleChild> region0_children;
    put<std::uint32_t>(out, static_cast<std::uint32_t>(regions));
    for (std::size_t g = 0; g < regions; ++g) {
      std::map<std::tuple<int, long, long>, std::size_t> position;
      for (const SectorPoint& p : layouts[vi].second[g]) position.emplace(std::tuple{p.sector, p.a, p.b}, position.size());
      put<std::uint32_t>(out, static_cast<std::uint32_t>(position.size()));
      std::vector<std::tuple<int, long, long>> ordered(position.size());
      for (const auto& [p, at] : position) ordered[at] = p;
      for (const auto& [s, a, b] : ordered) {
        put<std::int32_t>(out, s);
        put<std::int32_t>(out, static_cast<std::int32_t>(a));
        put<std::int32_t>(out, static_cast<std::int32_t>(b));
      }
      using Key = std::pair<std::pair<long, long>, std::pair<long, long>>;
      std::map<Key, std::uint32_t> slot;
      std::vector<std::vector<double>> stencils;
      std::vector<std::vector<std::uint32_t>> index(tables.size());
      for (std::size_t r = 0; r < tables.size(); ++r) {
        const TriangleTable& t = tables[r];
        const TriangleTable::Region& region = t.regions[g];
        auto intern = [&](const TriangleTable::Entry& e, long offset) {
          const Key key{reduced_fraction(3 * e.i + offset, 3 * t.n), reduced_fraction(3 * e.j + offset, 3 * t.n)};
          auto [it, fresh] = slot.emplace(key, static_cast<std::uint32_t>(stencils.size()));
          if (fresh) {
            stencils.push_back(weights_over(t, region, e, position, position.size()));
            if (v == 6 && g == 0 && regular_derivatives) {
              if (!t.derivatives) throw Error("internal: the regular table of rate " + std::to_string(t.n) + " has no derivatives");
              regular_du.push_back(exact_over(region, e.du, position, position.size()));
              regular_dv.push_back(exact_over(region, e.dv, position, position.size()));
            }
          }
          index[r].push_back(it->second);
        };
        for (const auto& e : region.nodes) intern(e, 0);
        for (const auto& e : region.up) intern(e, 1);
        for (const auto& e : region.down) intern(e, 2);
      }
      put<std::uint32_t>(out, static_cast<std::uint32_t>(stencils.size()));
      for (const auto& w : stencils)
        for (double x : w) put_scalar(out, x, precision);
      for (const auto& rate : index)
        for (std::uint32_t k : rate) put<std::uint32_t>(out, k);
      std::vector<TriangleChild> children = triangle_children(scheme, v, static_cast<int>(g), layouts);
      put_children(out, children);
      if (g == 0) region0_children = std::move(children);
    }
    // Version 4: the tangent stencils at the extraordinary vertex, over region 0's layout.
    std::string why;
    const std::optional<TangentStencils> tangents =
        v == 6 ? std::nullopt : triangle_ev_tangents(region0_children, layouts[vi].second.front(), tables.back(), why);
    put<std::uint8_t>(out, tangents ? 1 : 0);
    if (tangents) {
      put<double>(out, to_double(tangents->eigenvalue));
      put<double>(out, to_double(tangents->residual));
      for (const Real& w : tangents->u) put<double>(out, to_double(w));
      for (const Real& w : tangents->v) put<double>(out, to_double(w));
    }
  }
  // The regular patch's polynomial basis, where it is one (Loop).
  put<std::uint32_t>(out, static_cast<std::uint32_t>(poly.degree));
  for (const auto& point : poly.coefficients)
    for (double c : point) put<double>(out, c);
  put<std::uint8_t>(out, regular_derivatives ? 1 : 0);
  if (regular_derivatives) {
    if (regular_du.empty()) throw Error("internal: the tables hold no regular patch (valence 6)");
    for (const auto* d : {&regular_du, &regular_dv})
      for (const auto& w : *d)
        for (double x : w) put_scalar(out, x, precision);
  }
  // Version 7: Loop's boundary sectors, up to the largest valence asked for.
  TriangleSectorSet sectors = solve_triangle_sectors(scheme, *std::max_element(set.valences.begin(), set.valences.end()), *regular_layout,
                                                     progress);
  put_sectors(out, scheme, sectors.sectors);
  if (sectors_out) *sectors_out = std::move(sectors);
  put<std::uint64_t>(out, fmt::fnv1a64(reinterpret_cast<const unsigned char*>(out.data()), out.size()));
  return out;
}

}  // namespace sg
