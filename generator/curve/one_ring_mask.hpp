#pragma once
// The curve masks surfaces build their one-ring rules from: a quad scheme's
// regular curve (its tensor product) and a Loop scheme's crease curve.
#include <array>
#include <string>

#include "algebra/rational.hpp"
#include "curve/curve_scheme.hpp"

namespace sg {

// The mask of `curve` by shift -2..2 (even rule m[0], m[2], m[4]; odd rule
// m[1], m[3]) when the scheme is uniform, binary, supported on [-2, 2] and
// symmetric. Throws Error saying which it is not; `need` ends the message
// about a wider mask (who needs the one ring, and why).
std::array<Rational, 5> one_ring_mask(const CurveScheme& curve, const std::string& need);

}  // namespace sg
