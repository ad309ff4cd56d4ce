#pragma once
// Sharp features and the boundary option given to both sides of a comparison:
// the runtime's MeshFeatures and OpenSubdiv's creasing (bfr_reference), kept
// in step by one call per feature.
#include "bfr_reference.hpp"
#include "stencil_runtime/mesh.hpp"

struct SharpFeatures {
  stencil_runtime::MeshFeatures ours;
  bfr_reference::Creasing osd;
  void crease(int a, int b, float s) {
    ours.edges.push_back({a, b, s});
    osd.crease_pairs.insert(osd.crease_pairs.end(), {a, b});
    osd.crease_sharpness.push_back(s);
  }
  void corner(int v, float s) {
    ours.vertices.push_back({v, s});
    osd.corners.push_back(v);
    osd.corner_sharpness.push_back(s);
  }
  void chaikin() { ours.chaikin = osd.chaikin = true; }
  void boundary(stencil_runtime::BoundaryInterpolation b) {
    ours.boundary = b;
    osd.boundary_corners = b == stencil_runtime::BoundaryInterpolation::EdgeAndCorner;
    osd.boundary_none = b == stencil_runtime::BoundaryInterpolation::None;
  }
  void boundary_none() { boundary(stencil_runtime::BoundaryInterpolation::None); }
  void smooth_triangles() { ours.smooth_triangles = osd.smooth_triangles = true; }
};
