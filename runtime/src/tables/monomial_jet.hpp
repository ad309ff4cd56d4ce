#pragma once
// The monomials x^e y^f of total degree <= d at one point, in the order of
// TriangleTables::polynomial() (f = 0..d, e = 0..d-f), with their partials up
// to second order: what a polynomial regular patch (Loop's quartic) is
// evaluated and differentiated with, at load for the derivative stencils and
// in the descent per point. Fixed-size: no allocation in inner loops.
#include <array>
#include <cstddef>

namespace stencil_runtime {

struct MonomialJet {
  static constexpr int kMaxDegree = 8;  // the loader's limit on the regular polynomial
  static constexpr std::size_t kMaxTerms = (kMaxDegree + 1) * (kMaxDegree + 2) / 2;
  std::size_t terms = 0;
  std::array<double, kMaxTerms> value{}, dx{}, dy{}, dxx{}, dxy{}, dyy{};

  // degree in 0..kMaxDegree (the caller's tables have checked it).
  MonomialJet(int degree, double x, double y) {
    std::array<double, kMaxDegree + 1> px{}, py{};
    px[0] = py[0] = 1;
    for (int e = 1; e <= degree; ++e) px[idx(e)] = px[idx(e - 1)] * x, py[idx(e)] = py[idx(e - 1)] * y;
    for (int f = 0; f <= degree; ++f)
      for (int e = 0; e + f <= degree; ++e, ++terms) {
        value[terms] = px[idx(e)] * py[idx(f)];
        dx[terms] = e >= 1 ? e * px[idx(e - 1)] * py[idx(f)] : 0.0;
        dy[terms] = f >= 1 ? f * px[idx(e)] * py[idx(f - 1)] : 0.0;
        dxx[terms] = e >= 2 ? e * (e - 1) * px[idx(e - 2)] * py[idx(f)] : 0.0;
        dxy[terms] = e >= 1 && f >= 1 ? e * f * px[idx(e - 1)] * py[idx(f - 1)] : 0.0;
        dyy[terms] = f >= 2 ? f * (f - 1) * px[idx(e)] * py[idx(f - 2)] : 0.0;
      }
  }

 private:
  static std::size_t idx(int e) { return static_cast<std::size_t>(e); }
};

}  // namespace stencil_runtime
