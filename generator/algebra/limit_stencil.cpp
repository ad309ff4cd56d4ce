#include "algebra/limit_stencil.hpp"

#include <Eigen/Dense>
#include <boost/multiprecision/eigen.hpp>

#include "algebra/exact_linear_system.hpp"
#include "base/error.hpp"

namespace sg {

std::vector<Rational> limit_stencil(const std::vector<std::vector<std::pair<std::size_t, Rational>>>& a,
                                    const std::string& context) {
  const LinearSolution sol = left_fixed_vector(a);
  if (sol.status != LinearSolution::Status::Unique) throw Error(context + ": the limit stencil has " + sol.describe());
  return sol.values;
}

std::vector<Real> limit_stencil(const std::vector<std::vector<std::pair<std::size_t, Real>>>& a,
                                const std::string& context) {
  using Matrix = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;
  using Vector = Eigen::Matrix<Real, Eigen::Dynamic, 1>;
  const Eigen::Index m = static_cast<Eigen::Index>(a.size());
  // Columns of (A - I), transposed; the last equation (dependent: the rows of A
  // sum to 1) is replaced by sum x = 1.
  Matrix s = Matrix::Zero(m, m);
  for (Eigen::Index r = 0; r < m; ++r)
    for (const auto& [c, w] : a[static_cast<std::size_t>(r)]) s(static_cast<Eigen::Index>(c), r) += w;
  for (Eigen::Index r = 0; r < m; ++r) s(r, r) -= 1;
  s.row(m - 1).setOnes();
  Vector rhs = Vector::Zero(m);
  rhs(m - 1) = 1;
  const auto lu = s.fullPivLu();
  if (lu.rank() < m) throw Error(context + ": the limit stencil is not unique (eigenvalue 1 is not simple)");
  const Vector x = lu.solve(rhs);
  return std::vector<Real>(x.data(), x.data() + m);
}

}  // namespace sg
