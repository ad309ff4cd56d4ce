#pragma once
// The special (single-column) types of a non-uniform scheme, solved in global
// coordinates X = K/n along the orbits K -> a K, which leave every special
// support unless K = 0 (residue_solver.hpp). Shared by the values (factor 1)
// and the first derivative (factor a: differentiating the relation
// phi_h(x) = sum c phi_g(a x - s) multiplies its right side by a).
#include <utility>
#include <vector>

#include "algebra/exact_linear_system.hpp"
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

// Index of type h among `types` (types.size() when absent).
std::size_t position_in(const std::vector<std::size_t>& types, std::size_t h);

// The relations at X = 0 of the special types `at_zero` (special_types_at_zero)
// as equations over those unknowns: G_h - factor sum c G_g = factor known_h.
// Singular on their own (A has the eigenvalue 1, and 1/a for the derivative):
// the caller adds the equation that fixes the solution.
void add_relations_at_zero(const CurveScheme& s, const CurveSolution& sol, const std::vector<std::size_t>& at_zero,
                           const Rational& factor, ExactLinearSystem& system);

// Sets the global value of type h at X = K/n (inside its support).
void set_global_value(const CurveScheme& s, CurveSolution& sol, std::size_t h, long K, const Rational& v);

}  // namespace sg
