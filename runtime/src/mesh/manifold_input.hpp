#pragma once
// Meshes as modellers save them, made into what the families subdivide: a
// vertex in no face is left out (it has no part in the surface), and a vertex
// whose faces form several fans (pieces of surface that meet only there,
// OpenSubdiv's non-manifold vertex) becomes one vertex per fan. OpenSubdiv
// makes such a vertex infinitely sharp, so each copy is a corner (or, for a
// closed fan, a cone point); the fans' own boundary edges are boundaries as
// anywhere else. An edge in more than two faces, or used twice in one
// direction (a face flipped against its neighbour), is non-manifold too:
// OpenSubdiv makes it infinitely sharp and its vertices sharp, except a
// vertex between two such edges with more faces than edges (a fin along a
// crease), which follows the crease. Here its faces stop sharing it (each
// copy tagged infinitely sharp), and the fans that leaves at its vertices
// become copies as above. The families work on the result; a first refinement step
// gathers its vertices from the control vertices, so positions, stencil rows
// and every other interface keep the caller's numbering.
#include <cstddef>
#include <string>
#include <vector>

#include "connectivity.hpp"
#include "stencil_runtime/mesh.hpp"

namespace stencil_runtime {

struct ManifoldInput {
  bool changed = false;            // false: the mesh is used as given (and the rest is empty)
  std::vector<int> face_vertices;  // over the new vertices, face by face as given
  std::vector<int> origin;         // per new vertex: the control vertex it is
  MeshFeatures features;           // the tags on the new vertices, the copies of a non-manifold vertex sharpened
};

// Throws link_polygons' MeshError (Fans::Any) for a mesh that fails its
// checks: sizes, indices, a face that repeats a vertex, a valence out of
// range. The features' tags must name
// edges and vertices of the mesh (LevelSharpness::of checks that first).
ManifoldInput make_manifold(const Connectivity& mesh, const MeshFeatures& features);

// `message` with every "vertex K" naming the control vertex that new vertex K is.
std::string name_control_vertices(const std::string& message, const std::vector<int>& origin);

}  // namespace stencil_runtime
