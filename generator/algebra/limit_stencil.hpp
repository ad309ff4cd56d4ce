#pragma once
// The limit stencil of a subdivision matrix A (rows: the refined points over
// the coarse ones, each summing to 1): the left eigenvector x A = x for the
// eigenvalue 1 with sum x = 1. Exact for rational A; in 80 digits for real A
// (Eigen's full-pivot LU), whose callers report the residual.
#include <string>
#include <utility>
#include <vector>

#include "algebra/rational.hpp"
#include "algebra/real.hpp"

namespace sg {

// Throws sg::Error ("<context>: the limit stencil ...") when 1 is not a simple eigenvalue.
std::vector<Rational> limit_stencil(const std::vector<std::vector<std::pair<std::size_t, Rational>>>& a,
                                    const std::string& context);
std::vector<Real> limit_stencil(const std::vector<std::vector<std::pair<std::size_t, Real>>>& a,
                                const std::string& context);

}  // namespace sg
