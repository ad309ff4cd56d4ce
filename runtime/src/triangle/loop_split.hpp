#pragma once
// Where a point of a triangle lands when a Loop step splits it in four
// (loop_step: child c < 3 covers corner c, its u axis along the face's edge
// c -> c+1; child 3 is the middle one, its corners at the midpoints of edges
// 0, 1, 2), and back. Every child's map keeps the orientation.
#include <array>
#include <utility>

#include "family/parameter_ops.hpp"

namespace stencil_runtime {

// The child holding (u, v), and the parameter there (exact or real parameters).
template <class P>
std::pair<int, std::array<P, 2>> loop_child(const P& u, const P& v) {
  // Barycentric coordinates times 2: (k, a, b) on corners 0, 1, 2. The child at
  // corner c holds the points where corner c's weight is at least 1/2.
  const P one = integer<P>(1);
  const P a = multiply(u, 2), b = multiply(v, 2);
  const P k = subtract(subtract(integer<P>(2), a), b);
  if (compare(k, one) >= 0) return {0, {a, b}};
  if (compare(a, one) >= 0) return {1, {b, k}};
  if (compare(b, one) >= 0) return {2, {k, a}};
  return {3, {subtract(one, k), subtract(one, a)}};
}

// The same on the grid (a, b) / d, in place: the child, and (a, b) its point over d.
inline int loop_child_on_grid(long& a, long& b, long d) {
  const long A = 2 * a, B = 2 * b, K = 2 * d - A - B;
  if (K >= d) return a = A, b = B, 0;
  if (A >= d) return a = B, b = K, 1;
  if (B >= d) return a = K, b = A, 2;
  return a = d - K, b = d - A, 3;
}

// Child c's parameter (u, v) in its parent's, in place: the inverse of loop_child.
inline void loop_parent(int c, double& u, double& v) {
  double pu = 0, pv = 0;
  switch (c) {
    case 0: pu = u / 2, pv = v / 2; break;
    case 1: pu = (2 - u - v) / 2, pv = u / 2; break;
    case 2: pu = v / 2, pv = (2 - u - v) / 2; break;
    default: pu = (1 - v) / 2, pv = (u + v) / 2; break;
  }
  u = pu, v = pv;
}

}  // namespace stencil_runtime
