// Loading the exact JSON tables of a quad scheme (a directory written by
// stencilgen: v<V>/n<N>.json and regular/n<2N>.json) into the same in-memory
// form as the binary file. Exact rationals become doubles; the binary file is
// the fast path. Every name, count, index and rational is checked.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>

#include "json_reader.hpp"
#include "quad_tables.hpp"
#include "stencil_runtime/binary_format.hpp"
#include "stencil_runtime/limits.hpp"

namespace stencil_runtime {

namespace fs = std::filesystem;
using nlohmann::json;
using detail::JsonFile;

namespace {

// The number in a name "<prefix><digits><suffix>", or -1 when the name has
// another form; `digits` must be a plain decimal within [lo, hi] (else an error).
long numbered_name(const std::string& name, char prefix, const std::string& suffix, long lo, long hi, const fs::path& where) {
  if (name.size() <= 1 + suffix.size() || name[0] != prefix || name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
    return -1;
  const std::string digits = name.substr(1, name.size() - 1 - suffix.size());
  std::int64_t n = 0;
  if (digits.find_first_not_of("0123456789") != std::string::npos || !detail::parse_int64(digits, n) || n < lo || n > hi)
    throw LoadError(where.string() + ": not a table name of the form " + std::string(1, prefix) + "<N>" + suffix +
                    " with N in " + std::to_string(lo) + ".." + std::to_string(hi));
  return static_cast<long>(n);
}

// A vertex rule triple ["centre", "edge", "face"].
QuadTables::VertexRule read_rule(const JsonFile& f, const std::string& key, const json& r, const std::string& field) {
  std::int64_t valence = 0;
  if (!detail::parse_int64(key, valence) || valence < 3 || valence > limits::kMaxValence)
    f.fail(field, "valence " + quoted_excerpt(key) + " is not an integer in 3.." + std::to_string(limits::kMaxValence));
  const json& a = f.array(r, field + "." + key);
  if (a.size() != 3) f.fail(field + "." + key, "expected three weights");
  double w[3];
  for (std::size_t k = 0; k < 3; ++k)
    w[k] = detail::parse_exact_rational(f.string(a[k], field + "." + key), f, field + "." + key);
  return {static_cast<int>(valence), w[0], w[1], w[2]};
}

// Sparse rows [[column, "p/q"], ...] over `columns` points.
SparseRows read_rows(const JsonFile& f, const json& rows, std::size_t count, std::size_t columns, const std::string& field) {
  f.array(rows, field);
  if (rows.size() != count) f.fail(field, "expected " + std::to_string(count) + " rows");
  SparseRows m;
  m.columns_count = columns;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const std::string row_field = field + "[" + std::to_string(r) + "]";
    const json& row = f.array(rows[r], row_field);
    if (row.size() > columns) f.fail(row_field, "more entries than points");
    for (std::size_t e = 0; e < row.size(); ++e) {
      const std::string entry = row_field + "[" + std::to_string(e) + "]";
      const json& pair = f.array(row[e], entry);
      if (pair.size() != 2) f.fail(entry, "expected [column, weight]");
      const std::int64_t column = f.integer(pair[0], entry);
      if (column < 0 || static_cast<std::size_t>(column) >= columns) f.fail(entry, "column out of range");
      m.columns.push_back(static_cast<std::uint32_t>(column));
      m.weights.push_back(detail::parse_exact_rational(f.string(pair[1], entry), f, entry));
    }
    m.offsets.push_back(m.columns.size());
  }
  return m;
}

bool boolean(const JsonFile& f, const json& value, const std::string& field) {
  if (!value.is_boolean()) f.fail(field, "expected true or false");
  return value.get<bool>();
}

double decimal(const JsonFile& f, const json& x, const std::string& where) {
  const std::string text = f.string(x, where);
  double value = 0;
  const auto [end, err] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (err != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
    f.fail(where, "not a finite decimal number: " + quoted_excerpt(text));
  return value;
}

// The tangent stencils at the vertex, entry["tangents"] (null: none); `second`:
// with the second eigenvalue of the pair (boundary sectors).
void read_tangents(const JsonFile& f, const json& entry, QuadDescent::Valence& out, std::size_t points, bool second,
                   const std::string& field) {
  const json& t = f.member(entry, "tangents", field);
  if (t.is_null()) return;
  const std::string tf = field + ".tangents";
  out.tangent_eigenvalue = decimal(f, f.member(t, "eigenvalue", tf), tf + ".eigenvalue");
  out.tangent_second_eigenvalue =
      second ? decimal(f, f.member(t, "second_eigenvalue", tf), tf + ".second_eigenvalue") : out.tangent_eigenvalue;
  out.tangent_residual = decimal(f, f.member(t, "residual", tf), tf + ".residual");
  if (!(out.tangent_eigenvalue > 0 && out.tangent_eigenvalue < 1)) f.fail(tf + ".eigenvalue", "must lie in (0, 1)");
  if (!(out.tangent_second_eigenvalue > 0 && out.tangent_second_eigenvalue < 1)) f.fail(tf + ".second_eigenvalue", "must lie in (0, 1)");
  for (const char* which : {"u", "v"}) {
    const std::string where = tf + "." + which;
    const json& w = f.array(f.member(t, which, tf), where);
    if (w.size() != points) f.fail(where, "expected " + std::to_string(points) + " weights");
    std::vector<double>& dest = which[0] == 'u' ? out.tangent_u : out.tangent_v;
    for (const json& x : w) dest.push_back(decimal(f, x, where));
  }
}

}  // namespace

QuadTables QuadTables::load_json_directory(const std::string& dir, std::uint64_t expected_hash) {
  QuadTables t;
  std::map<int, std::map<int, fs::path>> files;  // valence -> rate -> file
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (!entry.is_directory() || name.size() < 2 || name[0] != 'v' || name[1] < '0' || name[1] > '9') continue;
    const long v = numbered_name(name, 'v', "", 3, limits::kMaxValence, entry.path());
    for (const auto& f : fs::directory_iterator(entry.path())) {
      const std::string fn = f.path().filename().string();
      if (fn.empty() || fn[0] != 'n' || f.path().extension() != ".json") continue;
      const long n = numbered_name(fn, 'n', ".json", 1, limits::kMaxRate, f.path());
      files[static_cast<int>(v)][static_cast<int>(n)] = f.path();
    }
  }
  if (ec) throw LoadError(dir + ": cannot list: " + ec.message());
  if (files.empty()) throw LoadError(dir + ": no v<V>/n<N>.json surface tables here");
  for (const auto& [v, by_rate] : files) {
    std::vector<int> rates;
    for (const auto& [n, path] : by_rate) rates.push_back(n);
    if (t.rates_.empty()) t.rates_ = rates;
    if (rates != t.rates_)
      throw LoadError(dir + ": valence " + std::to_string(v) + " has a different set of rates than valence " +
                      std::to_string(files.begin()->first));
  }
  bool first = true;
  for (const auto& [v, by_rate] : files) {
    Valence val;
    val.valence = v;
    val.points = points(v);
    for (const auto& [n, path] : by_rate) {
      const JsonFile f(path.string());
      const json& doc = f.root();
      if (f.string(f.member(doc, "format", ""), "format") != "stencilgen-surface-table" || f.integer(f.member(doc, "version", ""), "version") != 1)
        f.fail("format", "not a version 1 stencilgen surface table");
      if (f.integer(f.member(doc, "valence", ""), "valence") != v || f.integer(f.member(doc, "n", ""), "n") != n ||
          f.integer(f.member(doc, "points", ""), "points") != val.points)
        f.fail("valence", "valence, rate or point count does not match the file name");
      std::uint64_t hash = 0;
      const std::string hash_text = f.string(f.member(doc, "scheme_hash", ""), "scheme_hash");
      const auto [end, err] = std::from_chars(hash_text.data(), hash_text.data() + hash_text.size(), hash, 16);
      if (err != std::errc() || end != hash_text.data() + hash_text.size()) f.fail("scheme_hash", "not a hexadecimal hash");
      const std::string scheme = f.string(f.member(doc, "scheme", ""), "scheme");
      const json& rules = f.member(doc, "rules", "");
      if (first) {
        t.hash_ = hash;
        t.name_ = scheme;
        if (expected_hash != 0 && t.hash_ != expected_hash) f.fail("scheme_hash", "made from a different scheme (hash mismatch)");
        t.face_corner_ = detail::parse_exact_rational(f.string(f.member(rules, "face_corner", "rules"), "rules.face_corner"), f, "rules.face_corner");
        t.edge_end_ = detail::parse_exact_rational(f.string(f.member(rules, "edge_end", "rules"), "rules.edge_end"), f, "rules.edge_end");
        t.edge_wing_ = detail::parse_exact_rational(f.string(f.member(rules, "edge_wing", "rules"), "rules.edge_wing"), f, "rules.edge_wing");
        first = false;
      } else if (hash != t.hash_ || scheme != t.name_) {
        f.fail("scheme_hash", "made from a different scheme than the other tables in " + dir);
      }
      if (rules.contains("polygon")) {
        const json& pg = f.member(rules, "polygon", "rules");
        t.has_polygon_ = true;
        t.polygon_edge_end_ = detail::parse_exact_rational(f.string(f.member(pg, "edge_end", "rules.polygon"), "rules.polygon.edge_end"), f, "rules.polygon.edge_end");
        t.polygon_edge_face_ = detail::parse_exact_rational(f.string(f.member(pg, "edge_face_point", "rules.polygon"), "rules.polygon.edge_face_point"), f, "rules.polygon.edge_face_point");
        const json& vertex = f.member(pg, "vertex", "rules.polygon");
        if (!vertex.is_object()) f.fail("rules.polygon.vertex", "expected an object");
        for (const auto& [key, r] : vertex.items()) {
          const VertexRule rule = read_rule(f, key, r, "rules.polygon.vertex");
          if (!t.polygon_vertex_rule(rule.valence)) t.polygon_rules_.push_back(rule);
        }
      }
      const json& vertex = f.member(rules, "vertex", "rules");
      if (!vertex.is_object()) f.fail("rules.vertex", "expected an object");
      for (const auto& [key, r] : vertex.items()) {
        const VertexRule rule = read_rule(f, key, r, "rules.vertex");
        if (!t.vertex_rule(rule.valence)) t.rules_.push_back(rule);
      }
      {  // the same reflection in every file of the valence
        const json& reflection = f.array(f.member(doc, "reflection", ""), "reflection");
        if (reflection.size() != static_cast<std::size_t>(val.points)) f.fail("reflection", "wrong length");
        std::vector<std::uint32_t> read;
        for (std::size_t k = 0; k < reflection.size(); ++k) {
          const std::int64_t x = f.integer(reflection[k], "reflection[" + std::to_string(k) + "]");
          if (x < 0 || x >= val.points) f.fail("reflection[" + std::to_string(k) + "]", "index out of range");
          read.push_back(static_cast<std::uint32_t>(x));
        }
        if (val.reflection.empty()) val.reflection = read;
        else if (read != val.reflection) f.fail("reflection", "differs from the other tables of valence " + std::to_string(v));
      }
      for (const char* kind : {"nodes", "centres"}) {
        const json& list = f.array(f.member(doc, kind, ""), kind);
        const std::size_t side = kind[0] == 'n' ? static_cast<std::size_t>(n + 1) : static_cast<std::size_t>(n);
        if (list.size() != side * (side + 1) / 2) f.fail(kind, "wrong number of stencils");
        std::vector<std::uint32_t> index;
        for (std::size_t e = 0; e < list.size(); ++e) {
          const std::string field = std::string(kind) + "[" + std::to_string(e) + "]";
          const std::string den = f.string(f.member(list[e], "denominator", field), field + ".denominator");
          const json& nums = f.array(f.member(list[e], "numerators", field), field + ".numerators");
          if (nums.size() != static_cast<std::size_t>(val.points)) f.fail(field + ".numerators", "a stencil has the wrong length");
          index.push_back(static_cast<std::uint32_t>(val.weights.size() / static_cast<std::size_t>(val.points)));
          for (std::size_t h = 0; h < nums.size(); ++h)
            val.weights.push_back(detail::parse_ratio(f.string(nums[h], field + ".numerators"), den, f, field + ".numerators"));
        }
        (kind[0] == 'n' ? val.nodes : val.centres).push_back(std::move(index));
      }
    }
    if (v != 4) t.valences_.push_back(std::move(val));
  }
  // The regular patch: the curve on the grid 2n, supported on [-2, 2].
  for (int n : t.rates_) {
    const fs::path path = fs::path(dir) / "regular" / ("n" + std::to_string(2 * n) + ".json");
    const JsonFile f(path.string());
    const json& functions = f.array(f.member(f.root(), "functions", ""), "functions");
    if (functions.size() != 1) f.fail("functions", "expected one function (the regular curve's scaling function)");
    const std::int64_t g = 2 * static_cast<std::int64_t>(n);
    // A map from grid parameter p/q to exact value, dense from its first key.
    auto read_grid = [&](const json& values, const std::string& where, std::vector<double>& dense, std::int64_t& first) {
      if (!values.is_object()) f.fail(where, "expected an object");
      std::map<std::int64_t, double> grid;
      for (const auto& [key, value] : values.items()) {
        const std::string field = where + "[\"" + key + "\"]";
        const auto slash = key.find('/');
        std::int64_t p = 0, q = 1;
        if (!detail::parse_int64(std::string_view(key).substr(0, slash), p) ||
            (slash != std::string::npos && !detail::parse_int64(std::string_view(key).substr(slash + 1), q)) || q <= 0)
          f.fail(field, "the key is not a parameter p/q with q > 0");
        // p/q on the grid 1/g within [-2, 2]: |p| <= 2q and q | p g.
        if (p < -2 * q || p > 2 * q || q > g * 1000000 || (p * g) % q != 0)
          f.fail(field, "the key is not a grid point k/" + std::to_string(g) + " within the support [-2, 2]");
        grid[p * g / q] = detail::parse_exact_rational(f.string(value, field), f, field);
      }
      const std::int64_t lo = grid.empty() ? 0 : grid.begin()->first, hi = grid.empty() ? -1 : grid.rbegin()->first;
      dense.assign(static_cast<std::size_t>(hi - lo + 1), 0.0);
      for (const auto& [k, x] : grid) dense[static_cast<std::size_t>(k - lo)] = x;
      first = lo;
    };
    std::vector<double> dense;
    std::int64_t first = 0;
    read_grid(f.member(functions[0], "values", "functions[0]"), "functions[0].values", dense, first);
    t.regular_first_.push_back(first);
    t.regular_.push_back(std::move(dense));
    // phi' (curve tables of version 2 whose curve is C1): all rates or none.
    dense.clear();
    first = 0;
    if (functions[0].contains("derivatives")) {
      const json& derivatives = f.array(functions[0]["derivatives"], "functions[0].derivatives");
      if (!derivatives.empty())
        read_grid(f.member(derivatives[0], "values", "functions[0].derivatives[0]"), "functions[0].derivatives[0].values",
                  dense, first);
    }
    t.regular_derivative_first_.push_back(first);
    t.regular_derivative_.push_back(std::move(dense));
  }
  // The patch subdivision, for evaluation at any parameter (absent in tables from older stencilgens).
  const fs::path descent = fs::path(dir) / "descent.json";
  if (fs::exists(descent)) {
    const JsonFile f(descent.string());
    const json& doc = f.root();
    const std::int64_t version = f.integer(f.member(doc, "version", ""), "version");
    if (f.string(f.member(doc, "format", ""), "format") != "stencilgen-quad-descent" || version < 1 || version > 4)
      f.fail("format", "not a version 1 to 4 stencilgen quad descent file");
    if (f.string(f.member(doc, "scheme", ""), "scheme") != t.name_) f.fail("scheme", "another scheme than the tables'");
    QuadDescent& d = t.descent_;
    const json& mask = f.member(doc, "mask", "");
    d.mask_first = f.integer(f.member(mask, "first", "mask"), "mask.first");
    const json& coefficients = f.array(f.member(mask, "coefficients", "mask"), "mask.coefficients");
    if (coefficients.empty() || coefficients.size() > 32 || d.mask_first < -32 || d.mask_first > 32) f.fail("mask", "invalid regular mask");
    for (std::size_t k = 0; k < coefficients.size(); ++k)
      d.mask.push_back(detail::parse_exact_rational(f.string(coefficients[k], "mask.coefficients"), f, "mask.coefficients"));
    d.mask_nonnegative = boolean(f, f.member(doc, "mask_nonnegative", ""), "mask_nonnegative");
    d.derivative_nonnegative = boolean(f, f.member(doc, "derivative_nonnegative", ""), "derivative_nonnegative");
    const json& basis = f.member(doc, "polynomial_basis", "");
    if (!basis.is_null()) {
      const std::int64_t degree = f.integer(f.member(basis, "degree", "polynomial_basis"), "polynomial_basis.degree");
      if (degree < 1 || degree > 7) f.fail("polynomial_basis.degree", "must be 1..7");
      d.degree = static_cast<int>(degree);
      const json& pieces = f.array(f.member(basis, "pieces", "polynomial_basis"), "polynomial_basis.pieces");
      if (pieces.size() != 4) f.fail("polynomial_basis.pieces", "expected four pieces");
      for (const json& piece : pieces) {
        f.array(piece, "polynomial_basis.pieces");
        if (piece.size() != static_cast<std::size_t>(degree) + 1) f.fail("polynomial_basis.pieces", "wrong number of coefficients");
        d.basis.emplace_back();
        for (const json& c : piece)
          d.basis.back().push_back(detail::parse_exact_rational(f.string(c, "polynomial_basis.pieces"), f, "polynomial_basis.pieces"));
      }
    }
    const json& valences = f.array(f.member(doc, "valences", ""), "valences");
    t.descent_valences_.resize(t.valences_.size());
    std::vector<char> seen(t.valences_.size(), 0);
    for (std::size_t k = 0; k < valences.size(); ++k) {
      const std::string field = "valences[" + std::to_string(k) + "]";
      const std::int64_t v = f.integer(f.member(valences[k], "valence", field), field + ".valence");
      std::size_t slot = t.valences_.size();
      for (std::size_t s = 0; s < t.valences_.size(); ++s)
        if (t.valences_[s].valence == v) slot = s;
      if (slot == t.valences_.size()) continue;  // a valence the tables were not written for
      const std::size_t points = static_cast<std::size_t>(QuadTables::points(static_cast<int>(v)));
      QuadDescent::Valence& out = t.descent_valences_[slot];
      out.nonnegative = boolean(f, f.member(valences[k], "nonnegative", field), field + ".nonnegative");
      out.ev_child = read_rows(f, f.member(valences[k], "ev_child", field), points, points, field + ".ev_child");
      const json& children = f.array(f.member(valences[k], "regular_children", field), field + ".regular_children");
      if (children.size() != 3) f.fail(field + ".regular_children", "expected three children");
      for (std::size_t c = 0; c < 3; ++c)
        out.regular_children[c] = read_rows(f, children[c], 16, points, field + ".regular_children[" + std::to_string(c) + "]");
      if (version >= 2) read_tangents(f, valences[k], out, points, false, field);  // the tangent stencils (null: none)
      seen[slot] = 1;
    }
    for (std::size_t s = 0; s < seen.size(); ++s)
      if (!seen[s]) f.fail("valences", "no patch subdivision for valence " + std::to_string(t.valences_[s].valence));
    if (version >= 3) {  // the boundary sectors
      const json& sectors = f.array(f.member(doc, "sectors", ""), "sectors");
      for (std::size_t k = 0; k < sectors.size(); ++k) {
        const std::string field = "sectors[" + std::to_string(k) + "]";
        const json& e = sectors[k];
        Sector sec;
        const std::string kind = f.string(f.member(e, "kind", field), field + ".kind");
        if (kind == "corner") sec.key.rule = SectorRule::Corner;
        else if (kind == "dart") sec.key.rule = SectorRule::Dart;
        else if (kind == "cone" && version >= 4) sec.key.rule = SectorRule::Cone;
        else if (kind != "crease") f.fail(field + ".kind", version >= 4 ? "expected \"crease\", \"corner\", \"dart\" or \"cone\""
                                                                         : "expected \"crease\", \"corner\" or \"dart\"");
        const std::int64_t faces = f.integer(f.member(e, "faces", field), field + ".faces");
        const std::int64_t position = f.integer(f.member(e, "position", field), field + ".position");
        sec.key.faces = static_cast<int>(std::clamp<std::int64_t>(faces, -1, 1024));
        sec.key.position = static_cast<int>(std::clamp<std::int64_t>(position, -1, 1024));
        if (!sec.key.valid())
          f.fail(field, "face count outside 1.." + std::to_string(limits::kMaxValence) + " (a dart or cone: 3..) or position outside 0..faces-1 (a cone: 0)");
        const std::size_t points = static_cast<std::size_t>(sec.key.points());
        if (f.integer(f.member(e, "points", field), field + ".points") != static_cast<std::int64_t>(points))
          f.fail(field + ".points", "expected " + std::to_string(points));
        for (int n : t.rates_)
          if (format::expansion_grid_entries(static_cast<std::uint64_t>(n), points) > format::kMaxExpansionGridEntries)
            f.fail(field, "too large to expand at rate " + std::to_string(n) + " (the runtime's limit is " +
                              std::to_string(format::kMaxExpansionGridEntries) + " grid entries per rate)");
        const json& limit = f.array(f.member(e, "limit", field), field + ".limit");
        if (limit.size() != points) f.fail(field + ".limit", "expected " + std::to_string(points) + " weights");
        for (const json& x : limit) sec.limit.push_back(detail::parse_exact_rational(f.string(x, field + ".limit"), f, field + ".limit"));
        QuadDescent::Valence& out = sec.descent;
        out.nonnegative = boolean(f, f.member(e, "nonnegative", field), field + ".nonnegative");
        out.ev_child = read_rows(f, f.member(e, "ev_child", field), points, points, field + ".ev_child");
        const json& children = f.array(f.member(e, "regular_children", field), field + ".regular_children");
        if (children.size() != 3) f.fail(field + ".regular_children", "expected three children");
        for (std::size_t c = 0; c < 3; ++c)
          out.regular_children[c] = read_rows(f, children[c], 16, points, field + ".regular_children[" + std::to_string(c) + "]");
        read_tangents(f, e, out, points, true, field);
        t.sectors_.push_back(std::move(sec));
      }
    }
    t.has_descent_ = true;
  }
  t.validate(dir);
  return t;
}

}  // namespace stencil_runtime
