#pragma once
// Partition of unity for a (possibly non-uniform) scheme: the basis functions of
// all control points sum to 1 at every parameter.
#include <optional>
#include <string>
#include <vector>

#include "curve/curve_solution.hpp"

namespace sg {

// Sets of translation-invariant types that must sum to 1 on their own far from
// the special point: those placed toward -infinity and those toward +infinity
// (one set for a uniform scheme).
std::vector<std::vector<std::size_t>> pou_groups(const CurveScheme& s, const std::vector<std::size_t>& invariant);

// Sum over translation-invariant types h and their placements j of phi_h(K/n - j).
Rational invariant_sum_at(const CurveScheme& s, const CurveSolution& sol, long K);

// Checks partition of unity at every residue and at every grid point near the
// special point; returns a description of the first failure. With `sum` 0 and
// the derivatives in `sol`: their sum vanishes (the derivative of 1).
std::optional<std::string> check_partition_of_unity(const CurveScheme& s, const CurveSolution& sol,
                                                    const Rational& sum = 1);

}  // namespace sg
