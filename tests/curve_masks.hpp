#pragma once
// The masks of the shipped uniform curve schemes, as their descriptions state
// them, written out here independently of the scheme files.
#include <stdexcept>
#include <string>
#include <vector>

#include "independent.hpp"

namespace independent {

struct UniformMask {
  long arity, first;
  std::vector<Q> coeffs;
};
// The mask as stated in the scheme's description, written out here independently.
inline UniformMask mask_of(const std::string& name) {
  if (name == "fourpoint") return {2, -3, {Q(-1, 16), 0, Q(9, 16), 1, Q(9, 16), 0, Q(-1, 16)}};
  if (name == "dd6") return {2, -5, {Q(3, 256), 0, Q(-25, 256), 0, Q(150, 256), 1, Q(150, 256), 0, Q(-25, 256), 0, Q(3, 256)}};
  if (name == "ternary-dd4") return {3, -5, {Q(-4, 81), Q(-5, 81), 0, Q(30, 81), Q(60, 81), 1, Q(60, 81), Q(30, 81), 0, Q(-5, 81), Q(-4, 81)}};
  if (name == "nonpoly-curve") return {2, -2, {Q(1, 6), Q(1, 2), Q(2, 3), Q(1, 2), Q(1, 6)}};
  if (name == "bspline3") return {2, -2, {Q(1, 8), Q(1, 2), Q(3, 4), Q(1, 2), Q(1, 8)}};
  if (name == "chaikin") return {2, -2, {Q(1, 4), Q(3, 4), Q(3, 4), Q(1, 4)}};
  if (name == "ternary-bspline3") return {3, -4, {Q(1, 27), Q(4, 27), Q(10, 27), Q(16, 27), Q(19, 27), Q(16, 27), Q(10, 27), Q(4, 27), Q(1, 27)}};
  throw std::runtime_error("no mask for " + name);
}

}  // namespace independent
