// Built with -fno-math-errno (runtime/CMakeLists.txt): std::sqrt then needs no
// errno path and the row loop below runs as vector square roots; its argument
// is a sum of squares, never negative.
#include "regular_face_samples.hpp"

#include <cmath>

#include "stencil_runtime/derivatives.hpp"

namespace stencil_runtime {

namespace {

// out[i] = sum_q c[q] base[q stride + i], i < count: one component of four rows
// weighted, a loop of independent samples.
__attribute__((always_inline)) inline void weighted_sum(const double* c, const double* base, std::size_t stride, std::size_t count, double* __restrict out) {
  const double* __restrict b0 = base;
  const double* __restrict b1 = base + stride;
  const double* __restrict b2 = base + 2 * stride;
  const double* __restrict b3 = base + 3 * stride;
  const double c0 = c[0], c1 = c[1], c2 = c[2], c3 = c[3];
  for (std::size_t i = 0; i < count; ++i) out[i] = c0 * b0[i] + c1 * b1[i] + c2 * b2[i] + c3 * b3[i];
}

// The unit normals of a row of tangent pairs into c (cx, cy, cz, then the
// squared length); unit_cross's formula, split into loops over the row.
__attribute__((always_inline)) inline void unit_crosses(const double* __restrict ux, const double* __restrict uy,
                                                        const double* __restrict uz, const double* __restrict vx,
                                                        const double* __restrict vy, const double* __restrict vz,
                                                        std::size_t count, double* __restrict cx, double* __restrict cy,
                                                        double* __restrict cz, double* __restrict squared) {
  for (std::size_t i = 0; i < count; ++i) {
    const double x = uy[i] * vz[i] - uz[i] * vy[i];
    const double y = uz[i] * vx[i] - ux[i] * vz[i];
    const double z = ux[i] * vy[i] - uy[i] * vx[i];
    cx[i] = x, cy[i] = y, cz[i] = z;
    squared[i] = x * x + y * y + z * z;
  }
  // One division per sample: the normal differs from unit_cross's three by
  // at most an ulp of a double, far below the float it is written as.
  for (std::size_t i = 0; i < count; ++i) {
    const double scale = 1.0 / std::sqrt(squared[i]);
    cx[i] *= scale, cy[i] *= scale, cz[i] *= scale;
  }
}

}  // namespace

__attribute__((target_clones("avx2", "default")))
void regular_face_samples(const QuadPatch& patch, const double* w, const double* dw, int n, const Point* prepared,
                          std::array<float, 3>* positions, std::array<float, 3>* normals, RegularFaceScratch& scratch) {
  const auto count = static_cast<std::size_t>(n);
  // Structure of arrays, so that the loops over a row's samples run as vector
  // instructions: component k of row q at sample i is rows[(3q + k) n + i],
  // of its slope slopes[(3q + k) n + i].
  scratch.rows.resize(12 * count);
  scratch.slopes.resize(12 * count);
  double* __restrict rows = scratch.rows.data();
  double* __restrict slopes = scratch.slopes.data();
  // The weights by column (c n + i: weight c of sample i), so that the rows are
  // weighted sums over contiguous samples too.
  scratch.columns.resize(8 * count);
  double* __restrict columns = scratch.columns.data();
  for (std::size_t i = 0; i < count; ++i)
    for (std::size_t c = 0; c < 4; ++c) columns[c * count + i] = w[4 * i + c], columns[(4 + c) * count + i] = dw[4 * i + c];
  for (std::size_t q = 0; q < 4; ++q)
    for (std::size_t k = 0; k < 3; ++k) {
      const double p[4] = {prepared[patch.points[q * 4]][k], prepared[patch.points[q * 4 + 1]][k],
                           prepared[patch.points[q * 4 + 2]][k], prepared[patch.points[q * 4 + 3]][k]};
      weighted_sum(p, columns, count, count, rows + (3 * q + k) * count);
      weighted_sum(p, columns + 4 * count, count, count, slopes + (3 * q + k) * count);
    }
  // Per row of samples: the tangents' six components, the cross product, its
  // squared length, each an array over the row.
  scratch.row.resize(10 * count);
  double* __restrict ux = scratch.row.data();
  double* __restrict uy = ux + count;
  double* __restrict uz = uy + count;
  double* __restrict vx = uz + count;
  double* __restrict vy = vx + count;
  double* __restrict vz = vy + count;
  double* __restrict cx = vz + count;
  double* __restrict cy = cx + count;
  double* __restrict cz = cy + count;
  double* __restrict squared = cz + count;
  for (std::size_t j = 0; j < count; ++j) {
    const double* wy = w + 4 * j;
    const double* dwy = dw + 4 * j;
    if (positions) {  // regular_centres' sums, into the tangents' arrays before those are made
      weighted_sum(wy, rows, 3 * count, count, ux);
      weighted_sum(wy, rows + count, 3 * count, count, uy);
      weighted_sum(wy, rows + 2 * count, 3 * count, count, uz);
      std::array<float, 3>* out = positions + j * count;
      for (std::size_t i = 0; i < count; ++i)
        out[i] = {static_cast<float>(ux[i]), static_cast<float>(uy[i]), static_cast<float>(uz[i])};
    }
    // du = sum_q w_j[q] D[q], dv = sum_q w'_j[q] R[q], by component.
    double* const du[3] = {ux, uy, uz};
    double* const dv[3] = {vx, vy, vz};
    for (std::size_t k = 0; k < 3; ++k) {
      weighted_sum(wy, slopes + k * count, 3 * count, count, du[k]);
      weighted_sum(dwy, rows + k * count, 3 * count, count, dv[k]);
    }
    unit_crosses(ux, uy, uz, vx, vy, vz, count, cx, cy, cz, squared);
    std::array<float, 3>* out = normals + j * count;
    for (std::size_t i = 0; i < count; ++i) {
      if (squared[i] >= 1e-280) {
        out[i] = {static_cast<float>(cx[i]), static_cast<float>(cy[i]), static_cast<float>(cz[i])};
      } else {  // tiny, zero or not a number: unit_cross's other branches
        const Point u = unit_cross({ux[i], uy[i], uz[i]}, {vx[i], vy[i], vz[i]});
        out[i] = {static_cast<float>(u[0]), static_cast<float>(u[1]), static_cast<float>(u[2])};
      }
    }
  }
}

}  // namespace stencil_runtime
