#pragma once
// A primal triangle subdivision scheme as data: the refinement topology (Loop's
// midpoint split, or Kobbelt's sqrt(3) face split with edge flips, whose two
// steps the generator composes into one ternary step) and the weights, with the
// vertex rule a formula in the valence v. Where the formula is irrational
// (cos(2 pi / v) in Loop's and sqrt(3)'s rules) the weights are evaluated in
// high precision and the tables say so.
#include <cstdint>
#include <optional>
#include <string>

#include "algebra/expression.hpp"
#include "algebra/rational.hpp"
#include "algebra/real.hpp"
#include "base/limits.hpp"

namespace sg {

enum class TriangleRefinement {
  Loop,  // one step: a new vertex on every edge, each triangle split into 4 (dilation 2)
  Sqrt3  // one step: a new vertex in every triangle, old edges flipped; two steps = dilation 3
};

struct TriangleScheme {
  std::string name, description, source;
  std::uint64_t hash = 0;
  Bindings parameters;
  TriangleRefinement refinement = TriangleRefinement::Loop;
  // Loop's edge point: edge_end * (both ends) + edge_opposite * (the two opposite vertices).
  Rational edge_end, edge_opposite;
  // Both: new vertex = (1 - v w) old + w * (each of its v neighbours), w = vertex_neighbour(v).
  // (For sqrt(3) the new face vertex is the centroid; the old vertex is relaxed.)
  std::string vertex_neighbour;
  // The rule along a crease (scheme field "crease_curve", a binary curve
  // scheme with midpoint edge rule): new vertex = crease_centre * old +
  // crease_neighbour * (each of its two crease neighbours); new edge points
  // are midpoints. Absent (has_crease false) when the scheme names none.
  bool has_crease = false;
  std::string crease_curve;
  Rational crease_centre, crease_neighbour;
  std::uint64_t crease_hash = 0;  // of the crease curve's scheme
  int min_valence = limits::kMinValence, max_valence = limits::kMaxValence;

  // The dilation of one refinement of the lattice (sqrt(3): two steps composed).
  int dilation() const { return refinement == TriangleRefinement::Loop ? 2 : 3; }
  const char* refinement_name() const { return refinement == TriangleRefinement::Loop ? "loop" : "sqrt3"; }

  // The neighbour weight at valence v exactly, or nullopt where it is
  // irrational. Throws sg::Error (naming the file) for a valence outside the
  // scheme's range or a formula that fails.
  std::optional<Rational> exact_neighbour_weight(int valence) const;
  // The same weight in high precision (always available).
  Real real_neighbour_weight(int valence) const;
};

// The rules of one valence in the arithmetic T (Rational or Real).
template <class T>
struct TriangleWeights {
  T edge_end, edge_opposite;         // Loop only
  T neighbour, neighbour_regular;    // w(v) and w(6)
};

}  // namespace sg
