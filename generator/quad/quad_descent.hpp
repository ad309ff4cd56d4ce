#pragma once
// What the runtime needs to evaluate a quad scheme's patches at any parameter
// by the scheme's own subdivision of the patch (docs/runtime.md, "Evaluation
// at any parameter"): the regular curve's mask (its two half-interval
// subdivision matrices follow), whether the mask and the mask of its derivative
// scheme are non-negative (then the limit and its derivatives lie in the convex
// hulls of the control points and their differences, which bounds the error),
// the regular basis as polynomial pieces where it is polynomial, and per
// extraordinary valence the patch's one-step subdivision matrices and the
// tangent stencils at the vertex.
#include <array>
#include <optional>
#include <vector>

#include "curve/polynomial_pieces.hpp"
#include "quad/ev_tangents.hpp"
#include "quad/patch_subdivision.hpp"
#include "quad/quad_scheme.hpp"

namespace sg {

struct QuadDescent {
  long mask_first = 0;
  std::vector<Rational> mask;  // a_i, i = mask_first ..: p'_k = sum_j a_{k - 2j} p_j
  bool mask_nonnegative = false;
  bool derivative_nonnegative = false;  // the mask 2 a(z) / (1 + z) of the derivative scheme
  std::optional<PolynomialPieces> pieces;
  struct Valence {
    int valence = 0;
    PatchSubdivision subdivision;
    bool nonnegative = false;  // every entry of A0 and of the regular children
    std::optional<EvTangents> tangents;  // the tangent plane at the vertex (ev_tangents.hpp)
    std::string no_tangents;             // why there are none
  };
  std::vector<Valence> valences;  // the extraordinary ones (valence 4 is the regular patch)
};

QuadDescent quad_descent(const QuadScheme& scheme, const std::vector<int>& valences);

}  // namespace sg
