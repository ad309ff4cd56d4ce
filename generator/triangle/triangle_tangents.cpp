#include "triangle/triangle_tangents.hpp"

#include <map>
#include <tuple>

#include "base/error.hpp"

namespace sg {

std::optional<TangentStencils> triangle_ev_tangents(const std::vector<TriangleChild>& children,
                                                    const std::vector<SectorPoint>& layout, const TriangleTable& table,
                                                    std::string& why) {
  // The child at the vertex is the first "up" cell, with corners (0,0), (1,0), (0,1):
  // region 0 again, unrotated (triangle_children.hpp).
  if (children.empty() || children.front().valence != table.valence || children.front().region != 0 ||
      children.front().rotation != 0)
    throw Error("internal: the first child of an extraordinary patch is not its own region 0");
  const TriangleChild& ev = children.front();
  const std::size_t m = layout.size();
  if (ev.real_rows.size() != m) throw Error("internal: the child at the vertex has another layout");
  std::vector<std::vector<Real>> a0(m, std::vector<Real>(m, Real(0)));
  for (std::size_t r = 0; r < m; ++r)
    for (const auto& [c, w] : ev.real_rows[r]) a0[r][c] += w;
  // Region 0's node stencils at (n, 0) and (0, n), over the union layout.
  std::map<std::tuple<int, long, long>, std::size_t> position;
  for (std::size_t h = 0; h < m; ++h) position.emplace(std::tuple{layout[h].sector, layout[h].a, layout[h].b}, h);
  const TriangleTable::Region& region = table.regions.at(0);
  auto end = [&](long i, long j) {
    for (const TriangleTable::Entry& e : region.nodes) {
      if (e.i != i || e.j != j) continue;
      std::vector<Real> w(m, Real(0));
      for (std::size_t h = 0; h < region.layout.size(); ++h) {
        const SectorPoint& p = region.layout[h];
        w[position.at({p.sector, p.a, p.b})] =
            table.exact ? to_real(Rational(e.exact.num[h], e.exact.den)) : e.approx[h];
      }
      return w;
    }
    throw Error("internal: region 0 has no node (" + std::to_string(i) + ", " + std::to_string(j) + ")");
  };
  return tangent_stencils(a0, end(table.n, 0), end(0, table.n), why);
}

}  // namespace sg
