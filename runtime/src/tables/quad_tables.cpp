#include "quad_tables.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "binary_reader.hpp"
#include "quad_expansion.hpp"
#include "stencil_runtime/binary_format.hpp"
#include "stencil_runtime/limits.hpp"

namespace stencil_runtime {

namespace {

std::vector<double> read_scalars(detail::BinaryReader& r, std::size_t count, std::uint32_t bytes, std::size_t available) {
  if (count > available / bytes) r.fail("truncated scalar block");
  std::vector<double> out(count);
  for (auto& x : out) x = bytes == 8 ? r.get<double>() : static_cast<double>(r.get<float>());
  return out;
}

// `rows` sparse rows over `columns` inputs: per row an entry count, then (column, weight) pairs.
SparseRows read_rows(detail::BinaryReader& r, std::size_t rows, std::size_t columns, const std::string& what) {
  SparseRows m;
  m.columns_count = columns;
  for (std::size_t k = 0; k < rows; ++k) {
    const auto count = r.get<std::uint32_t>();
    if (count > columns) r.fail(what + ": a row has " + std::to_string(count) + " entries for " + std::to_string(columns) + " points");
    for (std::uint32_t e = 0; e < count; ++e) {
      const auto column = r.get<std::uint32_t>();
      const double weight = r.get<double>();
      if (column >= columns) r.fail(what + ": column " + std::to_string(column) + " out of range");
      if (!std::isfinite(weight)) r.fail(what + ": a weight is not finite");
      m.columns.push_back(column);
      m.weights.push_back(weight);
    }
    m.offsets.push_back(m.columns.size());
  }
  return m;
}

std::size_t half_count(long side) { return static_cast<std::size_t>(side * (side + 1) / 2); }

bool finite(const std::vector<double>& xs) {
  return std::all_of(xs.begin(), xs.end(), [](double x) { return std::isfinite(x); });
}

// The tangent stencils at the vertex (version 6), with the second eigenvalue for a boundary sector (version 8).
void read_tangents(detail::BinaryReader& r, QuadDescent::Valence& d, std::size_t points, bool second, const std::string& where,
                   std::size_t available) {
  const auto tangents = r.get<std::uint8_t>();
  if (tangents > 1) r.fail(where + ": invalid tangent flag");
  if (tangents == 0) return;
  d.tangent_eigenvalue = r.get<double>();
  d.tangent_second_eigenvalue = second ? r.get<double>() : d.tangent_eigenvalue;
  d.tangent_residual = r.get<double>();
  d.tangent_u = read_scalars(r, points, 8, available);
  d.tangent_v = read_scalars(r, points, 8, available);
  auto eigenvalue = [](double x) { return std::isfinite(x) && x > 0 && x < 1; };
  if (!eigenvalue(d.tangent_eigenvalue) || !eigenvalue(d.tangent_second_eigenvalue) || !std::isfinite(d.tangent_residual) ||
      !finite(d.tangent_u) || !finite(d.tangent_v))
    r.fail(where + ": invalid tangent stencils");
}

}  // namespace

QuadTables QuadTables::load_binary(const std::string& path, std::uint64_t expected_hash) {
  const std::string bytes = detail::read_binary_file(path);
  detail::BinaryReader r(bytes, path);
  detail::check_envelope(bytes, r, format::kSurfaceMagic, "binary surface table");
  const auto version = r.get<std::uint32_t>();
  if (version != format::kSurfaceVersion)
    r.fail("format version " + std::to_string(version) + " is not supported (expected " +
           std::to_string(format::kSurfaceVersion) + "; regenerate the tables with this stencilgen)");
  const auto scalar = r.get<std::uint32_t>();
  if (scalar != 4 && scalar != 8) r.fail("invalid scalar size " + std::to_string(scalar));
  const auto layout_byte = r.get<std::uint8_t>();
  if (layout_byte > 1) r.fail("invalid stencil layout " + std::to_string(layout_byte));
  const bool generated = layout_byte == static_cast<std::uint8_t>(format::SurfaceLayout::Generated);
  QuadTables t;
  t.single_precision_ = scalar == 4;
  t.hash_ = r.get<std::uint64_t>();
  if (expected_hash != 0 && t.hash_ != expected_hash) r.fail("made from a different scheme (hash mismatch)");
  auto left = [&] { return bytes.size() - r.position(); };
  const auto name_length = r.get<std::uint32_t>();
  if (name_length == 0 || name_length > 256) r.fail("invalid scheme name length " + std::to_string(name_length));
  t.name_ = r.get_string(name_length);
  t.face_corner_ = r.get<double>();
  t.edge_end_ = r.get<double>();
  t.edge_wing_ = r.get<double>();
  const auto rule_count = r.get<std::uint32_t>();
  if (rule_count > left() / 28) r.fail("truncated rule list");
  for (std::uint32_t k = 0; k < rule_count; ++k) {
    VertexRule rule;
    rule.valence = static_cast<int>(r.get<std::uint32_t>());
    rule.centre = r.get<double>();
    rule.edge = r.get<double>();
    rule.face = r.get<double>();
    t.rules_.push_back(rule);
  }
  const auto polygon_flag = r.get<std::uint8_t>();
  if (polygon_flag > 1) r.fail("invalid polygon-rules flag " + std::to_string(polygon_flag));
  t.has_polygon_ = polygon_flag != 0;
  if (t.has_polygon_) {
    t.polygon_edge_end_ = r.get<double>();
    t.polygon_edge_face_ = r.get<double>();
    for (const auto& rule : t.rules_) {
      VertexRule p{rule.valence, r.get<double>(), r.get<double>(), r.get<double>()};
      t.polygon_rules_.push_back(p);
    }
  }
  {  // the regular curve's mask, sign flags and polynomial pieces
    QuadDescent& d = t.descent_;
    d.mask_first = r.get<std::int32_t>();
    const auto mask_size = r.get<std::uint32_t>();
    if (mask_size == 0 || mask_size > 32 || d.mask_first < -32 || d.mask_first > 32) r.fail("invalid regular mask");
    for (std::uint32_t k = 0; k < mask_size; ++k) d.mask.push_back(r.get<double>());
    const auto flags = r.get<std::uint8_t>();
    if (flags > 3) r.fail("invalid regular mask flags " + std::to_string(flags));
    d.mask_nonnegative = (flags & 1) != 0;
    d.derivative_nonnegative = (flags & 2) != 0;
    const auto degree = r.get<std::uint32_t>();
    if (degree > 7) r.fail("invalid polynomial degree " + std::to_string(degree) + " of the regular basis (0..7)");
    d.degree = static_cast<int>(degree);
    if (degree > 0)
      for (int p = 0; p < 4; ++p) {
        d.basis.emplace_back();
        for (std::uint32_t e = 0; e <= degree; ++e) d.basis.back().push_back(r.get<double>());
      }
    t.has_descent_ = true;
  }
  const auto rate_count = r.get<std::uint32_t>();
  if (rate_count > left() / 4) r.fail("truncated rate list");
  for (std::uint32_t k = 0; k < rate_count; ++k) {
    const auto n = r.get<std::uint32_t>();
    if (n == 0 || n > static_cast<std::uint32_t>(limits::kMaxRate))
      r.fail("invalid rate " + std::to_string(n) + " (rates are 1.." + std::to_string(limits::kMaxRate) + ")");
    t.rates_.push_back(static_cast<int>(n));
  }
  for (std::uint32_t k = 0; k < rate_count; ++k) {
    t.regular_first_.push_back(r.get<std::int32_t>());
    const auto count = r.get<std::uint32_t>();
    t.regular_.push_back(read_scalars(r, count, scalar, left()));
  }
  for (std::uint32_t k = 0; k < rate_count; ++k) {  // version 5: phi' (count 0: no derivative)
    t.regular_derivative_first_.push_back(r.get<std::int32_t>());
    const auto count = r.get<std::uint32_t>();
    t.regular_derivative_.push_back(read_scalars(r, count, scalar, left()));
  }
  const auto valence_count = r.get<std::uint32_t>();
  if (valence_count > left() / 12) r.fail("truncated valence list");
  std::vector<std::vector<double>> limits_of_generated;  // per valence: W(0), expanded below
  std::uint64_t expansion_entries = 0;
  for (std::uint32_t k = 0; k < valence_count; ++k) {
    Valence v;
    const auto valence = r.get<std::uint32_t>();
    const auto points = r.get<std::uint32_t>();
    if (valence < 3 || valence > static_cast<std::uint32_t>(limits::kMaxValence))
      r.fail("valence " + std::to_string(valence) + " is outside 3.." + std::to_string(limits::kMaxValence) +
             " (the runtime's limit; regenerate the tables with valences up to " + std::to_string(limits::kMaxValence) + ")");
    v.valence = static_cast<int>(valence);
    v.points = static_cast<int>(points);
    if (v.points != QuadTables::points(v.valence)) r.fail("valence " + std::to_string(valence) + ": invalid point count");
    if (points > left() / 4) r.fail("truncated reflection");
    for (std::uint32_t h = 0; h < points; ++h) v.reflection.push_back(r.get<std::uint32_t>());
    if (generated) {
      // Refused before any work: a small file must not ask for a huge expansion.
      for (int n : t.rates_) {
        const std::uint64_t grid = format::expansion_grid_entries(static_cast<std::uint64_t>(n), points);
        expansion_entries += grid;
        if (grid > format::kMaxExpansionGridEntries || expansion_entries > format::kMaxExpansionEntries)
          r.fail("valence " + std::to_string(valence) + ", rate " + std::to_string(n) +
                 ": too large to expand at load time (the runtime's limit is " +
                 std::to_string(format::kMaxExpansionGridEntries) + " grid entries per rate and " +
                 std::to_string(format::kMaxExpansionEntries) + " in all; regenerate with --binary-layout stored)");
      }
      limits_of_generated.push_back(read_scalars(r, points, scalar, left()));
    }
    const auto stencils = generated ? 0 : r.get<std::uint32_t>();
    if (!generated) v.weights = read_scalars(r, static_cast<std::size_t>(stencils) * points, scalar, left());
    for (int n : generated ? std::vector<int>{} : t.rates_) {
      for (int kind = 0; kind < 2; ++kind) {
        const std::size_t count = half_count(kind == 0 ? n + 1 : n);
        if (count > left() / 4) r.fail("truncated index block");
        std::vector<std::uint32_t> index(count);
        for (auto& x : index) {
          x = r.get<std::uint32_t>();
          if (x >= stencils) r.fail("stencil index out of range");
        }
        (kind == 0 ? v.nodes : v.centres).push_back(std::move(index));
      }
    }
    QuadDescent::Valence d;
    const auto flag = r.get<std::uint8_t>();
    if (flag > 1) r.fail("valence " + std::to_string(valence) + ": invalid sign flag");
    d.nonnegative = flag == 1;
    const std::string where = "valence " + std::to_string(valence) + " patch subdivision";
    d.ev_child = read_rows(r, points, points, where);
    for (auto& child : d.regular_children) child = read_rows(r, 16, points, where);
    read_tangents(r, d, points, false, "valence " + std::to_string(valence), left());  // version 6
    t.descent_valences_.push_back(std::move(d));
    t.valences_.push_back(std::move(v));
  }
  const auto sector_count = r.get<std::uint32_t>();  // version 8: boundary sectors (9: cone points too)
  if (sector_count > left() / 14) r.fail("truncated sector list");
  for (std::uint32_t k = 0; k < sector_count; ++k) {
    Sector sec;
    const auto rule = r.get<std::uint8_t>();
    const auto faces = r.get<std::uint32_t>(), position = r.get<std::uint32_t>(), points = r.get<std::uint32_t>();
    sec.key = {static_cast<SectorRule>(rule), static_cast<int>(std::min<std::uint32_t>(faces, 1024)),
               static_cast<int>(std::min<std::uint32_t>(position, 1024))};
    if (rule > 3 || !sec.key.valid())
      r.fail("boundary sector " + std::to_string(k) + ": invalid kind, face count (1.." + std::to_string(limits::kMaxValence) +
             ", a dart or cone 3..) or position (a cone: 0)");
    const std::string where = sec.key.name();
    if (points != static_cast<std::uint32_t>(sec.key.points())) r.fail(where + ": invalid point count");
    for (int n : t.rates_)  // expanded on first use: refused now if it could not be
      if (format::expansion_grid_entries(static_cast<std::uint64_t>(n), points) > format::kMaxExpansionGridEntries)
        r.fail(where + ", rate " + std::to_string(n) + ": too large to expand (the runtime's limit is " +
               std::to_string(format::kMaxExpansionGridEntries) + " grid entries per rate)");
    sec.limit = read_scalars(r, points, scalar, left());
    const auto flag = r.get<std::uint8_t>();
    if (flag > 1) r.fail(where + ": invalid sign flag");
    sec.descent.nonnegative = flag == 1;
    sec.descent.ev_child = read_rows(r, points, points, where + " patch subdivision");
    for (auto& child : sec.descent.regular_children) child = read_rows(r, 16, points, where + " patch subdivision");
    read_tangents(r, sec.descent, points, true, where, left());
    t.sectors_.push_back(std::move(sec));
  }
  if (r.position() != bytes.size() - 8) r.fail("unexpected trailing bytes");
  // Generated stencils: the patch recursion from what the file holds (quad_expansion.hpp);
  // validate() then checks them like stored ones (finite, indices in range, sums).
  // Its time is bounded first, now that the rows' sizes are known.
  std::uint64_t work = 0;
  for (std::size_t k = 0; k < limits_of_generated.size(); ++k) {
    const QuadDescent::Valence& d = t.descent_valences_[k];
    std::uint64_t densest_child = 0;
    for (const auto& child : d.regular_children) densest_child = std::max<std::uint64_t>(densest_child, child.weights.size());
    for (int n : t.rates_) {
      work += format::expansion_work(static_cast<std::uint64_t>(n), d.ev_child.weights.size() + densest_child);
      if (work > format::kMaxExpansionWork)
        r.fail("valence " + std::to_string(t.valences_[k].valence) + ": too much work to expand at load time (more than " +
               std::to_string(format::kMaxExpansionWork) + " multiply-adds, the runtime's limit; regenerate with --binary-layout stored)");
    }
  }
  for (std::size_t k = 0; k < limits_of_generated.size(); ++k) {
    Valence& v = t.valences_[k];
    ExpandedPatch e = expand_patch(v.valence, t.descent_valences_[k], limits_of_generated[k], t.rates_, t.regular_, t.regular_first_);
    v.weights = std::move(e.weights);
    v.nodes = std::move(e.nodes);
    v.centres = std::move(e.centres);
  }
  t.validate(path);
  return t;
}

void QuadTables::validate(const std::string& origin) {
  auto fail = [&](const std::string& what) -> void { throw LoadError(origin + ": " + what); };
  if (rates_.empty()) fail("holds no rates");
  for (std::size_t k = 0; k < rates_.size(); ++k) {
    if (rates_[k] < 1 || rates_[k] > limits::kMaxRate)
      fail("invalid rate " + std::to_string(rates_[k]) + " (rates are 1.." + std::to_string(limits::kMaxRate) + ")");
    if (k > 0 && rates_[k] <= rates_[k - 1]) fail("rates are not strictly ascending");
  }
  if (regular_.size() != rates_.size() || regular_first_.size() != rates_.size()) fail("regular patch values missing for some rate");
  for (std::size_t k = 0; k < rates_.size(); ++k) {
    // phi is supported on [-2, 2]: at most 8n + 1 values on the grid 1/(2n).
    const std::int64_t g = 2 * static_cast<std::int64_t>(rates_[k]);
    if (regular_[k].size() > static_cast<std::size_t>(4 * g + 1) || regular_first_[k] < -2 * g || regular_first_[k] > 2 * g)
      fail("regular patch values of rate " + std::to_string(rates_[k]) + " reach beyond the support [-2, 2]");
    if (!finite(regular_[k])) fail("a regular patch value is not finite");
  }
  // phi' of the regular curve: for every rate or for none (a curve that is not C1).
  if (!regular_derivative_.empty()) {
    if (regular_derivative_.size() != rates_.size() || regular_derivative_first_.size() != rates_.size())
      fail("regular curve derivatives missing for some rate");
    const bool none = regular_derivative_[0].empty();
    for (std::size_t k = 0; k < rates_.size(); ++k) {
      const std::int64_t g = 2 * static_cast<std::int64_t>(rates_[k]);
      if (regular_derivative_[k].empty() != none) fail("regular curve derivatives present for some rates only");
      if (regular_derivative_[k].size() > static_cast<std::size_t>(4 * g + 1) || regular_derivative_first_[k] < -2 * g ||
          regular_derivative_first_[k] > 2 * g)
        fail("regular curve derivatives of rate " + std::to_string(rates_[k]) + " reach beyond the support [-2, 2]");
      if (!finite(regular_derivative_[k])) fail("a regular curve derivative is not finite");
    }
    if (none) regular_derivative_.clear(), regular_derivative_first_.clear();
  }
  auto check_rules = [&](const std::vector<VertexRule>& rules, const char* what) {
    for (std::size_t k = 0; k < rules.size(); ++k) {
      const VertexRule& r = rules[k];
      if (r.valence < 3 || r.valence > limits::kMaxValence)
        fail(std::string(what) + " for valence " + std::to_string(r.valence) + " is outside 3.." + std::to_string(limits::kMaxValence));
      if (!std::isfinite(r.centre) || !std::isfinite(r.edge) || !std::isfinite(r.face)) fail(std::string(what) + " weight is not finite");
      for (std::size_t j = 0; j < k; ++j)
        if (rules[j].valence == r.valence) fail(std::string(what) + " for valence " + std::to_string(r.valence) + " is repeated");
    }
  };
  check_rules(rules_, "vertex rule");
  check_rules(polygon_rules_, "polygon vertex rule");
  if (!vertex_rule(4)) fail("holds no vertex rule for valence 4 (the regular case)");
  if (!std::isfinite(face_corner_) || !std::isfinite(edge_end_) || !std::isfinite(edge_wing_) ||
      !std::isfinite(polygon_edge_end_) || !std::isfinite(polygon_edge_face_))
    fail("a face or edge rule weight is not finite");
  for (std::size_t k = 0; k < valences_.size(); ++k) {
    Valence& v = valences_[k];
    const std::string where = "valence " + std::to_string(v.valence);
    if (v.valence < 3 || v.valence > limits::kMaxValence || v.valence == 4)
      fail(where + " is outside 3.." + std::to_string(limits::kMaxValence) + " or is the regular valence 4");
    for (std::size_t j = 0; j < k; ++j)
      if (valences_[j].valence == v.valence) fail(where + " is stored twice");
    if (v.points != points(v.valence)) fail(where + ": " + std::to_string(v.points) + " points, expected " + std::to_string(points(v.valence)));
    // The reflection must be a permutation of the points.
    if (v.reflection.size() != static_cast<std::size_t>(v.points)) fail(where + ": the reflection has the wrong length");
    std::vector<char> hit(v.reflection.size(), 0);
    for (std::uint32_t x : v.reflection) {
      if (x >= v.reflection.size() || hit[x]) fail(where + ": the reflection is not a permutation of the points");
      hit[x] = 1;
    }
    if (v.weights.size() % static_cast<std::size_t>(v.points) != 0) fail(where + ": the weights do not fill whole stencils");
    if (!finite(v.weights)) fail(where + ": a weight is not finite");
    // Every stencil reproduces constants: its weights sum to 1 (up to the rounding of its scalars).
    for (std::size_t s = 0; s + static_cast<std::size_t>(v.points) <= v.weights.size(); s += static_cast<std::size_t>(v.points)) {
      double sum = 0, size = 0;
      for (int h = 0; h < v.points; ++h) sum += v.weights[s + static_cast<std::size_t>(h)], size += std::fabs(v.weights[s + static_cast<std::size_t>(h)]);
      if (!(std::fabs(sum - 1) <= 1e-5 * std::max(1.0, size)))
        fail(where + ": stencil " + std::to_string(s / static_cast<std::size_t>(v.points)) + " sums to " + number_text(sum) + ", not 1");
    }
    const std::size_t stencils = v.weights.size() / static_cast<std::size_t>(v.points);
    if (v.nodes.size() != rates_.size() || v.centres.size() != rates_.size()) fail(where + ": stencil index missing for some rate");
    for (std::size_t s = 0; s < rates_.size(); ++s) {
      if (v.nodes[s].size() != half_count(rates_[s] + 1) || v.centres[s].size() != half_count(rates_[s]))
        fail(where + ": the stencil index of rate " + std::to_string(rates_[s]) + " has the wrong size");
      for (const auto* index : {&v.nodes[s], &v.centres[s]})
        for (std::uint32_t x : *index)
          if (x >= stencils) fail(where + ": stencil index out of range");
    }
  }
  for (std::size_t k = 0; k < sectors_.size(); ++k) {
    const Sector& sec = sectors_[k];
    const std::string where = sec.key.valid() ? sec.key.name() : "boundary sector " + std::to_string(k);
    if (!sec.key.valid()) fail(where + ": invalid face count or position");
    if (!sector_by_kind_.emplace(sector_kind(sec.key), k).second) fail(where + " is stored twice");
    const std::size_t n = static_cast<std::size_t>(sec.key.points());
    const QuadDescent::Valence& d = sec.descent;
    if (sec.limit.size() != n || d.ev_child.rows() != n || d.ev_child.columns_count != n)
      fail(where + ": the limit stencil or A0 does not match the point count");
    for (const auto& child : d.regular_children)
      if (child.rows() != 16 || child.columns_count != n) fail(where + ": a regular child does not have 16 rows over the points");
    double sum = 0, size = 0;
    for (double w : sec.limit) sum += w, size += std::fabs(w);
    if (!finite(sec.limit) || !(std::fabs(sum - 1) <= 1e-5 * std::max(1.0, size))) fail(where + ": the limit stencil does not sum to 1");
    if (!d.tangent_u.empty() && (d.tangent_u.size() != n || d.tangent_v.size() != n)) fail(where + ": tangent stencils of the wrong length");
  }
  if (has_descent_) {
    for (double a : descent_.mask)
      if (!std::isfinite(a)) fail("a regular mask weight is not finite");
    for (const auto& piece : descent_.basis)
      if (!finite(piece)) fail("a polynomial coefficient of the regular basis is not finite");
    if (descent_valences_.size() != valences_.size()) fail("patch subdivision missing for some valence");
  }
  slot_of_rate_.assign(static_cast<std::size_t>(rates_.back()) + 1, -1);
  for (std::size_t k = 0; k < rates_.size(); ++k) slot_of_rate_[static_cast<std::size_t>(rates_[k])] = static_cast<int>(k);
}

const QuadTables::Sector* QuadTables::find_sector(const SectorKey& s) const {
  const auto it = sector_by_kind_.find(sector_kind(s));  // per evaluated point: no scan over the sectors
  return it == sector_by_kind_.end() ? nullptr : &sectors_[it->second];
}

bool QuadTables::has_sector_rule(SectorRule rule) const {
  return std::any_of(sectors_.begin(), sectors_.end(), [&](const Sector& x) { return x.key.rule == rule; });
}

std::vector<SectorKey> QuadTables::sectors() const {
  std::vector<SectorKey> out;
  for (const Sector& x : sectors_) out.push_back(x.key);
  return out;
}

const QuadTables::Valence& QuadTables::expanded(const Sector& s) const {
  std::call_once(*s.once, [&] {
    ExpandedPatch e = expand_patch(sector_kind(s.key), s.descent, s.limit, rates_, regular_, regular_first_, false);
    auto v = std::make_unique<Valence>();
    v->valence = sector_kind(s.key);
    v->points = s.key.points();
    v->weights = std::move(e.weights);
    v->nodes = std::move(e.nodes);
    v->centres = std::move(e.centres);
    s.expanded = std::move(v);
  });
  return *s.expanded;
}

const QuadDescent::Valence& QuadTables::descent(int valence) const {
  if (is_sector_kind(valence)) {
    if (const Sector* s = find_sector(sector_of(valence))) return s->descent;
    throw EvaluationError(kind_name(valence) + " is not in the tables");
  }
  for (std::size_t k = 0; k < valences_.size(); ++k)
    if (valences_[k].valence == valence && has_descent_) return descent_valences_[k];
  throw EvaluationError("valence " + std::to_string(valence) + " has no patch subdivision in the tables");
}

QuadTables::Expanded QuadTables::expand(int valence) const {
  std::vector<double> limit(static_cast<std::size_t>(points(valence)));
  node_stencil(valence, rates_.front(), 0, 0, limit.data());
  ExpandedPatch e = expand_patch(valence, descent(valence), limit, rates_, regular_, regular_first_);
  return {std::move(e.weights), std::move(e.nodes), std::move(e.centres)};
}

const QuadTables::VertexRule* QuadTables::vertex_rule(int valence) const {
  for (const auto& rule : rules_)
    if (rule.valence == valence) return &rule;
  return nullptr;
}

const QuadTables::VertexRule* QuadTables::polygon_vertex_rule(int valence) const {
  for (const auto& rule : polygon_rules_)
    if (rule.valence == valence) return &rule;
  return nullptr;
}

std::vector<int> QuadTables::valences() const {
  std::vector<int> out;
  for (const auto& v : valences_) out.push_back(v.valence);
  return out;
}

bool QuadTables::has_valence(int v) const {
  if (v == 4) return true;
  if (is_sector_kind(v)) return has_sector(sector_of(v));
  for (const auto& x : valences_)
    if (x.valence == v) return true;
  return false;
}

int QuadTables::checked_slot(int n) const {
  const int slot = rate_slot(n);
  if (slot < 0) throw EvaluationError("rate " + std::to_string(n) + " is not in the tables");
  return slot;
}

const double* QuadTables::stored_weights(const Valence& v, int slot, long i, long j, bool centre) const {
  const auto& index = centre ? v.centres[static_cast<std::size_t>(slot)] : v.nodes[static_cast<std::size_t>(slot)];
  const long side = rates_[static_cast<std::size_t>(slot)] + (centre ? 0 : 1);
  const long at = stored_at(!v.reflection.empty(), side, i, j);
  return v.weights.data() + static_cast<std::size_t>(index[static_cast<std::size_t>(at)]) * static_cast<std::size_t>(v.points);
}

int QuadTables::rate_slot(int n) const {
  return n >= 0 && static_cast<std::size_t>(n) < slot_of_rate_.size() ? slot_of_rate_[static_cast<std::size_t>(n)] : -1;
}

const QuadTables::Valence& QuadTables::valence_data(int v) const {
  if (is_sector_kind(v)) {
    if (const Sector* s = find_sector(sector_of(v))) return expanded(*s);
    throw EvaluationError(kind_name(v) + " is not in the tables: regenerate them with this stencilgen and --valence up to " +
                          std::to_string(sector_of(v).faces) + " at least");
  }
  for (const auto& x : valences_)
    if (x.valence == v) return x;
  throw EvaluationError("valence " + std::to_string(v) + " is not in the tables");
}

void QuadTables::node_stencil(int valence, int n, int i, int j, double* weights) const {
  const int slot = checked_slot(n);
  if (i < 0 || j < 0 || i > n || j > n) throw EvaluationError("node index outside 0..n");
  stencil(valence, slot, 2L * i, 2L * j, false, weights);
}

void QuadTables::centre_stencil(int valence, int n, int i, int j, double* weights) const {
  const int slot = checked_slot(n);
  if (i < 0 || j < 0 || i >= n || j >= n) throw EvaluationError("cell index outside 0..n-1");
  stencil(valence, slot, 2L * i + 1, 2L * j + 1, true, weights);
}

const double* QuadTables::centre_weights(int valence, int n, int i, int j, bool& mirrored) const {
  checked_slot(n);
  if (i < 0 || j < 0 || i >= n || j >= n) throw EvaluationError("cell index outside 0..n-1");
  return centre_grid(valence, n).at(i, j, mirrored);
}

QuadTables::CentreGrid QuadTables::centre_grid(int valence, int n) const {
  const int slot = checked_slot(n);
  const Valence& v = valence_data(valence);
  CentreGrid g;
  g.weights_ = v.weights.data();
  g.index_ = v.centres[static_cast<std::size_t>(slot)].data();
  g.side_ = n;
  g.points_ = static_cast<std::size_t>(v.points);
  g.reflected_ = !v.reflection.empty();
  return g;
}

void QuadTables::regular_weights_at(int slot, long a, double* w4) const {
  const auto& phi = regular_[static_cast<std::size_t>(slot)];
  const std::int64_t first = regular_first_[static_cast<std::size_t>(slot)];
  for (int p = -1; p <= 2; ++p) {
    const std::int64_t idx = a - 2L * rates_[static_cast<std::size_t>(slot)] * p - first;
    w4[p + 1] = idx >= 0 && idx < static_cast<std::int64_t>(phi.size()) ? phi[static_cast<std::size_t>(idx)] : 0.0;
  }
}

void QuadTables::regular_derivative_weights(int n, long a, double* w4) const {
  const int slot = checked_slot(n);
  if (!has_regular_derivatives()) throw EvaluationError("these tables hold no derivative of the regular curve");
  if (a < 0 || a > 2L * n) throw EvaluationError("regular weight index outside 0..2n");
  const auto& d = regular_derivative_[static_cast<std::size_t>(slot)];
  const std::int64_t first = regular_derivative_first_[static_cast<std::size_t>(slot)];
  for (int p = -1; p <= 2; ++p) {
    const std::int64_t idx = a - 2L * n * p - first;
    w4[p + 1] = idx >= 0 && idx < static_cast<std::int64_t>(d.size()) ? d[static_cast<std::size_t>(idx)] : 0.0;
  }
}

void QuadTables::regular_weights(int n, long a, double* w4) const {
  const int slot = checked_slot(n);
  if (a < 0 || a > 2L * n) throw EvaluationError("regular weight index outside 0..2n");
  regular_weights_at(slot, a, w4);
}

void QuadTables::stencil(int valence, int slot, long a, long b, bool centre, double* weights) const {
  if (valence == 4) {  // regular: phi(x - p) phi(y - q), points row by row
    double wx[4], wy[4];
    regular_weights_at(slot, a, wx);
    regular_weights_at(slot, b, wy);
    for (int q = 0; q < 4; ++q)
      for (int p = 0; p < 4; ++p) weights[q * 4 + p] = wx[p] * wy[q];
    return;
  }
  const Valence& v = valence_data(valence);
  const bool mirrored = a > b && !v.reflection.empty();
  const long lo = mirrored ? b : a, hi = mirrored ? a : b;
  const double* w = centre ? stored_weights(v, slot, (lo - 1) / 2, (hi - 1) / 2, true) : stored_weights(v, slot, lo / 2, hi / 2, false);
  for (int h = 0; h < v.points; ++h) weights[mirrored ? v.reflection[static_cast<std::size_t>(h)] : h] = w[h];
}

}  // namespace stencil_runtime

namespace stencil_runtime {

void QuadTables::check_smooth_triangles() const {
  if (polygon_edge_end_ != 0.25 || polygon_edge_face_ != 0.25)
    throw MeshError("OpenSubdiv's smooth triangle rule (`smoothtriangles`) is made for Catmull-Clark's polygon edge "
                    "rule (1/4 each end and each face point); the scheme " + name_ + " has its own");
}

}  // namespace stencil_runtime
