#include "stencil_runtime/curve_table.hpp"

#include <cmath>

#include "binary_reader.hpp"

namespace stencil_runtime {

namespace {

// Grid indices of a real table are small (support times rate); far larger
// ones would only make index arithmetic overflow.
constexpr std::int64_t kMaxIndex = std::int64_t{1} << 40;

// first (i64, within +-2^40), count (u32), count finite doubles.
void read_grid_values(detail::BinaryReader& r, std::size_t file_size, const std::string& what, std::int64_t& first,
                      std::vector<double>& values) {
  first = r.get<std::int64_t>();
  if (first < -kMaxIndex || first > kMaxIndex) r.fail(what + ": first grid index outside +-2^40");
  const auto size = r.get<std::uint32_t>();
  if (size > (file_size - r.position()) / 8) r.fail("truncated value block in " + what);
  values.resize(size);
  for (auto& v : values) {
    v = r.get<double>();
    if (!std::isfinite(v)) r.fail("a value in " + what + " is not finite");
  }
}

}  // namespace

CurveTable load_curve_table(const std::string& path, std::uint64_t expected_hash) {
  const std::string bytes = detail::read_binary_file(path);
  detail::BinaryReader r(bytes, path);
  detail::check_envelope(bytes, r, format::kCurveMagic, "binary curve table");
  CurveTable t;
  const auto version = r.get<std::uint32_t>();
  if (version != format::kCurveVersion)
    r.fail("format version " + std::to_string(version) + " is not supported (expected " + std::to_string(format::kCurveVersion) +
           "; regenerate the tables with this stencilgen)");
  t.arity = r.get<std::uint32_t>();
  t.n = r.get<std::uint32_t>();
  const auto count = r.get<std::uint32_t>();
  t.scheme_hash = r.get<std::uint64_t>();
  if (expected_hash != 0 && t.scheme_hash != expected_hash) r.fail("made from a different scheme (hash mismatch)");
  if (t.n == 0 || t.n > static_cast<std::uint32_t>(limits::kMaxRate) || (t.arity != 2 && t.arity != 3))
    r.fail("invalid header (n must be 1.." + std::to_string(limits::kMaxRate) + ", arity 2 or 3)");
  if (count == 0 || count > 64) r.fail("invalid function count " + std::to_string(count) + " (1..64)");
  t.derivative_orders = r.get<std::uint8_t>();
  if (t.derivative_orders > format::kMaxCurveDerivativeOrder)
    r.fail("invalid derivative order count " + std::to_string(t.derivative_orders) + " (0.." +
           std::to_string(format::kMaxCurveDerivativeOrder) + ")");
  for (std::uint32_t i = 0; i < count; ++i) {
    CurveFunction f;
    const auto name_length = r.get<std::uint32_t>();
    if (name_length > 256) r.fail("function name longer than 256 bytes");
    f.name = r.get_string(name_length);
    const auto placement = r.get<std::uint8_t>();
    if (placement > 3) r.fail("invalid placement code " + std::to_string(placement));
    f.placement = static_cast<format::Placement>(placement);
    f.position = r.get<std::int64_t>();
    if (f.position < -kMaxIndex || f.position > kMaxIndex)
      r.fail("function " + quoted_excerpt(f.name) + ": position outside +-2^40");
    const std::string what = "function " + quoted_excerpt(f.name);
    read_grid_values(r, bytes.size(), what, f.first, f.values);
    f.derivatives.resize(t.derivative_orders);
    for (std::uint32_t order = 1; order <= t.derivative_orders; ++order)
      read_grid_values(r, bytes.size(), what + " (derivative " + std::to_string(order) + ")", f.derivatives[order - 1].first,
                       f.derivatives[order - 1].values);
    t.functions.push_back(std::move(f));
  }
  if (r.position() != bytes.size() - 8) r.fail("unexpected trailing bytes");
  return t;
}

namespace {

// sum_j points[j] * f(k/n - j) for grid values f of a one-function table.
double combine(const CurveTable& table, std::int64_t first, const std::vector<double>& values, const std::vector<double>& points,
               std::int64_t k) {
  double sum = 0;
  for (std::size_t j = 0; j < points.size(); ++j) {
    std::int64_t at = 0;
    if (__builtin_sub_overflow(k, static_cast<std::int64_t>(j) * table.n, &at)) continue;  // beyond every support
    sum += points[j] * grid_value(first, values, at);
  }
  return sum;
}

const CurveFunction& only_function(const CurveTable& table, const char* caller) {
  if (table.functions.size() != 1) throw EvaluationError(std::string(caller) + " needs a uniform (one-function) table");
  return table.functions.front();
}

}  // namespace

double evaluate_uniform_curve(const CurveTable& table, const std::vector<double>& points, std::int64_t k) {
  const CurveFunction& phi = only_function(table, "evaluate_uniform_curve");
  return combine(table, phi.first, phi.values, points, k);
}

double evaluate_uniform_curve_derivative(const CurveTable& table, const std::vector<double>& points, std::int64_t k, int order) {
  const CurveFunction& phi = only_function(table, "evaluate_uniform_curve_derivative");
  if (order < 1 || order > static_cast<int>(table.derivative_orders))
    throw EvaluationError("this curve table holds derivatives of order 1.." + std::to_string(table.derivative_orders) +
                          " only, not " + std::to_string(order) +
                          " (the scheme is not that smooth, or the table is from a scheme without derivative tables)");
  const GridValues& d = phi.derivatives[static_cast<std::size_t>(order - 1)];
  return combine(table, d.first, d.values, points, k);
}

}  // namespace stencil_runtime
