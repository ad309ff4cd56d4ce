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
#include <functional>
#include <string>
#include <optional>
#include <vector>

#include "curve/polynomial_pieces.hpp"
#include "quad/boundary_sector.hpp"
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
  // Faces at a vertex on a boundary (boundary_sector.hpp): their patch has no
  // stored stencils, only what generates them (the runtime expands them).
  struct Sector {
    BoundarySector sector;
    PatchSubdivision subdivision;
    std::vector<Rational> limit;  // W(0): the vertex's limit stencil, exact
    bool nonnegative = false;  // A0 and the mask: the limit lies in the hull of the points (quad_descent.cpp)
    std::optional<EvTangents> tangents;  // the tangent plane at the vertex, where the surface has one
    std::string no_tangents;             // why there is none
  };
  std::vector<Sector> sectors;
};

// `sectors`: the boundary sectors to describe (boundary_sectors(), or none).
// Valences and sectors are solved in parallel; `progress`, when given, hears
// of each valence and of every tenth of the sectors (large valences take
// minutes: the sectors up to 64 faces are thousands of exact eigen-analyses).
QuadDescent quad_descent(const QuadScheme& scheme, const std::vector<int>& valences,
                         const std::vector<BoundarySector>& sectors = {},
                         const std::function<void(const std::string&)>& progress = {});

}  // namespace sg
