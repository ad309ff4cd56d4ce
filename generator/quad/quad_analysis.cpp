#include "quad/quad_analysis.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "base/error.hpp"
#include "quad/ev_patch_solver.hpp"
#include "quad/patch_subdivision.hpp"
#include "quad/quad_descent.hpp"
#include <cstdio>

namespace sg {

namespace {

// Two-ring numbering: 0 = the vertex; 1 + 6k + p = point p of sector k, with p
// the sector chart positions (1,0), (1,1), (2,0), (2,1), (2,2), (1,2).
class TwoRing {
 public:
  explicit TwoRing(int v) : v_(v), layout_(v) {}
  std::size_t size() const { return static_cast<std::size_t>(6 * v_ + 1); }
  std::size_t at(int sector, int p) const { return static_cast<std::size_t>(1 + 6 * (((sector % v_) + v_) % v_) + p); }
  // Two-ring index of patch control point h of the patch in sector k.
  std::size_t of_patch_point(std::size_t h, int k) const {
    if (h == PatchLayout::ev()) return 0;
    if (h <= 2 * static_cast<std::size_t>(v_)) {
      const int j = static_cast<int>(h - 1) / 2;
      return at(j + k, (h % 2 == 1) ? 0 : 1);
    }
    switch (h - (2 * v_ + 1)) {
      case 0: return at(k - 1, 5);  // (2,-1)
      case 1: return at(k, 2);      // (2,0)
      case 2: return at(k, 3);      // (2,1)
      case 3: return at(k, 4);      // (2,2)
      case 4: return at(k, 5);      // (1,2)
      case 5: return at(k + 1, 2);  // (0,2)
      default: return at(k + 1, 3);  // (-1,2)
    }
  }
  const PatchLayout& layout() const { return layout_; }

 private:
  int v_;
  PatchLayout layout_;
};

Eigen::MatrixXd two_ring_matrix(const QuadScheme& scheme, int v, const TwoRing& ring) {
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(static_cast<long>(ring.size()), static_cast<long>(ring.size()));
  auto put = [&](std::size_t row, const SparseRow& weights, int k) {
    for (const auto& [h, w] : weights) S(static_cast<long>(row), static_cast<long>(ring.of_patch_point(h, k))) += to_double(w);
  };
  put(0, refined_chart_point(scheme, v, 0, 0), 0);
  constexpr int kOwn[6][2] = {{1, 0}, {1, 1}, {2, 0}, {2, 1}, {2, 2}, {1, 2}};
  for (int p = 0; p < 6; ++p) {
    const SparseRow row = refined_chart_point(scheme, v, kOwn[p][0], kOwn[p][1]);
    for (int k = 0; k < v; ++k) put(ring.at(k, p), row, k);
  }
  return S;
}

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

}  // namespace

SmoothnessReport analyse_quad_valence(const QuadScheme& scheme, int v, long samples) {
  SmoothnessReport r;
  r.valence = v;
  const TwoRing ring(v);
  const Eigen::MatrixXd S = two_ring_matrix(scheme, v, ring);
  Eigen::EigenSolver<Eigen::MatrixXd> eig(S, false);
  const Eigen::VectorXcd ev = eig.eigenvalues();
  classify_spectrum(r, std::vector<std::complex<double>>(ev.data(), ev.data() + ev.size()));
  if (!r.subdominant_real_double) return r;

  // Right eigenspace of the subdominant eigenvalue: two real vectors.
  const Eigen::MatrixXd shifted = S - r.subdominant * Eigen::MatrixXd::Identity(S.rows(), S.cols());
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(shifted, Eigen::ComputeFullV);
  const long n = S.cols();
  const Eigen::VectorXd ex = svd.matrixV().col(n - 1), ey = svd.matrixV().col(n - 2);

  // Characteristic map on every sector, sampled through the exact patch stencils.
  const PatchGrid patch = solve_ev_patch(scheme, v, samples);
  const long side = samples + 1;
  std::vector<std::vector<Eigen::Vector2d>> phi(static_cast<std::size_t>(v),
                                                std::vector<Eigen::Vector2d>(static_cast<std::size_t>(side * side)));
  for (int k = 0; k < v; ++k)
    for (long j = 0; j <= samples; ++j)
      for (long i = 0; i <= samples; ++i) {
        Eigen::Vector2d p(0, 0);
        const auto& w = patch.at(i, j);
        for (std::size_t h = 0; h < w.size(); ++h) {
          if (w[h] == 0) continue;
          const double c = to_double(w[h]);
          const long q = static_cast<long>(ring.of_patch_point(h, k));
          p += c * Eigen::Vector2d(ex(q), ey(q));
        }
        phi[static_cast<std::size_t>(k)][static_cast<std::size_t>(j * side + i)] = p;
      }
  // Orientation of every sampled cell (two triangles each).
  long positive = 0, negative = 0;
  for (int k = 0; k < v; ++k) {
    const auto& P = phi[static_cast<std::size_t>(k)];
    for (long j = 0; j < samples; ++j)
      for (long i = 0; i < samples; ++i) {
        const auto& a = P[static_cast<std::size_t>(j * side + i)];
        const auto& b = P[static_cast<std::size_t>(j * side + i + 1)];
        const auto& c = P[static_cast<std::size_t>((j + 1) * side + i + 1)];
        const auto& d = P[static_cast<std::size_t>((j + 1) * side + i)];
        for (double area : {cross(b - a, c - a), cross(c - a, d - a)}) {
          if (area > 0) ++positive;
          else ++negative;  // zero area is degenerate: counted against regularity
        }
      }
  }
  r.cells_checked = positive + negative;
  r.cells_flipped = std::min(positive, negative);
  r.map_regular = r.cells_flipped == 0;
  // Winding of the outer boundary: in each sector, (1,0) -> (1,1) -> (0,1).
  double angle = 0;
  Eigen::Vector2d prev = phi[0][static_cast<std::size_t>(samples)];  // sector 0, (1,0)
  for (int k = 0; k < v; ++k) {
    const auto& P = phi[static_cast<std::size_t>(k)];
    std::vector<Eigen::Vector2d> path;
    for (long j = 0; j <= samples; ++j) path.push_back(P[static_cast<std::size_t>(j * side + samples)]);
    for (long i = samples - 1; i >= 0; --i) path.push_back(P[static_cast<std::size_t>(samples * side + i)]);
    for (const auto& p : path) {
      angle += std::atan2(cross(prev, p), prev.dot(p));
      prev = p;
    }
  }
  r.winding = angle / (2 * std::numbers::pi);
  r.map_injective = r.map_regular && std::abs(std::abs(r.winding) - 1) < 1e-6;
  return r;
}

std::string analyse_quad_boundary(const QuadScheme& scheme, int faces, bool& ok) {
  std::vector<BoundarySector> sectors;
  for (int p = 0; p < faces; ++p) sectors.push_back({SectorKind::Crease, faces, p});
  const QuadDescent d = quad_descent(scheme, {}, sectors);
  // The spectrum of the one ring (2k+2 points, the same for every face).
  const std::size_t ring = static_cast<std::size_t>(2 * faces + 2);
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(static_cast<long>(ring), static_cast<long>(ring));
  for (std::size_t r = 0; r < ring; ++r)
    for (const auto& [c, w] : d.sectors.front().subdivision.extraordinary_child[r]) a(static_cast<long>(r), static_cast<long>(c)) += to_double(w);
  Eigen::EigenSolver<Eigen::MatrixXd> eig(a, false);
  std::vector<std::complex<double>> ev(eig.eigenvalues().data(), eig.eigenvalues().data() + eig.eigenvalues().size());
  std::sort(ev.begin(), ev.end(), [](const auto& x, const auto& y) { return std::abs(x) > std::abs(y); });
  std::string out = "boundary vertex in " + std::to_string(faces) + " face" + (faces == 1 ? "" : "s") + ": eigenvalues";
  for (std::size_t k = 0; k < std::min<std::size_t>(5, ev.size()); ++k) {
    char buf[64];
    if (std::abs(ev[k].imag()) > 1e-9) std::snprintf(buf, sizeof buf, " %.6f%+.6fi", ev[k].real(), ev[k].imag());
    else std::snprintf(buf, sizeof buf, " %.6f", ev[k].real());
    out += buf;
  }
  ok = std::all_of(d.sectors.begin(), d.sectors.end(), [](const QuadDescent::Sector& s) { return s.tangents.has_value(); });
  if (ok) return out + "; tangent plane: yes (the boundary curve's tangent and the first direction across it)\n";
  for (const QuadDescent::Sector& s : d.sectors)
    if (!s.tangents) return out + "; tangent plane: NO (" + s.sector.name() + ": " + s.no_tangents + ")\n";
  return out + "\n";
}

}  // namespace sg
