#pragma once
// One iteration's quadratic model of the fit and its solves:
//   sum_k (A_k P - X_k)^T M_k (A_k P - X_k) + s |L P|^2 + mu |P - P0|^2
// over the control positions P (n x 3), A_k the stencil rows, M_k the error
// weights (already divided by the point count), L the control Laplacian. The
// normal equations are sparse and positive (semi)definite; they are built
// once per iteration and factorised (sparse Cholesky, LDL^T) once per damping
// mu tried, the symbolic analysis kept from one solve to the next while the
// matrix's sparsity pattern stays (FactorCache).
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <vector>

#include "stencil_runtime/stencil_rows.hpp"

namespace stencil_runtime::fitting {

// The factorisation kept between solves and iterations: the warm start. Its
// symbolic part (fill-reducing ordering, elimination tree) depends only on the
// matrix's sparsity pattern, which changes only when feet move to faces with
// other control points; once the fit settles it stays, and only the numeric
// factorisation is redone.
class FactorCache {
 public:
  using Solver = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>;
  // Analyses `matrix` (compressed) unless its pattern is the one analysed last, then factorises it.
  const Solver& factorize(const Eigen::SparseMatrix<double>& matrix);
  int factorizations() const { return factorizations_; }
  int analyses() const { return analyses_; }

 private:
  Solver solver_;
  Eigen::Index rows_ = -1;
  std::vector<Eigen::SparseMatrix<double>::StorageIndex> outer_, inner_;  // the pattern analysed
  int factorizations_ = 0, analyses_ = 0;
};

class NormalEquations {
 public:
  // `weights` empty: every M_k = identity_weight * I (PDM), whose normal
  // equations split into three with one matrix. Otherwise one symmetric 3x3
  // per row, and the system couples the coordinates.
  NormalEquations(const StencilRows& rows, const std::vector<Eigen::Matrix3d>& weights, double identity_weight,
                  const std::vector<Point>& targets, const Eigen::SparseMatrix<double>& laplacian, double smoothing);

  // The minimiser with damping mu towards `current`, factorised through
  // `cache`; throws FitError when the system is singular (too few points for
  // the control points, and no smoothing).
  std::vector<Point> solve(double mu, const std::vector<Point>& current, FactorCache& cache) const;

 private:
  std::size_t n_ = 0;
  bool coupled_ = false;
  Eigen::SparseMatrix<double> hessian_;  // n x n (split) or 3n x 3n (coupled, coordinate-major)
  Eigen::MatrixXd rhs_;                  // n x 3 or 3n x 1
};

// The stencil rows as an Eigen sparse matrix (rows x control vertices).
Eigen::SparseMatrix<double, Eigen::RowMajor> row_matrix(const StencilRows& rows);

}  // namespace stencil_runtime::fitting
