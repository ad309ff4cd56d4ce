#include "curve/curve_table_binary.hpp"

#include "common/byte_writer.hpp"
#include "stencil_runtime/binary_format.hpp"

namespace sg {
namespace fmt = stencil_runtime::format;

std::string curve_table_to_binary(const CurveTable& t, std::uint64_t scheme_hash) {
  std::string out(fmt::kCurveMagic, sizeof fmt::kCurveMagic);
  put<std::uint32_t>(out, fmt::kCurveVersion);
  put<std::uint32_t>(out, static_cast<std::uint32_t>(t.arity));
  put<std::uint32_t>(out, static_cast<std::uint32_t>(t.n));
  put<std::uint32_t>(out, static_cast<std::uint32_t>(t.functions.size()));
  put<std::uint64_t>(out, scheme_hash);
  for (const auto& f : t.functions) {
    put<std::uint32_t>(out, static_cast<std::uint32_t>(f.name.size()));
    out += f.name;
    put<std::uint8_t>(out, static_cast<std::uint8_t>(f.placement));
    put<std::int64_t>(out, f.position);
    const long first = f.values.empty() ? 0 : f.values.begin()->first;
    const long last = f.values.empty() ? -1 : f.values.rbegin()->first;
    put<std::int64_t>(out, first);
    put<std::uint32_t>(out, static_cast<std::uint32_t>(last - first + 1));
    for (long k = first; k <= last; ++k) {
      const auto it = f.values.find(k);
      put<double>(out, it == f.values.end() ? 0.0 : to_double(it->second));
    }
  }
  put<std::uint64_t>(out, fmt::fnv1a64(reinterpret_cast<const unsigned char*>(out.data()), out.size()));
  return out;
}

}  // namespace sg
