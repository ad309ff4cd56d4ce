#pragma once
// A dart's slit folded shut, for its tangent plane (quad and triangle
// sectors alike). The sector's chart is cut open along the infinitely sharp
// crease that ends at the dart, so the points on the slit's far side (ray k)
// are copies of those on its near side (ray 0): the same mesh points. The
// patch's surface is that of the points with each copy folded onto its twin;
// the folded A0 has no slit modes (ray k minus ray 0, such as e_k - e_0 for
// 1/2, zero on any mesh), so its tangent plane needs no boundary curve to
// contain. Stencils found on the folded points are spread back, with their
// weight on the twins and none on the copies.
#include <cstddef>
#include <utility>
#include <vector>

#include "algebra/real.hpp"
#include "base/error.hpp"

namespace sg {

class SlitFold {
 public:
  // `twin[h]`: the point h folds onto, or h itself (then it is kept); a twin
  // is kept. With every point its own twin nothing is folded.
  explicit SlitFold(const std::vector<std::size_t>& twin) : twin_(twin), to_(twin.size()) {
    for (std::size_t h = 0; h < twin.size(); ++h)
      if (twin[h] == h) to_[h] = kept_++;
    for (std::size_t h = 0; h < twin.size(); ++h) to_[h] = to_[twin[h]];
  }

  std::size_t points() const { return kept_; }

  // A square matrix over the points (row r: child point r over the parents),
  // folded: a copy's row repeats its twin's and is left out; columns add up.
  template <class T>
  std::vector<std::vector<Real>> matrix(const std::vector<std::vector<std::pair<std::size_t, T>>>& rows) const {
    if (rows.size() != twin_.size()) throw Error("internal: a matrix to fold has a row count other than its points'");
    std::vector<std::vector<Real>> out(kept_, std::vector<Real>(kept_, Real(0)));
    for (std::size_t r = 0; r < rows.size(); ++r) {
      if (twin_[r] != r) continue;
      for (const auto& [c, w] : rows[r]) out[to_[r]][to_[c]] += real(w);
    }
    return out;
  }

  // Weights over the points, each copy's added to its twin's.
  template <class T>
  std::vector<Real> weights(const std::vector<T>& w) const {
    std::vector<Real> out(kept_, Real(0));
    for (std::size_t h = 0; h < w.size(); ++h) out[to_[h]] += real(w[h]);
    return out;
  }

  // Weights over the folded points back over all of them (0 on the copies).
  std::vector<Real> spread(const std::vector<Real>& folded) const {
    std::vector<Real> out(twin_.size(), Real(0));
    for (std::size_t h = 0; h < twin_.size(); ++h)
      if (twin_[h] == h) out[h] = folded[to_[h]];
    return out;
  }

 private:
  static Real real(const Rational& x) { return to_real(x); }
  static const Real& real(const Real& x) { return x; }

  std::vector<std::size_t> twin_;
  std::vector<std::size_t> to_;
  std::size_t kept_ = 0;
};

}  // namespace sg
