#include "stencil_runtime/curve_table.hpp"

#include <cmath>

#include "binary_reader.hpp"

namespace stencil_runtime {

CurveTable load_curve_table(const std::string& path, std::uint64_t expected_hash) {
  const std::string bytes = detail::read_binary_file(path);
  detail::BinaryReader r(bytes, path);
  detail::check_envelope(bytes, r, format::kCurveMagic, "binary curve table");
  CurveTable t;
  const auto version = r.get<std::uint32_t>();
  if (version != format::kCurveVersion)
    r.fail("format version " + std::to_string(version) + " is not supported (expected " + std::to_string(format::kCurveVersion) + ")");
  t.arity = r.get<std::uint32_t>();
  t.n = r.get<std::uint32_t>();
  const auto count = r.get<std::uint32_t>();
  t.scheme_hash = r.get<std::uint64_t>();
  if (expected_hash != 0 && t.scheme_hash != expected_hash) r.fail("made from a different scheme (hash mismatch)");
  if (t.n == 0 || t.n > static_cast<std::uint32_t>(limits::kMaxRate) || (t.arity != 2 && t.arity != 3))
    r.fail("invalid header (n must be 1.." + std::to_string(limits::kMaxRate) + ", arity 2 or 3)");
  if (count == 0 || count > 64) r.fail("invalid function count " + std::to_string(count) + " (1..64)");
  for (std::uint32_t i = 0; i < count; ++i) {
    CurveFunction f;
    const auto name_length = r.get<std::uint32_t>();
    if (name_length > 256) r.fail("function name longer than 256 bytes");
    f.name = r.get_string(name_length);
    const auto placement = r.get<std::uint8_t>();
    if (placement > 3) r.fail("invalid placement code " + std::to_string(placement));
    f.placement = static_cast<format::Placement>(placement);
    f.position = r.get<std::int64_t>();
    f.first = r.get<std::int64_t>();
    // Grid indices of a real table are small (support times rate); far larger
    // ones would only make index arithmetic overflow.
    constexpr std::int64_t kMaxIndex = std::int64_t{1} << 40;
    if (f.position < -kMaxIndex || f.position > kMaxIndex || f.first < -kMaxIndex || f.first > kMaxIndex)
      r.fail("function " + quoted_excerpt(f.name) + ": position or first grid index outside +-2^40");
    const auto size = r.get<std::uint32_t>();
    if (size > (bytes.size() - r.position()) / 8) r.fail("truncated value block in function " + quoted_excerpt(f.name));
    f.values.resize(size);
    for (auto& v : f.values) {
      v = r.get<double>();
      if (!std::isfinite(v)) r.fail("a value of function '" + f.name + "' is not finite");
    }
    t.functions.push_back(std::move(f));
  }
  if (r.position() != bytes.size() - 8) r.fail("unexpected trailing bytes");
  return t;
}

double evaluate_uniform_curve(const CurveTable& table, const std::vector<double>& points, std::int64_t k) {
  if (table.functions.size() != 1) throw EvaluationError("evaluate_uniform_curve needs a uniform (one-function) table");
  const CurveFunction& phi = table.functions.front();
  double sum = 0;
  for (std::size_t j = 0; j < points.size(); ++j) {
    std::int64_t at = 0;
    if (__builtin_sub_overflow(k, static_cast<std::int64_t>(j) * table.n, &at)) continue;  // beyond every support
    sum += points[j] * phi.at(at);
  }
  return sum;
}

}  // namespace stencil_runtime
