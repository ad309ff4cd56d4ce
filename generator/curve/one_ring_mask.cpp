#include "curve/one_ring_mask.hpp"

#include "base/error.hpp"

namespace sg {

std::array<Rational, 5> one_ring_mask(const CurveScheme& c, const std::string& need) {
  if (!c.is_uniform() || c.arity != 2) throw Error("'" + c.name + "' must be a uniform binary curve scheme");
  std::array<Rational, 5> m;
  for (const Term& t : c.types[0].terms) {
    if (t.shift < -2 || t.shift > 2)
      throw Error("'" + c.name + "' has a mask coefficient at " + std::to_string(t.shift) + "; " + need);
    m[static_cast<std::size_t>(t.shift + 2)] = t.coeff;
  }
  if (m[0] != m[4] || m[1] != m[3]) throw Error("'" + c.name + "' must have a symmetric mask");
  return m;
}

}  // namespace sg
