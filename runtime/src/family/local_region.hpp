#pragma once
// A region of a mesh, cut out to be subdivided on its own: what refining only
// round semi-sharp features needs (semi_sharp_levels.hpp). A region is a set
// of faces; it is grown by vertex rings (faces sharing a vertex with it) and
// then until it is a manifold, so that the scheme's steps, which need one fan
// of faces round each vertex, can run on it. Its border is a boundary of the
// cut-out mesh: the points the steps make next to it are wrong (they follow
// the boundary rules), which is why a caller keeps a margin of rings.
#include <cstdint>
#include <vector>

#include "mesh/connectivity.hpp"
#include "mesh/sharpness.hpp"

namespace stencil_runtime {

// The faces of each vertex (compressed rows: faces of v are
// faces[offsets[v]] .. faces[offsets[v + 1] - 1]).
struct VertexFaces {
  std::vector<std::size_t> offsets;
  std::vector<std::uint32_t> faces;
  explicit VertexFaces(const Connectivity& mesh);
};

// Marks (per face) grown by `rings` vertex rings, then by every face round a
// vertex where the marked faces would form more than one fan (a pinch), until
// there is none. `mesh` is a manifold; `faces` has one flag per face.
std::vector<char> grow_region(const Connectivity& mesh, const VertexFaces& incidence, std::vector<char> faces, int rings);

// The marked faces as a mesh of their own: its faces in the order of the
// originals, its vertices numbered in order of first use.
struct SubMesh {
  Connectivity mesh;
  std::vector<std::uint32_t> faces;     // its face -> the mesh's face
  std::vector<std::uint32_t> vertices;  // its vertex -> the mesh's vertex
};
SubMesh cut_out(const Connectivity& mesh, const std::vector<char>& region);

// The sharpness of `parent`'s features that lie on the sub-mesh, in its numbers.
LevelSharpness restrict_sharpness(const LevelSharpness& parent, const SubMesh& sub);

// Per vertex of `mesh`: whether a semi-sharp feature is at it (its own
// sharpness, or that of an edge at it, strictly between 0 and infinite).
// A face with no such vertex has a stationary limit surface: the creasing
// rules change only the points of such vertices and of such edges.
std::vector<char> semi_sharp_vertices(const Connectivity& mesh, const LevelSharpness& sharpness);
// Per face: whether a corner of it is such a vertex (faces of any size).
std::vector<char> semi_sharp_faces(const Connectivity& mesh, const LevelSharpness& sharpness);

}  // namespace stencil_runtime
