#include "algebra/tangent_stencils.hpp"

#include <Eigen/Dense>
#include <boost/multiprecision/eigen.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <complex>

#include "base/error.hpp"

namespace sg {

namespace {
using Matrix = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;

Real magnitude(const Real& x) { return x < 0 ? Real(-x) : x; }

// Columns made orthonormal (Gram-Schmidt, twice for stability); false if they are dependent.
bool orthonormalise(Matrix& x) {
  for (int pass = 0; pass < 2; ++pass)
    for (Eigen::Index k = 0; k < x.cols(); ++k) {
      for (Eigen::Index j = 0; j < k; ++j) x.col(k) -= x.col(j).dot(x.col(k)) * x.col(j);
      const Real norm = sqrt(x.col(k).squaredNorm());
      if (norm == 0) return false;
      x.col(k) /= norm;
    }
  return true;
}

// The invariant subspace of `b` for the eigenvalue near `estimate` (double when
// `start` is m x 2, simple when m x 1), by inverse subspace iteration from
// `start`: returns the orthonormal basis and sets `lambda` to the Rayleigh
// quotient's mean eigenvalue.
Matrix eigenspace(const Matrix& b, Matrix start, double estimate, Real& lambda) {
  const Eigen::Index m = b.rows();
  if (!orthonormalise(start)) {  // a deterministic fallback start
    for (Eigen::Index i = 0; i < m; ++i) {
      start(i, 0) = Real(1 + i % 3);
      if (start.cols() > 1) start(i, 1) = Real(1 + (i * 7) % 5);
    }
    orthonormalise(start);
  }
  Matrix x = start;
  lambda = Real(estimate);
  for (int it = 0; it < 8; ++it) {
    Matrix shifted = b;
    // A shift a hair off lambda keeps the factorisation regular at working precision.
    const Real shift = lambda * (1 + Real("1e-60"));
    for (Eigen::Index i = 0; i < m; ++i) shifted(i, i) -= shift;
    x = shifted.fullPivLu().solve(x);
    if (!orthonormalise(x)) throw Error("internal: inverse iteration lost rank");
    const Matrix rq = x.transpose() * b * x;
    lambda = rq.trace() / Real(x.cols());
  }
  return x;
}

// t_u = c(end_u) L and t_v = c(end_v) L, with c = W R the characteristic map;
// returns the largest magnitude of their weights (not yet scaled).
Real combine_tangents(const Matrix& l, const Matrix& r, const std::vector<Real>& end_u, const std::vector<Real>& end_v,
                      TangentStencils& out, std::array<Real, 4>& c) {
  const Eigen::Index m = l.rows();
  auto characteristic = [&](const std::vector<Real>& w, Real& c0, Real& c1) {
    c0 = 0, c1 = 0;
    for (Eigen::Index h = 0; h < m; ++h) c0 += w[static_cast<std::size_t>(h)] * r(h, 0), c1 += w[static_cast<std::size_t>(h)] * r(h, 1);
  };
  characteristic(end_u, c[0], c[1]);
  characteristic(end_v, c[2], c[3]);
  out.u.resize(static_cast<std::size_t>(m));
  out.v.resize(static_cast<std::size_t>(m));
  Real largest = 0;
  for (Eigen::Index h = 0; h < m; ++h) {
    out.u[static_cast<std::size_t>(h)] = c[0] * l(h, 0) + c[1] * l(h, 1);
    out.v[static_cast<std::size_t>(h)] = c[2] * l(h, 0) + c[3] * l(h, 1);
    largest = std::max({largest, magnitude(out.u[static_cast<std::size_t>(h)]), magnitude(out.v[static_cast<std::size_t>(h)])});
  }
  return largest;
}

}  // namespace

std::optional<TangentStencils> tangent_stencils(const std::vector<std::vector<Real>>& a0, const std::vector<Real>& end_u,
                                                const std::vector<Real>& end_v, std::string& why) {
  const auto m = static_cast<Eigen::Index>(a0.size());
  if (m < 3 || end_u.size() != a0.size() || end_v.size() != a0.size()) throw Error("internal: tangent_stencils: sizes differ");
  Matrix a(m, m);
  for (Eigen::Index r = 0; r < m; ++r) {
    if (a0[static_cast<std::size_t>(r)].size() != a0.size()) throw Error("internal: tangent_stencils: A0 is not square");
    for (Eigen::Index c = 0; c < m; ++c) a(r, c) = a0[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)];
  }
  // The spectrum in doubles: 1 first, then the subdominant pair.
  Eigen::MatrixXd ad(m, m);
  for (Eigen::Index r = 0; r < m; ++r)
    for (Eigen::Index c = 0; c < m; ++c) ad(r, c) = to_double(a(r, c));
  Eigen::EigenSolver<Eigen::MatrixXd> left(ad.transpose(), true);
  std::vector<Eigen::Index> order(static_cast<std::size_t>(m));
  for (Eigen::Index i = 0; i < m; ++i) order[static_cast<std::size_t>(i)] = i;
  const Eigen::VectorXcd ev = left.eigenvalues();
  std::stable_sort(order.begin(), order.end(), [&](Eigen::Index p, Eigen::Index q) { return std::abs(ev(p)) > std::abs(ev(q)); });
  const std::complex<double> one = ev(order[0]), s1 = ev(order[1]), s2 = ev(order[2]), next = ev(order[3]);
  const double scale = 1e-9;
  if (std::abs(one - 1.0) > scale || std::abs(s1.imag()) > scale || std::abs(s2.imag()) > scale ||
      std::abs(s1.real() - s2.real()) > scale * std::max(1.0, std::abs(s1.real())) ||
      std::abs(next) >= std::abs(s1) - scale) {
    why = "the subdominant eigenvalue of A0 is not a real double eigenvalue with a gap below it (" + std::to_string(s1.real()) +
          (s1.imag() != 0 ? "+" + std::to_string(s1.imag()) + "i" : "") + ", " + std::to_string(s2.real()) + ", then |" +
          std::to_string(std::abs(next)) + "|)";
    return std::nullopt;
  }
  const double estimate = s1.real();
  auto start = [&](const Eigen::MatrixXcd& vectors) {
    Matrix x(m, 2);
    for (Eigen::Index i = 0; i < m; ++i)
      for (int k = 0; k < 2; ++k) x(i, k) = Real(vectors(i, order[static_cast<std::size_t>(1 + k)]).real());
    return x;
  };
  TangentStencils out;
  Real lambda_left, lambda_right;
  const Matrix l = eigenspace(a.transpose(), start(left.eigenvectors()), estimate, lambda_left);  // columns: left eigenvectors
  Eigen::EigenSolver<Eigen::MatrixXd> right_solver(ad, true);
  // The right solver orders its eigenvalues its own way: its pair nearest the estimate.
  Eigen::MatrixXcd rv = right_solver.eigenvectors();
  std::vector<Eigen::Index> near(static_cast<std::size_t>(m));
  for (Eigen::Index i = 0; i < m; ++i) near[static_cast<std::size_t>(i)] = i;
  std::stable_sort(near.begin(), near.end(), [&](Eigen::Index p, Eigen::Index q) {
    return std::abs(right_solver.eigenvalues()(p) - estimate) < std::abs(right_solver.eigenvalues()(q) - estimate);
  });
  Matrix rstart(m, 2);
  for (Eigen::Index i = 0; i < m; ++i)
    for (int k = 0; k < 2; ++k) rstart(i, k) = Real(rv(i, near[static_cast<std::size_t>(k)]).real());
  Matrix r = eigenspace(a, rstart, estimate, lambda_right);
  // Biorthogonal: L^T R = I.
  const Matrix lr = l.transpose() * r;
  r = r * lr.inverse();
  out.eigenvalue = lambda_left;
  out.second_eigenvalue = lambda_left;

  // The characteristic map at the ends of the patch's two edges from the vertex.
  std::array<Real, 4> c;
  const Real largest = combine_tangents(l, r, end_u, end_v, out, c);
  if (largest == 0) {
    why = "the characteristic map vanishes at the patch's corners";
    return std::nullopt;
  }
  // Scaled so that the largest weight is 1 (the length is arbitrary).
  for (Eigen::Index h = 0; h < m; ++h) out.u[static_cast<std::size_t>(h)] /= largest, out.v[static_cast<std::size_t>(h)] /= largest;
  Real residual = 0;
  for (const std::vector<Real>* t : {&out.u, &out.v})
    for (Eigen::Index c = 0; c < m; ++c) {
      Real s = -out.eigenvalue * (*t)[static_cast<std::size_t>(c)];
      for (Eigen::Index h = 0; h < m; ++h) s += (*t)[static_cast<std::size_t>(h)] * a(h, c);
      residual = std::max(residual, magnitude(s));
    }
  out.residual = residual;
  return out;
}

namespace {

Matrix square(const std::vector<std::vector<Real>>& a0, std::size_t columns_of_ends) {
  const auto m = static_cast<Eigen::Index>(a0.size());
  if (m < 3 || columns_of_ends != a0.size()) throw Error("internal: tangent_stencils: sizes differ");
  Matrix a(m, m);
  for (Eigen::Index r = 0; r < m; ++r) {
    if (a0[static_cast<std::size_t>(r)].size() != a0.size()) throw Error("internal: tangent_stencils: A0 is not square");
    for (Eigen::Index c = 0; c < m; ++c) a(r, c) = a0[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)];
  }
  return a;
}

std::string describe(const std::complex<double>& z) {
  return std::to_string(z.real()) + (std::abs(z.imag()) > 1e-9 ? (z.imag() > 0 ? "+" : "") + std::to_string(z.imag()) + "i" : "");
}

// Real start vectors for the eigenvalue `estimate` from a double eigen-decomposition (`dim` of them).
Matrix start_near(const Eigen::EigenSolver<Eigen::MatrixXd>& solver, double estimate, int dim) {
  const Eigen::Index m = solver.eigenvectors().rows();
  std::vector<Eigen::Index> near(static_cast<std::size_t>(m));
  for (Eigen::Index i = 0; i < m; ++i) near[static_cast<std::size_t>(i)] = i;
  std::stable_sort(near.begin(), near.end(), [&](Eigen::Index p, Eigen::Index q) {
    return std::abs(solver.eigenvalues()(p) - estimate) < std::abs(solver.eigenvalues()(q) - estimate);
  });
  Matrix x(m, dim);
  for (Eigen::Index i = 0; i < m; ++i)
    for (int k = 0; k < dim; ++k) x(i, k) = Real(solver.eigenvectors()(i, near[static_cast<std::size_t>(k)]).real());
  return x;
}

}  // namespace

std::optional<TangentStencils> boundary_tangent_stencils(const std::vector<std::vector<Real>>& a0,
                                                         const std::vector<Real>& end_u, const std::vector<Real>& end_v,
                                                         const std::vector<Real>& boundary_tangent,
                                                         const std::vector<std::vector<double>>& grid, long g,
                                                         std::string& why) {
  if (g < 1 || grid.size() != static_cast<std::size_t>((g + 1) * (g + 1))) throw Error("internal: boundary_tangent_stencils: grid size");
  std::vector<std::vector<std::size_t>> cells;
  for (long j = 0; j < g; ++j)
    for (long i = 0; i < g; ++i) {
      const auto at = [&](long x, long y) { return static_cast<std::size_t>(y * (g + 1) + x); };
      cells.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return boundary_tangent_stencils(a0, end_u, end_v, boundary_tangent, grid, cells, why);
}

std::optional<TangentStencils> boundary_tangent_stencils(const std::vector<std::vector<Real>>& a0,
                                                         const std::vector<Real>& end_u, const std::vector<Real>& end_v,
                                                         const std::vector<Real>& boundary_tangent,
                                                         const std::vector<std::vector<double>>& samples,
                                                         const std::vector<std::vector<std::size_t>>& cells,
                                                         std::string& why) {
  if (end_u.size() != end_v.size() || (!boundary_tangent.empty() && boundary_tangent.size() != end_u.size()))
    throw Error("internal: boundary_tangent_stencils: sizes differ");
  const Matrix a = square(a0, end_u.size());
  const Eigen::Index m = a.rows();
  Eigen::MatrixXd ad(m, m);
  for (Eigen::Index r = 0; r < m; ++r)
    for (Eigen::Index c = 0; c < m; ++c) ad(r, c) = to_double(a(r, c));
  const Eigen::EigenSolver<Eigen::MatrixXd> left(ad.transpose(), true), right(ad, true);
  std::vector<std::complex<double>> ev(left.eigenvalues().data(), left.eigenvalues().data() + m);
  std::stable_sort(ev.begin(), ev.end(), [](const auto& p, const auto& q) { return std::abs(p) > std::abs(q); });
  const double scale = 1e-9;
  const std::complex<double> one = ev[0], s1 = ev[1], s2 = ev[2], next = ev[3];
  if (std::abs(one - 1.0) > scale || std::abs(s1.imag()) > scale || std::abs(s2.imag()) > scale || s2.real() <= 0 ||
      std::abs(next) >= std::abs(s2) - scale) {
    why = "the two largest eigenvalues of A0 below 1 are not real with a gap below them (" + describe(s1) + ", " +
          describe(s2) + ", then " + describe(next) + ")";
    return std::nullopt;
  }
  const bool double_one = std::abs(s1.real() - s2.real()) <= scale * std::max(1.0, std::abs(s1.real()));
  Matrix l(m, 2), r(m, 2);
  Real lambda[2];
  if (double_one) {
    Real lr_lambda;
    l = eigenspace(a.transpose(), start_near(left, s1.real(), 2), s1.real(), lambda[0]);
    r = eigenspace(a, start_near(right, s1.real(), 2), s1.real(), lr_lambda);
    lambda[1] = lambda[0];
  } else {
    for (int k = 0; k < 2; ++k) {
      const double estimate = (k == 0 ? s1 : s2).real();
      Real unused;
      l.col(k) = eigenspace(a.transpose(), start_near(left, estimate, 1), estimate, lambda[k]).col(0);
      r.col(k) = eigenspace(a, start_near(right, estimate, 1), estimate, unused).col(0);
    }
  }
  // Is the boundary curve's tangent in the span of l_1, l_2? (least squares in Real; no boundary: nothing to contain)
  if (!boundary_tangent.empty()) {
    Eigen::Matrix<Real, Eigen::Dynamic, 1> b(m);
    for (Eigen::Index h = 0; h < m; ++h) b(h) = boundary_tangent[static_cast<std::size_t>(h)];
    const Matrix gram = l.transpose() * l;
    const Eigen::Matrix<Real, Eigen::Dynamic, 1> coeff = gram.inverse() * (l.transpose() * b);
    const Real off = sqrt((b - l * coeff).squaredNorm()), size = sqrt(b.squaredNorm());
    if (size == 0) throw Error("internal: boundary_tangent_stencils: no boundary tangent");
    if (off > size * Real("1e-40")) {
      why = "the two largest eigenvalues of A0 below 1 (" + describe(s1) + ", " + describe(s2) +
            ") have eigenvectors that do not contain the boundary curve's tangent (1/2): Reif's condition fails there, the "
            "surface approaches the vertex along other directions from inside than along its boundary, and the spectrum "
            "gives no tangent plane";
      return std::nullopt;
    }
  }
  r = r * (l.transpose() * r).inverse();  // biorthogonal: L^T R = I
  // Regularity of the characteristic map over the patch: the signed area of every sampled cell.
  std::vector<std::pair<double, double>> image(samples.size());
  for (std::size_t k = 0; k < samples.size(); ++k) {
    if (samples[k].size() != static_cast<std::size_t>(m)) throw Error("internal: boundary_tangent_stencils: sample size");
    double x = 0, y = 0;
    for (Eigen::Index h = 0; h < m; ++h) x += samples[k][static_cast<std::size_t>(h)] * to_double(r(h, 0)), y += samples[k][static_cast<std::size_t>(h)] * to_double(r(h, 1));
    image[k] = {x, y};
  }
  long positive = 0, negative = 0;
  double largest_area = 0;
  std::vector<double> areas;
  for (const auto& cell : cells) {  // twice the signed area (shoelace)
    double area = 0;
    for (std::size_t c = 0; c < cell.size(); ++c) {
      const auto& a = image.at(cell[c]);
      const auto& b = image.at(cell[(c + 1) % cell.size()]);
      area += a.first * b.second - a.second * b.first;
    }
    areas.push_back(area);
    largest_area = std::max(largest_area, std::abs(area));
  }
  for (double area : areas) {
    if (area > 1e-9 * largest_area) ++positive;
    else if (area < -1e-9 * largest_area) ++negative;
    else ++negative, ++positive;  // degenerate: counts against regularity either way
  }
  if (largest_area == 0 || std::min(positive, negative) > 0) {
    why = "the characteristic map of the two largest eigenvalues below 1 (" + describe(s1) + ", " + describe(s2) +
          ") is not regular on the patch (" + std::to_string(std::min(positive, negative)) + " of " + std::to_string(areas.size()) +
          " sampled cells folded or degenerate): they do not span a tangent plane";
    return std::nullopt;
  }
  TangentStencils out;
  out.eigenvalue = lambda[0];
  out.second_eigenvalue = lambda[1];
  std::array<Real, 4> c;  // c(end_u), c(end_v)
  const Real largest = combine_tangents(l, r, end_u, end_v, out, c);
  if (largest == 0 || c[0] * c[3] - c[1] * c[2] == 0) {
    why = "the characteristic map does not separate the patch's corners";
    return std::nullopt;
  }
  // Scaled so that the largest weight is 1; weights below 1e-60 are the
  // iteration's noise on points that take no part (exactly 0).
  for (Eigen::Index h = 0; h < m; ++h)
    for (std::vector<Real>* t : {&out.u, &out.v}) {
      Real& w = (*t)[static_cast<std::size_t>(h)];
      w /= largest;
      if (magnitude(w) < Real("1e-60")) w = 0;
    }
  // Residual of each eigenvector (largest weight 1).
  Real residual = 0;
  for (int k = 0; k < 2; ++k) {
    Real big = 0;
    for (Eigen::Index h = 0; h < m; ++h) big = std::max(big, magnitude(l(h, k)));
    for (Eigen::Index c = 0; c < m; ++c) {
      Real s = -lambda[k] * l(c, k);
      for (Eigen::Index h = 0; h < m; ++h) s += l(h, k) * a(h, c);
      residual = std::max(residual, magnitude(s) / big);
    }
  }
  out.residual = residual;
  return out;
}

}  // namespace sg
