#include "fitting/normal_equations.hpp"

#include <algorithm>
#include <string>

#include "stencil_runtime/surface_fit.hpp"

namespace stencil_runtime::fitting {

Eigen::SparseMatrix<double, Eigen::RowMajor> row_matrix(const StencilRows& rows) {
  Eigen::SparseMatrix<double, Eigen::RowMajor> a(static_cast<Eigen::Index>(rows.rows()),
                                                 static_cast<Eigen::Index>(rows.columns));
  a.reserve(static_cast<Eigen::Index>(rows.weights.size()));
  for (std::size_t r = 0; r < rows.rows(); ++r) {
    a.startVec(static_cast<Eigen::Index>(r));
    for (std::size_t e = rows.offsets[r]; e < rows.offsets[r + 1]; ++e)
      a.insertBack(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(rows.vertices[e])) = rows.weights[e];
  }
  a.finalize();
  return a;
}

NormalEquations::NormalEquations(const StencilRows& rows, const std::vector<Eigen::Matrix3d>& weights,
                                 double identity_weight, const std::vector<Point>& targets,
                                 const Eigen::SparseMatrix<double>& laplacian, double smoothing)
    : n_(rows.columns), coupled_(!weights.empty()) {
  const auto a = row_matrix(rows);
  const Eigen::Index m = a.rows(), n = a.cols();
  Eigen::MatrixXd x(m, 3);
  for (Eigen::Index k = 0; k < m; ++k)
    for (int c = 0; c < 3; ++c) x(k, c) = targets[static_cast<std::size_t>(k)][c];
  const Eigen::SparseMatrix<double> smooth = smoothing * (laplacian.transpose() * laplacian);
  if (!coupled_) {
    hessian_ = identity_weight * Eigen::SparseMatrix<double>(a.transpose() * a) + smooth;
    rhs_ = identity_weight * (a.transpose() * x);
    return;
  }
  // Block (c, d) of the coupled matrix is A^T diag(M_k(c, d)) A.
  std::vector<Eigen::Triplet<double>> entries;
  rhs_ = Eigen::MatrixXd::Zero(3 * n, 1);
  for (int c = 0; c < 3; ++c)
    for (int d = c; d < 3; ++d) {
      Eigen::VectorXd w(m);
      for (Eigen::Index k = 0; k < m; ++k) w[k] = weights[static_cast<std::size_t>(k)](c, d);
      const Eigen::SparseMatrix<double> block = a.transpose() * w.asDiagonal() * a;
      for (Eigen::Index col = 0; col < block.outerSize(); ++col)
        for (Eigen::SparseMatrix<double>::InnerIterator it(block, col); it; ++it) {
          entries.emplace_back(c * n + it.row(), d * n + it.col(), it.value());
          if (c != d) entries.emplace_back(d * n + it.col(), c * n + it.row(), it.value());
        }
      rhs_.block(c * n, 0, n, 1) += a.transpose() * w.cwiseProduct(x.col(d));
      if (c != d) rhs_.block(d * n, 0, n, 1) += a.transpose() * w.cwiseProduct(x.col(c));
    }
  for (int c = 0; c < 3; ++c)
    for (Eigen::Index col = 0; col < smooth.outerSize(); ++col)
      for (Eigen::SparseMatrix<double>::InnerIterator it(smooth, col); it; ++it)
        entries.emplace_back(c * n + it.row(), c * n + it.col(), it.value());
  hessian_.resize(3 * n, 3 * n);
  hessian_.setFromTriplets(entries.begin(), entries.end());
}

const FactorCache::Solver& FactorCache::factorize(const Eigen::SparseMatrix<double>& matrix) {
  const auto* outer = matrix.outerIndexPtr();
  const auto* inner = matrix.innerIndexPtr();
  const std::size_t columns = static_cast<std::size_t>(matrix.outerSize()), entries = static_cast<std::size_t>(matrix.nonZeros());
  const bool same = matrix.isCompressed() && rows_ == matrix.rows() && outer_.size() == columns + 1 &&
                    inner_.size() == entries && std::equal(outer_.begin(), outer_.end(), outer) &&
                    std::equal(inner_.begin(), inner_.end(), inner);
  if (!same) {
    solver_.analyzePattern(matrix);
    ++analyses_;
    rows_ = matrix.rows();
    outer_.assign(outer, outer + columns + 1);
    inner_.assign(inner, inner + entries);
  }
  solver_.factorize(matrix);
  ++factorizations_;
  return solver_;
}

std::vector<Point> NormalEquations::solve(double mu, const std::vector<Point>& current, FactorCache& cache) const {
  const Eigen::Index n = static_cast<Eigen::Index>(n_);
  const Eigen::Index size = hessian_.rows();
  Eigen::SparseMatrix<double> damped = hessian_;
  Eigen::MatrixXd rhs = rhs_;
  if (mu > 0) {
    Eigen::SparseMatrix<double> identity(size, size);
    identity.setIdentity();
    damped += mu * identity;
    for (Eigen::Index i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) {
        if (coupled_) rhs(c * n + i, 0) += mu * current[static_cast<std::size_t>(i)][c];
        else rhs(i, c) += mu * current[static_cast<std::size_t>(i)][c];
      }
  }
  damped.makeCompressed();
  const FactorCache::Solver& solver = cache.factorize(damped);
  // LDL^T of a semidefinite matrix can succeed with a zero pivot: check the
  // pivots against the matrix's scale too.
  const double scale = damped.diagonal().cwiseAbs().maxCoeff();
  if (solver.info() != Eigen::Success || !(solver.vectorD().minCoeff() > 1e-13 * scale))
    throw FitError("the fit's least-squares system is singular (" + std::to_string(n_) +
                   " control points are not all determined by the points): add smoothing or points");
  const Eigen::MatrixXd solution = solver.solve(rhs);
  std::vector<Point> out(n_);
  for (Eigen::Index i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c)
      out[static_cast<std::size_t>(i)][c] = coupled_ ? solution(c * n + i, 0) : solution(i, c);
  return out;
}

}  // namespace stencil_runtime::fitting
