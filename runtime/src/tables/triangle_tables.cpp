#include "triangle_tables.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <set>
#include <tuple>

#include "binary_reader.hpp"
#include "monomial_jet.hpp"
#include "stencil_runtime/limits.hpp"

namespace stencil_runtime {

namespace {

// Stencils per rate n: nodes, up centres, down centres.
std::size_t nodes_of(long n) { return static_cast<std::size_t>((n + 1) * (n + 2) / 2); }
std::size_t ups_of(long n) { return static_cast<std::size_t>(n * (n + 1) / 2); }
std::size_t downs_of(long n) { return static_cast<std::size_t>(n * (n - 1) / 2); }

// A region's children (version 3): `dilation`^2 cells, each with its kind and
// sparse rows over the region's `points` layout points, written row by row.
void read_children(detail::BinaryReader& r, std::size_t left, int dilation, std::uint32_t points, const std::string& where,
                   std::vector<TriangleChild>& out, std::uint32_t own_code = 0) {
  const auto count = r.get<std::uint32_t>();
  if (count != static_cast<std::uint32_t>(dilation * dilation))
    r.fail(where + ": " + std::to_string(count) + " children (the scheme's step makes " + std::to_string(dilation * dilation) + ")");
  for (std::uint32_t k = 0; k < count; ++k) {
    TriangleChild c;
    const auto valence = r.get<std::uint32_t>(), region = r.get<std::uint32_t>(), rotation = r.get<std::uint32_t>();
    if ((valence > static_cast<std::uint32_t>(limits::kMaxValence) && (own_code == 0 || valence != own_code)) || region > 3 ||
        rotation > 2)
      r.fail(where + ": child " + std::to_string(k) + " has an invalid kind");
    c.valence = static_cast<int>(valence), c.region = static_cast<int>(region), c.rotation = static_cast<int>(rotation);
    const auto entries = r.get<std::uint32_t>();
    if (entries == 0 || entries > left / 16) r.fail(where + ": child " + std::to_string(k) + ": truncated rows");
    c.rows.columns_count = points;
    std::uint32_t row = 0;
    for (std::uint32_t e = 0; e < entries; ++e) {
      const auto at = r.get<std::uint32_t>(), column = r.get<std::uint32_t>();
      const double w = r.get<double>();
      const bool in_order = e == 0 ? at == 0 : (at == row || at == row + 1);  // every row has an entry
      if (!in_order || column >= points || !std::isfinite(w))
        r.fail(where + ": child " + std::to_string(k) + ": invalid entry " + std::to_string(e));
      if (e > 0 && at == row + 1) c.rows.offsets.push_back(e), row = at;
      c.rows.columns.push_back(column);
      c.rows.weights.push_back(w);
    }
    c.rows.offsets.push_back(entries);
    out.push_back(std::move(c));
  }
}

// Stencil triples (value, du, dv) of `points` entries each, without the
// entries where all three are zero: per stencil s, entries [start[s],
// start[s + 1]) of column and of wuv's triples.
void drop_common_zeros(const std::vector<double>& w, const std::vector<double>& du, const std::vector<double>& dv,
                       std::size_t points, std::vector<std::uint32_t>& start, std::vector<std::uint32_t>& column,
                       std::vector<double>& wuv) {
  const std::size_t stencils = points == 0 ? 0 : du.size() / points;
  start.assign(1, 0);
  column.clear(), wuv.clear();
  for (std::size_t s = 0; s < stencils; ++s) {
    for (std::size_t h = 0; h < points; ++h) {
      const std::size_t at = s * points + h;
      if (w[at] == 0 && du[at] == 0 && dv[at] == 0) continue;
      column.push_back(static_cast<std::uint32_t>(h));
      wuv.push_back(w[at]), wuv.push_back(du[at]), wuv.push_back(dv[at]);
    }
    if (column.size() > UINT32_MAX) throw LoadError("regular derivative stencils beyond 2^32 entries");
    start.push_back(static_cast<std::uint32_t>(column.size()));
  }
}

}  // namespace

// The tangent stencils at a patch's vertex (a valence's, version 4, or a
// sector's): eigenvalue, residual, then t_u and t_v over `points`.
static void read_tangents(detail::BinaryReader& r, std::size_t left, std::size_t points, const std::string& where,
                          TriangleTables::TangentData& out) {
  out.eigenvalue = r.get<double>();
  out.residual = r.get<double>();
  if (points > left / 16) r.fail(where + ": truncated tangent stencils");
  for (auto* t : {&out.u, &out.v}) {
    t->resize(points);
    for (double& x : *t) {
      x = r.get<double>();
      if (!std::isfinite(x)) r.fail(where + ": a tangent weight is not finite");
    }
  }
  if (!(out.eigenvalue > 0 && out.eigenvalue < 1) || !std::isfinite(out.residual))
    r.fail(where + ": invalid tangent eigenvalue or residual");
}

// Loop's boundary sectors (version 7): per sector its key, wedge layout, limit
// stencil, cells and tangents; every count, index and kind checked. The
// generator's layouts reach the wedge's second ring and hold k + 7 points at
// most; the reader allows the third ring and k + 16.
void TriangleTables::read_sectors(detail::BinaryReader& r, const std::function<std::size_t()>& left, TriangleTables& t) {
  constexpr int kMaxRing = 3, kMaxExtraPoints = 16;
  const auto count = r.get<std::uint32_t>();
  if (count > 0 && t.refinement_ != TriangleRefinement::Loop) r.fail("sqrt(3) tables with boundary sectors");
  if (count > 0 && !t.crease_) r.fail("boundary sectors in tables without a crease rule");
  if (count > left() / 64) r.fail("truncated sector list");
  const Valence* regular = t.find(6);
  const std::size_t regular_points = regular->regions[0].layout.size();
  for (std::uint32_t s = 0; s < count; ++s) {
    Sector sector;
    const auto rule = r.get<std::uint8_t>();
    const auto faces = r.get<std::uint32_t>(), position = r.get<std::uint32_t>();
    if (rule > 3 || faces < 1 || faces > static_cast<std::uint32_t>(limits::kMaxValence) || position >= faces ||
        (rule == 0 && faces == 3) || (rule >= 2 && faces < 3) || (rule == 3 && position != 0))
      r.fail("sector " + std::to_string(s) + ": invalid kind (rule " + std::to_string(rule) + ", " + std::to_string(faces) +
             " faces, face " + std::to_string(position) + "; a boundary vertex in three faces has the regular patch, a "
             "dart or cone point has at least three, a cone point's is stored for face 0)");
    sector.key = {static_cast<SectorRule>(rule), static_cast<int>(faces), static_cast<int>(position)};
    const std::string where = "sector " + std::to_string(s) + " (" + sector.key.name() + ")";
    if (t.sector_code(sector.key)) r.fail(where + " is stored twice");
    // A cone point's chart is the closed ring: e_0..e_{k-1}, no ray k.
    const bool cone = sector.key.rule == SectorRule::Cone;
    const std::uint32_t rays = cone ? faces : faces + 1;
    const auto points = r.get<std::uint32_t>();
    if (points < rays + 1 || points > faces + kMaxExtraPoints)
      r.fail(where + ": a layout of " + std::to_string(points) + " points (B and e_0..e_k, and at most " +
             std::to_string(kMaxExtraPoints) + " more)");
    if (points > left() / 20) r.fail(where + ": truncated layout");
    Region region;
    const int k = static_cast<int>(faces);
    std::set<std::tuple<int, int, int>> seen;
    for (std::uint32_t h = 0; h < points; ++h) {
      ChartPoint p{r.get<std::int32_t>(), r.get<std::int32_t>(), r.get<std::int32_t>()};
      const bool vertex = p.sector == 0 && p.a == 0 && p.b == 0;
      const bool inside = p.sector >= 0 && p.sector < k && p.a >= 1 && p.a <= kMaxRing && p.b >= 0 && p.b < p.a;
      const bool ray = !cone && p.sector == k && p.a >= 1 && p.a <= kMaxRing && p.b == 0;
      // B first, then e_0..e_k (e_{k-1} for a cone point), as the family gathers them.
      const bool in_place = h == 0 ? vertex : h <= rays ? (p.a == 1 && p.b == 0 && p.sector == static_cast<int>(h) - 1)
                                                      : (inside || ray) && p.a >= 2;
      if (!in_place)
        r.fail(where + ": invalid layout point " + std::to_string(h) + " [" + std::to_string(p.sector) + "," +
               std::to_string(p.a) + "," + std::to_string(p.b) + "]");
      if (!seen.insert({p.sector, p.a, p.b}).second) r.fail(where + ": layout point " + std::to_string(h) + " is repeated");
      region.layout.push_back(p);
    }
    if (points > left() / 8) r.fail(where + ": truncated limit stencil");
    double sum = 0;
    sector.limit.resize(points);
    for (double& x : sector.limit) {
      x = r.get<double>();
      if (!std::isfinite(x)) r.fail(where + ": a limit weight is not finite");
      sum += x;
    }
    if (std::abs(sum - 1) > 1e-9) r.fail(where + ": the limit stencil does not sum to 1");
    // The file names the child at B by format::kTriangleSectorCode + s; the runtime by sector_kind(key).
    const std::uint32_t file_code = format::kTriangleSectorCode + s;
    const int code = sector_kind(sector.key);
    read_children(r, left(), t.dilation(), points, where, region.children, file_code);
    for (std::size_t c = 0; c < region.children.size(); ++c) {
      TriangleChild& child = region.children[c];
      const bool own = c == 0;
      if (child.valence != (own ? static_cast<int>(file_code) : 6) || child.region != 0 || child.rotation != 0 ||
          child.rows.rows() != (own ? points : regular_points))
        r.fail(where + ": cell " + std::to_string(c) + " is not " + (own ? "the sector's own patch" : "a regular patch"));
      if (own) child.valence = code;
      for (std::size_t row = 0; row < child.rows.rows(); ++row) {
        double negative = 0;
        for (std::size_t e = child.rows.offsets[row]; e != child.rows.offsets[row + 1]; ++e)
          negative += std::max(0.0, -child.rows.weights[e]);
        if (own && negative > 0) sector.spread = INFINITY;
        else if (!own) sector.spread = std::max(sector.spread, negative);
      }
    }
    Valence& v = *sector.data;
    v.valence = code;
    v.exact = sector.key.rule != SectorRule::Dart;  // a dart's may come from 80 digits (Loop's smooth rule)
    if (left() < 1) r.fail(where + ": truncated before its tangent flag");
    const auto flag = r.get<std::uint8_t>();
    if (flag > 1 || (flag == 1 && (sector.key.rule == SectorRule::Corner || cone))) r.fail(where + ": invalid tangent flag");
    if (flag == 1) read_tangents(r, left(), points, where, v.tangents);
    v.regions.push_back(std::move(region));
    for (std::size_t slot = 0; slot < t.rates_.size(); ++slot) sector.rates.push_back(std::make_unique<SectorRate>());
    t.sector_at_.emplace(code, t.sectors_.size());
    t.sectors_.push_back(std::move(sector));
  }
}

TriangleTables TriangleTables::load(const std::string& path, std::uint64_t expected_hash) {
  const std::string bytes = detail::read_binary_file(path);
  detail::BinaryReader r(bytes, path);
  detail::check_envelope(bytes, r, format::kTriangleMagic, "binary triangle table");
  const auto version = r.get<std::uint32_t>();
  if (version < 2 || version > format::kTriangleVersion)
    r.fail("format version " + std::to_string(version) + " is not supported (expected 2 to " +
           std::to_string(format::kTriangleVersion) + "; regenerate the tables with this stencilgen)");
  const auto scalar = r.get<std::uint32_t>();
  if (scalar != 4 && scalar != 8) r.fail("invalid scalar size " + std::to_string(scalar));
  TriangleTables t;
  t.single_precision_ = scalar == 4;
  t.hash_ = r.get<std::uint64_t>();
  if (expected_hash != 0 && t.hash_ != expected_hash) r.fail("made from a different scheme (hash mismatch)");
  const auto refinement = r.get<std::uint8_t>();
  if (refinement > 1) r.fail("unknown refinement " + std::to_string(refinement));
  t.refinement_ = static_cast<TriangleRefinement>(refinement);
  t.descent_ = version >= 3;
  t.edge_end_ = r.get<double>();
  t.edge_opposite_ = r.get<double>();
  const double neighbour_regular = r.get<double>();
  if (version >= 5) {
    const auto has_crease = r.get<std::uint8_t>();
    if (has_crease > 1) r.fail("invalid crease flag " + std::to_string(has_crease));
    const double centre = r.get<double>(), neighbour = r.get<double>();
    if (has_crease) {
      if (!std::isfinite(centre) || !std::isfinite(neighbour) || std::abs(centre + 2 * neighbour - 1) > 1e-12)
        r.fail("the crease rule's weights do not sum to 1");
      t.crease_ = TriangleTables::CreaseRule{centre, neighbour};
    }
  }
  // Bytes left before the checksum.
  auto left = [&] { return bytes.size() - 8 - std::min(bytes.size() - 8, r.position()); };
  const auto rate_count = r.get<std::uint32_t>();
  if (rate_count == 0 || rate_count > left() / 4) r.fail("invalid rate list");
  for (std::uint32_t k = 0; k < rate_count; ++k) {
    const auto n = r.get<std::uint32_t>();
    if (n == 0 || n > static_cast<std::uint32_t>(limits::kMaxRate) || (!t.rates_.empty() && static_cast<int>(n) <= t.rates_.back()))
      r.fail("invalid rate " + std::to_string(n) + " (rates are 1.." + std::to_string(limits::kMaxRate) + ", ascending)");
    t.rates_.push_back(static_cast<int>(n));
  }
  const auto valence_count = r.get<std::uint32_t>();
  if (valence_count > left() / 32) r.fail("truncated valence list");
  for (std::uint32_t k = 0; k < valence_count; ++k) {
    Valence v;
    const auto valence = r.get<std::uint32_t>();
    if (valence < 3 || valence > static_cast<std::uint32_t>(limits::kMaxValence))
      r.fail("valence " + std::to_string(valence) + " is outside 3.." + std::to_string(limits::kMaxValence) +
             " (the runtime's limit; regenerate the tables with valences up to " + std::to_string(limits::kMaxValence) + ")");
    v.valence = static_cast<int>(valence);
    if (t.find(v.valence)) r.fail("valence " + std::to_string(v.valence) + " is stored twice");
    v.exact = r.get<std::uint8_t>() != 0;
    v.residual = r.get<double>();
    v.neighbour = r.get<double>();
    const auto regions = r.get<std::uint32_t>();
    if (regions != 1 && regions != 4) r.fail("valence " + std::to_string(v.valence) + ": invalid region count " + std::to_string(regions));
    for (std::uint32_t g = 0; g < regions; ++g) {
      Region region;
      const std::string where = "valence " + std::to_string(v.valence) + (g ? ", band region " + std::to_string(g) : "");
      const auto points = r.get<std::uint32_t>();
      if (points == 0 || points > left() / 12) r.fail(where + ": truncated layout");
      for (std::uint32_t h = 0; h < points; ++h) {
        ChartPoint p{r.get<std::int32_t>(), r.get<std::int32_t>(), r.get<std::int32_t>()};
        const bool ev = p.sector == 0 && p.a == 0 && p.b == 0;
        if (!ev && (p.sector < 0 || p.sector >= v.valence || p.a < 1 || p.a > 64 || p.b < 0 || p.b >= p.a))
          r.fail(where + ": invalid layout point [" + std::to_string(p.sector) + "," + std::to_string(p.a) + "," +
                 std::to_string(p.b) + "]");
        region.layout.push_back(p);
      }
      const auto stencils = r.get<std::uint32_t>();
      if (stencils > left() / scalar / points) r.fail(where + ": truncated weights");
      region.weights.resize(static_cast<std::size_t>(stencils) * points);
      for (auto& x : region.weights) {
        x = scalar == 8 ? r.get<double>() : static_cast<double>(r.get<float>());
        if (!std::isfinite(x)) r.fail(where + ": a weight is not finite");
      }
      for (int n : t.rates_) {
        const std::size_t count = nodes_of(n) + ups_of(n) + downs_of(n);
        if (count > left() / 4) r.fail(where + ": truncated index block");
        std::vector<std::uint32_t> index(count);
        for (auto& x : index) {
          x = r.get<std::uint32_t>();
          if (x >= stencils) r.fail(where + ": stencil index out of range");
        }
        region.index.push_back(std::move(index));
      }
      if (t.descent_) read_children(r, left(), t.dilation(), points, where, region.children);
      v.regions.push_back(std::move(region));
    }
    if (v.valence == 6 && regions != 1) r.fail("the regular patch (valence 6) has band regions");
    if (version >= 4) {  // the tangent stencils at the vertex
      const auto flag = r.get<std::uint8_t>();
      if (flag > 1 || (flag == 1 && v.valence == 6)) r.fail("valence " + std::to_string(v.valence) + ": invalid tangent flag");
      if (flag == 1) read_tangents(r, left(), v.regions.front().layout.size(), "valence " + std::to_string(v.valence), v.tangents);
    }
    t.valences_.push_back(std::move(v));
  }
  if (t.descent_) {
    const Valence* regular = t.find(6);
    if (!regular) r.fail("holds no valence 6 (the regular patch)");
    const auto degree = r.get<std::uint32_t>();
    if (degree > MonomialJet::kMaxDegree)
      r.fail("the regular polynomial's degree " + std::to_string(degree) + " is above " + std::to_string(MonomialJet::kMaxDegree));
    t.degree_ = static_cast<int>(degree);
    const std::size_t terms = static_cast<std::size_t>((t.degree_ + 1) * (t.degree_ + 2) / 2);
    const std::size_t count = t.degree_ == 0 ? 0 : terms * regular->regions[0].layout.size();
    if (count > left() / 8) r.fail("truncated regular polynomial");
    t.polynomial_.resize(count);
    for (double& c : t.polynomial_) {
      c = r.get<double>();
      if (!std::isfinite(c)) r.fail("a regular polynomial coefficient is not finite");
    }
    if (version >= 6) {  // the regular patch's derivative stencils, parallel to its weights
      const auto flag = r.get<std::uint8_t>();
      if (flag > 1 || (flag == 1) != (t.degree_ == 0))
        r.fail("invalid regular derivative flag (derivative stencils go with a regular patch that is not a polynomial)");
      if (flag == 1) {
        Region& region = t.valences_[static_cast<std::size_t>(regular - t.valences_.data())].regions[0];
        const std::size_t count = region.weights.size();
        if (count > left() / scalar / 2) r.fail("truncated regular derivative stencils");
        for (auto* d : {&region.du, &region.dv}) {
          d->resize(count);
          for (double& x : *d) {
            x = scalar == 8 ? r.get<double>() : static_cast<double>(r.get<float>());
            if (!std::isfinite(x)) r.fail("a regular derivative weight is not finite");
          }
        }
      }
    }
    if (version >= 7) read_sectors(r, left, t);
    // Every child's kind is a patch the tables hold, and its rows cover the kind's layout.
    for (const Valence& v : t.valences_)
      for (std::size_t g = 0; g < v.regions.size(); ++g)
        for (const TriangleChild& c : v.regions[g].children) {
          const std::string where = "valence " + std::to_string(v.valence) + ", region " + std::to_string(g) + ": a child";
          if (c.valence != v.valence && c.valence != 6) r.fail(where + " of valence " + std::to_string(c.valence));
          const Valence* kind = t.find(c.valence);
          if (!kind || static_cast<std::size_t>(c.region) >= kind->regions.size())
            r.fail(where + " of a region the tables lack");
          if (c.rows.rows() != kind->regions[static_cast<std::size_t>(c.region)].layout.size())
            r.fail(where + " with " + std::to_string(c.rows.rows()) + " rows for a layout of " +
                   std::to_string(kind->regions[static_cast<std::size_t>(c.region)].layout.size()) + " points");
          for (double w : c.rows.weights) t.children_nonnegative_ = t.children_nonnegative_ && w >= 0;
        }
  }
  if (t.degree_ > 0) {
    // A polynomial regular basis (Loop): its derivative stencils at the stored
    // grid points, made once here, so that tessellation normals on regular
    // faces are stencil sums as the points are.
    Region& region = t.valences_[static_cast<std::size_t>(t.find(6) - t.valences_.data())].regions[0];
    const std::size_t points = region.layout.size(), terms = static_cast<std::size_t>((t.degree_ + 1) * (t.degree_ + 2) / 2);
    region.du.assign(region.weights.size(), 0.0);
    region.dv.assign(region.weights.size(), 0.0);
    for (std::size_t slot = 0; slot < t.rates_.size(); ++slot) {
      const long n = t.rates_[slot];
      const std::vector<std::uint32_t>& index = region.index[slot];
      std::size_t k = 0;
      for (int kind = 0; kind < 3; ++kind)
        for (long j = 0; j + kind <= n; ++j)
          for (long i = 0; i + j + kind <= n; ++i, ++k) {
            const double x = static_cast<double>(3 * i + kind) / (3.0 * n), y = static_cast<double>(3 * j + kind) / (3.0 * n);
            double* du = region.du.data() + static_cast<std::size_t>(index[k]) * points;
            double* dv = region.dv.data() + static_cast<std::size_t>(index[k]) * points;
            const MonomialJet m(t.degree_, x, y);
            for (std::size_t h = 0; h < points; ++h) {
              double wx = 0, wy = 0;
              for (std::size_t q = 0; q < terms; ++q) wx += t.polynomial_[h * terms + q] * m.dx[q], wy += t.polynomial_[h * terms + q] * m.dy[q];
              du[h] = wx, dv[h] = wy;
            }
          }
    }
  }
  if (r.position() != bytes.size() - 8) r.fail("unexpected trailing bytes");
  if (!std::isfinite(t.edge_end_) || !std::isfinite(t.edge_opposite_)) r.fail("an edge rule weight is not finite");
  for (const Valence& v : t.valences_)
    if (!std::isfinite(v.neighbour) || !std::isfinite(v.residual)) r.fail("valence " + std::to_string(v.valence) + ": the vertex rule is not finite");
  const Valence* regular = t.find(6);
  if (!regular) r.fail("holds no valence 6 (the regular patch)");
  if (regular->neighbour != neighbour_regular) r.fail("inconsistent regular vertex rule");
  {
    Region& region = t.valences_[static_cast<std::size_t>(regular - t.valences_.data())].regions[0];
    if (!region.du.empty())
      drop_common_zeros(region.weights, region.du, region.dv, region.layout.size(), region.sparse_start, region.sparse_column,
                        region.sparse_wuv);
  }
  for (std::size_t k = 0; k < t.rates_.size(); ++k) {
    const auto n = static_cast<std::size_t>(t.rates_[k]);
    if (t.slot_of_rate_.size() <= n) t.slot_of_rate_.resize(n + 1, -1);
    t.slot_of_rate_[n] = static_cast<int>(k);
  }
  return t;
}

const std::vector<double>* TriangleTables::tangent_u(int valence) const {
  const Valence* v = find(valence);
  return v && !v->tangents.u.empty() ? &v->tangents.u : nullptr;
}

const std::vector<double>* TriangleTables::tangent_v(int valence) const {
  const Valence* v = find(valence);
  return v && !v->tangents.v.empty() ? &v->tangents.v : nullptr;
}

bool TriangleTables::neighbour_weight(int valence, double& weight) const {
  const Valence* v = find(valence);
  if (v) weight = v->neighbour;
  return v != nullptr;
}

std::vector<int> TriangleTables::valences() const {
  std::vector<int> out;
  for (const auto& v : valences_) out.push_back(v.valence);
  return out;
}

std::optional<int> TriangleTables::sector_code(const SectorKey& key) const {
  if (!key.valid()) return std::nullopt;
  const int code = sector_kind(key);
  if (sector_at_.count(code) == 0) return std::nullopt;
  return code;
}

const TriangleTables::Sector* TriangleTables::find_sector(int code) const {
  const auto it = sector_at_.find(code);
  return it == sector_at_.end() ? nullptr : &sectors_[it->second];
}

const SectorKey& TriangleTables::sector(int code) const {
  const Sector* s = find_sector(code);
  if (!s) throw EvaluationError("no boundary sector of code " + std::to_string(code) + " in the triangle table");
  return s->key;
}

double TriangleTables::sector_spread(int code) const {
  sector(code);  // checks the code
  return find_sector(code)->spread;
}

// A sector's stencils at one stored rate n, on the grid 1/(3n) (nodes, up and
// down centres: the order of Grid::offset), by the recursion of the generator
// (generator/triangle/triangle_sector.hpp): W(0) the limit stencil; in the
// child at B (u + v <= 1/2) W(x) = W(2x) A0; in a regular cell the regular
// patch's stencil at the cell's parameter, which lies on the same grid (a
// node, or an up or down centre), through the cell's rows. Made into locals
// and moved in at the end, so a failure leaves nothing half made.
const TriangleTables::SectorRate& TriangleTables::sector_rate(const Sector& s, int slot) const {
  SectorRate& rate = *s.rates[static_cast<std::size_t>(slot)];
  std::call_once(rate.once, [&] {
    const Region& region = s.data->regions[0];
    const std::size_t m = region.layout.size();
    const long n = rates_[static_cast<std::size_t>(slot)], g = 3 * n;
    const std::size_t stencils = nodes_of(n) + ups_of(n) + downs_of(n);
    constexpr std::size_t kBudget = std::size_t(1) << 27;  // doubles: 1 GiB
    if (stencils > kBudget / m)
      throw EvaluationError("the stencils of the " + s.key.name() + " at rate " + std::to_string(n) + " would take " +
                            std::to_string(stencils * m / (1 << 17)) + " MiB (more than 1 GiB): use a lower rate");
    const SparseRows& a0 = region.children[0].rows;
    const Grid regular = grid(6, static_cast<int>(n));
    std::vector<double> weights(stencils * m), fine(m), coarse(m);
    std::vector<std::uint32_t> index(stencils);
    std::size_t k = 0;
    for (int kind = 0; kind < 3; ++kind)
      for (long j = 0; j + kind <= n; ++j)
        for (long i = 0; i + j + kind <= n; ++i, ++k) {
          // Double (I, J) while it lies in the child at B, then the regular cell's stencil there, then A0 back up.
          long I = 3 * i + kind, J = 3 * j + kind;
          int doublings = 0;
          while ((I != 0 || J != 0) && 2 * (I + J) <= g) I *= 2, J *= 2, ++doublings;
          if (I == 0 && J == 0) {
            fine = s.limit;
          } else {
            int cell;
            long a, b;
            if (2 * I >= g) cell = 1, a = 2 * I - g, b = 2 * J;
            else if (2 * J >= g) cell = 2, a = 2 * I, b = 2 * J - g;
            else cell = 3, a = 2 * (I + J) - g, b = g - 2 * I;
            const SparseRows& rows = region.children[static_cast<std::size_t>(cell)].rows;
            const double* w = regular.weights(static_cast<GridPoint>(a % 3), a / 3, b / 3);
            std::fill(fine.begin(), fine.end(), 0.0);
            for (std::size_t r = 0; r < rows.rows(); ++r)
              for (std::size_t e = rows.offsets[r]; e != rows.offsets[r + 1]; ++e) fine[rows.columns[e]] += w[r] * rows.weights[e];
          }
          for (int d = 0; d < doublings; ++d) {
            std::fill(coarse.begin(), coarse.end(), 0.0);
            for (std::size_t r = 0; r < m; ++r)
              for (std::size_t e = a0.offsets[r]; e != a0.offsets[r + 1]; ++e) coarse[a0.columns[e]] += fine[r] * a0.weights[e];
            fine.swap(coarse);
          }
          std::copy(fine.begin(), fine.end(), weights.begin() + static_cast<std::ptrdiff_t>(k * m));
          index[k] = static_cast<std::uint32_t>(k);
        }
    rate.weights = std::move(weights);
    rate.index = std::move(index);
  });
  return rate;
}

const TriangleTables::Valence* TriangleTables::find(int v) const {
  if (is_sector_code(v)) {
    const Sector* s = find_sector(v);
    return s ? s->data.get() : nullptr;
  }
  for (const auto& x : valences_)
    if (x.valence == v) return &x;
  return nullptr;
}

const TriangleTables::Valence& TriangleTables::data(int v) const {
  if (const Valence* x = find(v)) return *x;
  throw EvaluationError("valence " + std::to_string(v) + " is not in the triangle table");
}

int TriangleTables::rate_slot(int n) const {
  return n >= 0 && static_cast<std::size_t>(n) < slot_of_rate_.size() ? slot_of_rate_[static_cast<std::size_t>(n)] : -1;
}

const TriangleTables::Region& TriangleTables::region_data(int valence, int region) const {
  const Valence& v = data(valence);
  if (region < 0 || static_cast<std::size_t>(region) >= v.regions.size())
    throw EvaluationError("valence " + std::to_string(valence) + " has no region " + std::to_string(region) +
                            " in the triangle table");
  return v.regions[static_cast<std::size_t>(region)];
}

TriangleTables::Grid TriangleTables::grid(int valence, int n, int region) const {
  const Region& v = region_data(valence, region);
  const int slot = rate_slot(n);
  if (slot < 0) throw EvaluationError("rate " + std::to_string(n) + " is not in the triangle table");
  Grid g;
  if (const Sector* s = is_sector_code(valence) ? find_sector(valence) : nullptr) {
    const SectorRate& rate = sector_rate(*s, slot);
    g.weights_ = rate.weights.data();
    g.points_ = v.layout.size();
    g.index_ = rate.index.data();
    g.n_ = n;
    return g;
  }
  g.weights_ = v.weights.data();
  g.points_ = v.layout.size();
  g.index_ = v.index[static_cast<std::size_t>(slot)].data();
  g.n_ = n;
  if (!v.du.empty()) g.du_ = v.du.data(), g.dv_ = v.dv.data();
  if (!v.sparse_start.empty())
    g.sparse_start_ = v.sparse_start.data(), g.sparse_column_ = v.sparse_column.data(), g.sparse_wuv_ = v.sparse_wuv.data();
  return g;
}

std::size_t TriangleTables::Grid::stencil(GridPoint kind, long i, long j) const {
  // Row j of each kind holds (n + 1 - kind) - j points; rows are j-major.
  const long k = static_cast<long>(kind), side = n_ + 1 - k;  // points in row 0
  if (i < 0 || j < 0 || i + j >= side) throw EvaluationError("grid index outside the patch triangle");
  const std::size_t before = kind == GridPoint::Node ? 0 : kind == GridPoint::Up ? nodes_of(n_) : nodes_of(n_) + ups_of(n_);
  const std::size_t row = static_cast<std::size_t>(j * side - j * (j - 1) / 2);
  return static_cast<std::size_t>(index_[before + row + static_cast<std::size_t>(i)]);
}

const double* TriangleTables::Grid::weights(GridPoint kind, long i, long j) const { return weights_ + offset(kind, i, j); }

bool TriangleTables::Grid::derivative_weights(GridPoint kind, long i, long j, const double*& du, const double*& dv) const {
  if (!du_) return false;
  const std::size_t at = offset(kind, i, j);
  du = du_ + at, dv = dv_ + at;
  return true;
}

bool TriangleTables::Grid::sparse_jet(GridPoint kind, long i, long j, SparseJet& out) const {
  if (!sparse_start_) return false;
  const std::size_t s = stencil(kind, i, j), begin = sparse_start_[s];
  out.column = sparse_column_ + begin;
  out.wuv = sparse_wuv_ + 3 * begin;
  out.count = sparse_start_[s + 1] - begin;
  return true;
}

const double* TriangleTables::node_weights(int valence, int n, int i, int j) const { return grid(valence, n).weights(GridPoint::Node, i, j); }
const double* TriangleTables::up_weights(int valence, int n, int i, int j) const { return grid(valence, n).weights(GridPoint::Up, i, j); }
const double* TriangleTables::down_weights(int valence, int n, int i, int j) const { return grid(valence, n).weights(GridPoint::Down, i, j); }

}  // namespace stencil_runtime
