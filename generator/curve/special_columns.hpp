#pragma once
// The special (single-column) types of a non-uniform scheme, solved in global
// coordinates X = K/n along the orbits K -> a K, which leave every special
// support unless K = 0 (residue_solver.hpp). Shared by the values (factor 1)
// and the first derivative (factor a: differentiating the relation
// phi_h(x) = sum c phi_g(a x - s) multiplies its right side by a).
#include <utility>
#include <vector>

#include "curve/curve_solution.hpp"

namespace sg {

// Global value of type h at X = K/n: phi_h(K/n - p_h) (zero outside its support).
Rational global_value(const CurveScheme& s, const CurveSolution& sol, std::size_t h, long K);

// The right side of special type h's relation at X = K/n, without `factor`:
// returns the sum over its translation-invariant terms (known values in `sol`)
// and appends its special terms (type, coefficient), each at X = a K / n.
// Throws sg::Error when a special term is not stationary around 0.
Rational special_relation(const CurveScheme& s, const CurveSolution& sol, std::size_t h, long K,
                          std::vector<std::pair<std::size_t, Rational>>& special_terms);

// Fills every special type at every grid point but X = 0 by
// phi_h(K/n) = factor * (relation at K), outermost |K| first, from the
// invariant types' values already in `sol`.
void solve_special_orbits(const CurveScheme& s, CurveSolution& sol, const Rational& factor);

// The special types whose open support contains X = 0 (the unknowns there).
std::vector<std::size_t> special_types_at_zero(const CurveScheme& s, const CurveSolution& sol);

// Sets the global value of type h at X = K/n (inside its support).
void set_global_value(const CurveScheme& s, CurveSolution& sol, std::size_t h, long K, const Rational& v);

}  // namespace sg
