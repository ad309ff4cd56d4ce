#include "curve/curve_scheme_loader.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "base/limits.hpp"
#include "common/read_file.hpp"
#include "common/scheme_file.hpp"
#include "curve/knot_insertion.hpp"
#include "curve/support.hpp"

namespace sg {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

struct Mask {
  long first = 0;
  std::vector<Rational> coefficients;
  long last() const { return first + static_cast<long>(coefficients.size()) - 1; }
};

// Error context "FILE: FIELD: message", plus the curve mask reader.
class Context : public SchemeContext {
 public:
  using SchemeContext::SchemeContext;
  Mask mask(const json& j, const std::string& field, const Bindings& b) const {
    Mask m;
    m.first = integer(require(j, "first", field), field + ".first", -limits::kMaxMaskOffset, limits::kMaxMaskOffset);
    const json& coeffs = require(j, "coefficients", field);
    if (!coeffs.is_array() || coeffs.empty()) fail(field + ".coefficients", "expected a non-empty array");
    if (static_cast<long>(coeffs.size()) > limits::kMaxMaskLength)
      fail(field + ".coefficients", std::to_string(coeffs.size()) + " coefficients; the limit is " +
                                        std::to_string(limits::kMaxMaskLength));
    for (std::size_t i = 0; i < coeffs.size(); ++i)
      m.coefficients.push_back(rational(coeffs[i], field + ".coefficients[" + std::to_string(i) + "]", b));
    // Trim zero ends so that `first`/`last` are the true mask support.
    while (!m.coefficients.empty() && m.coefficients.back() == 0) m.coefficients.pop_back();
    std::size_t lead = 0;
    while (lead < m.coefficients.size() && m.coefficients[lead] == 0) ++lead;
    if (lead == m.coefficients.size()) fail(field + ".coefficients", "all coefficients are zero");
    m.coefficients.erase(m.coefficients.begin(), m.coefficients.begin() + static_cast<long>(lead));
    m.first += static_cast<long>(lead);
    return m;
  }
};

std::vector<Term> mask_terms(const Mask& m, std::size_t type) {
  std::vector<Term> terms;
  for (std::size_t i = 0; i < m.coefficients.size(); ++i)
    if (m.coefficients[i] != 0) terms.push_back({type, m.first + static_cast<long>(i), m.coefficients[i]});
  return terms;
}

// Builds the types of a non-uniform scheme from its two uniform masks and the
// explicit columns of S at the special control indices (which must be contiguous).
void build_from_columns(CurveScheme& s, const Mask& left, const Mask& right, const std::map<long, Column>& special,
                        const Context& ctx) {
  if (special.empty()) ctx.fail("special_columns", "at least one special column is required");
  const long jl = special.begin()->first - 1, jr = special.rbegin()->first + 1;
  if (static_cast<long>(special.size()) != jr - jl - 1) ctx.fail("special_columns", "column indices must be contiguous");
  const long a = s.arity;
  // Left uniform columns j <= jl must only reach fine points that are themselves left-uniform.
  if (a * jl + left.last() > jl)
    ctx.fail("special_columns", "the left uniform column " + std::to_string(jl) + " reaches fine point " +
                                    std::to_string(a * jl + left.last()) +
                                    ", which is special; list more columns as special");
  if (a * jr + right.first < jr)
    ctx.fail("special_columns", "the right uniform column " + std::to_string(jr) + " reaches fine point " +
                                    std::to_string(a * jr + right.first) +
                                    ", which is special; list more columns as special");
  s.types.clear();
  ScalingType L{"left", Placement::AtMost, jl, mask_terms(left, 0), 0, 0};
  ScalingType R{"right", Placement::AtLeast, jr, mask_terms(right, 1), 0, 0};
  s.types.push_back(L);
  s.types.push_back(R);
  std::map<long, std::size_t> type_of;
  for (const auto& [p, col] : special) {
    type_of[p] = s.types.size();
    s.types.push_back({"c" + std::to_string(p), Placement::Single, p, {}, 0, 0});
  }
  for (const auto& [p, col] : special) {
    ScalingType& t = s.types[type_of[p]];
    for (std::size_t k = 0; k < col.coefficients.size(); ++k) {
      if (col.coefficients[k] == 0) continue;
      const long i = col.first + static_cast<long>(k);  // fine control index
      const std::size_t g = i <= jl ? 0 : (i >= jr ? 1 : type_of.at(i));
      t.terms.push_back({g, i - a * p, col.coefficients[k]});
    }
    if (t.terms.empty()) ctx.fail("special_columns", "column " + std::to_string(p) + " is all zero");
  }
}

Mask pattern_of(const Column& c, long index, long arity) {
  return Mask{c.first - arity * index, c.coefficients};
}
bool same_mask(const Mask& a, const Mask& b) { return a.first == b.first && a.coefficients == b.coefficients; }

void build_from_knots(CurveScheme& s, const KnotSpec& spec, const Context& ctx) {
  const long radius = 4 * (spec.degree + 2);
  std::map<long, Column> cols;
  try {
    cols = knot_insertion_columns(spec, radius);
  } catch (const Error& e) {
    ctx.fail("knots", e.what());
  }
  const Mask left = pattern_of(cols.at(-radius), -radius, 2), right = pattern_of(cols.at(radius), radius, 2);
  // Uniform regions: the longest runs from either end that repeat the end pattern,
  // shrunk until their columns reach only uniform fine points.
  long jl = -radius;
  while (jl + 1 < radius && same_mask(pattern_of(cols.at(jl + 1), jl + 1, 2), left)) ++jl;
  while (2 * jl + left.last() > jl) --jl;
  long jr = radius;
  while (jr - 1 > -radius && same_mask(pattern_of(cols.at(jr - 1), jr - 1, 2), right)) --jr;
  while (2 * jr + right.first < jr) ++jr;
  std::map<long, Column> special;
  for (long j = jl + 1; j < jr; ++j) special[j] = cols.at(j);
  if (special.empty()) {  // uniform knots: one type
    s.types = {{"phi", Placement::Everywhere, 0, mask_terms(left, 0), 0, 0}};
    return;
  }
  build_from_columns(s, left, right, special, ctx);
}

}  // namespace

CurveScheme load_curve_scheme(const std::string& spec, const std::vector<std::string>& overrides, const fs::path& dir) {
  const fs::path file = resolve_scheme_file(spec, dir);
  CurveScheme scheme = curve_scheme_from_json(read_file(file, limits::kMaxSchemeFileBytes, "scheme"), file.string(), overrides);
  check_scheme_file_name(spec, scheme.name, file);
  return scheme;
}

CurveScheme curve_scheme_from_json(const std::string& text, const std::string& origin,
                                   const std::vector<std::string>& overrides) {
  const Context ctx(origin);
  const json doc = parse_scheme_document(text, ctx);

  CurveScheme s;
  s.source = origin;
  s.name = doc.at("name").get<std::string>();
  s.description = doc.value("description", "");
  s.parameters = resolve_parameters(doc, overrides, s.name, ctx);

  const std::string kind = doc.at("type").get<std::string>();
  auto arity = [&] { return static_cast<int>(ctx.integer(ctx.require(doc, "arity", ""), "arity", 2, 3)); };
  if (kind == "curve-uniform") {
    s.kind = "uniform";
    s.arity = arity();
    const Mask m = ctx.mask(ctx.require(doc, "mask", ""), "mask", s.parameters);
    s.types = {{"phi", Placement::Everywhere, 0, mask_terms(m, 0), 0, 0}};
  } else if (kind == "curve-columns") {
    s.kind = "columns";
    s.arity = arity();
    const Mask left = ctx.mask(doc.contains("left_mask") ? doc["left_mask"] : ctx.require(doc, "mask", ""),
                               doc.contains("left_mask") ? "left_mask" : "mask", s.parameters);
    const Mask right = ctx.mask(doc.contains("right_mask") ? doc["right_mask"] : ctx.require(doc, "mask", ""),
                                doc.contains("right_mask") ? "right_mask" : "mask", s.parameters);
    const json& cols = ctx.require(doc, "special_columns", "");
    ctx.array(cols, "special_columns");
    if (static_cast<long>(cols.size()) > limits::kMaxSpecialColumns)
      ctx.fail("special_columns", std::to_string(cols.size()) + " columns; the limit is " +
                                      std::to_string(limits::kMaxSpecialColumns));
    std::map<long, Column> special;
    for (std::size_t i = 0; i < cols.size(); ++i) {
      const std::string field = field_path("special_columns", i);
      const long index = ctx.integer(ctx.require(cols[i], "index", field), field + ".index", -limits::kMaxMaskOffset,
                                     limits::kMaxMaskOffset);
      const Mask m = ctx.mask(cols[i], field, s.parameters);
      if (special.count(index)) ctx.fail(field, "column " + std::to_string(index) + " is listed twice");
      special[index] = Column{m.first, m.coefficients};
    }
    build_from_columns(s, left, right, special, ctx);
  } else if (kind == "curve-knots") {
    s.kind = "knots";
    s.arity = 2;
    KnotSpec k;
    k.degree = static_cast<int>(
        ctx.integer(ctx.require(doc, "degree", ""), "degree", limits::kMinKnotDegree, limits::kMaxKnotDegree));
    const json& spacing = ctx.require(doc, "knot_spacing", "");
    k.left_spacing = ctx.rational(ctx.require(spacing, "left", "knot_spacing"), "knot_spacing.left", s.parameters);
    k.right_spacing = ctx.rational(ctx.require(spacing, "right", "knot_spacing"), "knot_spacing.right", s.parameters);
    if (k.left_spacing <= 0 || k.right_spacing <= 0) ctx.fail("knot_spacing", "spacings must be positive");
    build_from_knots(s, k, ctx);
  } else {
    ctx.fail("type", kind == "quad" || kind == "triangle"
                         ? "'" + kind + "' is a surface scheme, not a curve scheme"
                         : "unknown type '" + excerpt(kind) + "' (expected curve-uniform, curve-columns, curve-knots, quad or triangle)");
  }

  compute_supports(s);

  s.hash = scheme_content_hash(doc, s.parameters);
  return s;
}

}  // namespace sg
