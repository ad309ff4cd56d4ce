#include "curve/curve_table_binary.hpp"

#include <map>
#include <string>

#include "base/error.hpp"
#include "common/byte_writer.hpp"
#include "stencil_runtime/binary_format.hpp"

namespace sg {
namespace fmt = stencil_runtime::format;

namespace {

// Grid values dense from the first to the last nonzero one: first, count, values.
void put_grid_values(std::string& out, const std::map<long, Rational>& values) {
  const long first = values.empty() ? 0 : values.begin()->first;
  const long last = values.empty() ? -1 : values.rbegin()->first;
  put<std::int64_t>(out, first);
  put<std::uint32_t>(out, static_cast<std::uint32_t>(last - first + 1));
  for (long k = first; k <= last; ++k) {
    const auto it = values.find(k);
    put<double>(out, it == values.end() ? 0.0 : to_double(it->second));
  }
}

}  // namespace

std::string curve_table_to_binary(const CurveTable& t, std::uint64_t scheme_hash) {
  if (t.derivative_orders < 0 || t.derivative_orders > static_cast<int>(fmt::kMaxCurveDerivativeOrder))
    throw Error("internal: a curve table with " + std::to_string(t.derivative_orders) + " derivative orders");
  std::string out(fmt::kCurveMagic, sizeof fmt::kCurveMagic);
  put<std::uint32_t>(out, fmt::kCurveVersion);
  put<std::uint32_t>(out, static_cast<std::uint32_t>(t.arity));
  put<std::uint32_t>(out, static_cast<std::uint32_t>(t.n));
  put<std::uint32_t>(out, static_cast<std::uint32_t>(t.functions.size()));
  put<std::uint64_t>(out, scheme_hash);
  put<std::uint8_t>(out, static_cast<std::uint8_t>(t.derivative_orders));  // version 2
  for (const auto& f : t.functions) {
    put<std::uint32_t>(out, static_cast<std::uint32_t>(f.name.size()));
    out += f.name;
    put<std::uint8_t>(out, static_cast<std::uint8_t>(f.placement));
    put<std::int64_t>(out, f.position);
    put_grid_values(out, f.values);
    if (f.derivatives.size() != static_cast<std::size_t>(t.derivative_orders))
      throw Error("internal: function '" + f.name + "' lacks some of the table's derivative orders");
    for (const auto& d : f.derivatives) put_grid_values(out, d);
  }
  put<std::uint64_t>(out, fmt::fnv1a64(reinterpret_cast<const unsigned char*>(out.data()), out.size()));
  return out;
}

}  // namespace sg
