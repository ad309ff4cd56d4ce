#pragma once
// A primal quad subdivision scheme (Catmull-Clark family), reduced to what the
// surface solvers need: the face, edge and vertex rules, the vertex rule as a
// function of the valence, and the uniform curve scheme whose tensor product is
// the regular case. Only schemes whose rules reach the one-ring (basis support
// [-2,2]^2 in the regular case, 2v+8 control points per patch) are covered.
#include <cstdint>
#include <string>

#include "algebra/rational.hpp"
#include "base/limits.hpp"
#include "curve/curve_scheme.hpp"

namespace sg {

// New vertex = centre * old vertex + edge * (each of its v edge neighbours)
//            + face * (each of its v diagonal neighbours across a quad).
struct VertexRule {
  Rational centre, edge, face;
};

struct QuadScheme {
  std::string name, description, source;
  std::uint64_t hash = 0;
  Bindings parameters;  // resolved, after command-line overrides
  CurveScheme curve;    // regular case = curve (x) curve

  Rational face_corner;           // face point: face_corner * each of the 4 corners
  Rational edge_end, edge_wing;   // edge point: edge_end * both ends + edge_wing * the 4 other corners of its 2 faces
  std::string vertex_centre, vertex_edge, vertex_face;  // formulas in v (and the parameters)
  int min_valence = limits::kMinValence, max_valence = limits::kMaxValence;

  // Optional rules for one subdivision step of a mesh with arbitrary polygons
  // (after which every face is a quad). Face point: the centroid. Edge point:
  // edge_end * (both ends) + edge_face * (both new face points). Vertex point
  // at valence v: centre * old + midpoint * (mean of the edge midpoints) +
  // face * (mean of the new face points). On quads they must equal the quad rules.
  struct PolygonRules {
    bool present = false;
    Rational edge_end, edge_face;
    std::string vertex_centre, vertex_midpoint, vertex_face;  // formulas in v
  } polygon;
  struct PolygonVertexRule {
    Rational centre, midpoint, face;
  };
  PolygonVertexRule polygon_vertex_rule(int valence) const;

  // Exact vertex rule at valence v; throws sg::Error naming the file when v is
  // outside [min_valence, max_valence] or the weights do not sum to 1.
  VertexRule vertex_rule(int valence) const;
};

}  // namespace sg
