#include "triangle/triangle_analysis.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "triangle/triangle_patch.hpp"
#include "triangle/triangle_refinement.hpp"

namespace sg {
namespace {

Eigen::MatrixXd matrix_on(const TriangleScheme& scheme, const SectorChart& chart, const TriangleWeights<Real>& w) {
  const auto rows = refinement_matrix(scheme.refinement, chart, w);
  const long m = static_cast<long>(chart.size());
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(m, m);
  for (long r = 0; r < m; ++r)
    for (const auto& [c, x] : rows[static_cast<std::size_t>(r)]) S(r, static_cast<long>(c)) += to_double(x);
  return S;
}

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

}  // namespace

SmoothnessReport analyse_triangle_valence(const TriangleScheme& scheme, int v, long samples) {
  SmoothnessReport r;
  r.valence = v;
  const TriangleWeights<Real> weights = triangle_weights<Real>(scheme, v);
  // The two-ring is closed under the (composite) step for both refinements.
  const Eigen::MatrixXd S2 = matrix_on(scheme, SectorChart(v, 2), weights);
  Eigen::EigenSolver<Eigen::MatrixXd> eig(S2, false);
  const Eigen::VectorXcd ev = eig.eigenvalues();
  classify_spectrum(r, std::vector<std::complex<double>>(ev.data(), ev.data() + ev.size()));
  if (!r.subdominant_real_double) return r;

  // Right eigenvectors of the subdominant eigenvalue on the patches' chart.
  const TrianglePatch<Real> patch = solve_triangle_patch<Real>(scheme, v, samples, solve_regular(scheme, samples));
  const SectorChart& chart = patch.chart;
  const Eigen::MatrixXd S = matrix_on(scheme, chart, weights);
  const Eigen::MatrixXd shifted = S - r.subdominant * Eigen::MatrixXd::Identity(S.rows(), S.cols());
  Eigen::BDCSVD<Eigen::MatrixXd> svd(shifted, Eigen::ComputeFullV);
  const long n = S.cols();
  const Eigen::VectorXd ex = svd.matrixV().col(n - 1), ey = svd.matrixV().col(n - 2);

  // The characteristic map on every sector: sector k's stencil is sector 0's
  // with every control point turned by k sectors.
  const long side = samples + 1;
  std::vector<std::vector<Eigen::Vector2d>> phi(static_cast<std::size_t>(v),
                                                std::vector<Eigen::Vector2d>(static_cast<std::size_t>(side * side)));
  for (int k = 0; k < v; ++k)
    for (long j = 0; j <= samples; ++j)
      for (long i = 0; i + j <= samples; ++i) {
        Eigen::Vector2d p(0, 0);
        for (const auto& [h, w] : patch.at(i, j)) {
          SectorPoint q = chart.point(h);
          if (q.a > 0) q.sector = (q.sector + k) % v;
          const long id = static_cast<long>(chart.index(q));
          p += to_double(w) * Eigen::Vector2d(ex(id), ey(id));
        }
        phi[static_cast<std::size_t>(k)][static_cast<std::size_t>(j * side + i)] = p;
      }
  long positive = 0, negative = 0;
  for (const auto& P : phi)
    for (long j = 0; j < samples; ++j)
      for (long i = 0; i + j < samples; ++i) {
        auto at = [&](long a, long b) { return P[static_cast<std::size_t>(b * side + a)]; };
        const double up = cross(at(i + 1, j) - at(i, j), at(i, j + 1) - at(i, j));
        (up > 0 ? positive : negative)++;
        if (i + j + 2 <= samples) {
          const double down = cross(at(i + 1, j + 1) - at(i + 1, j), at(i, j + 1) - at(i + 1, j));
          (down > 0 ? positive : negative)++;
        }
      }
  r.cells_checked = positive + negative;
  r.cells_flipped = std::min(positive, negative);
  r.map_regular = r.cells_flipped == 0;
  // Winding of the outer boundary: in each sector from e_k to e_{k+1} (i + j = samples).
  double angle = 0;
  Eigen::Vector2d prev = phi[0][static_cast<std::size_t>(samples)];
  for (const auto& P : phi)
    for (long j = 0; j <= samples; ++j) {
      const Eigen::Vector2d p = P[static_cast<std::size_t>(j * side + samples - j)];
      angle += std::atan2(cross(prev, p), prev.dot(p));
      prev = p;
    }
  r.winding = angle / (2 * std::numbers::pi);
  r.map_injective = r.map_regular && std::abs(std::abs(r.winding) - 1) < 1e-6;
  return r;
}

}  // namespace sg
