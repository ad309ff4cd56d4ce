#pragma once
// Floor/ceiling division and a non-negative remainder for grid indices
// (C++'s / and % truncate toward zero, which is wrong for negative grid points).

namespace sg {

inline long floor_div(long a, long b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
inline long ceil_div(long a, long b) { return -floor_div(-a, b); }
inline long pos_mod(long a, long b) { return ((a % b) + b) % b; }

}  // namespace sg
