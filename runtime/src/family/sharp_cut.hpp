#pragma once
// Infinitely sharp creases as boundaries. Across an edge of infinite sharpness
// (OpenSubdiv's >= 10) the two sides of the surface are independent: each side
// is the surface of a mesh with a boundary there, its vertices on the crease
// following the crease curve (two sharp edges) or staying put (a corner: three
// or more, or a sharp vertex). Cutting the mesh along those edges therefore
// turns every face at a crease into a face at a boundary, whose patches the
// boundary machinery already has (boundary sectors, regular boundary patches
// with phantom points): each vertex on such edges becomes one copy per sector
// of faces between its sharp edges. The subdivision steps still run on the
// uncut mesh (with OpenSubdiv's creasing rules); only the patches are gathered
// on the cut one, and tessellations keep the uncut adjacency, so that they are
// watertight across creases.
//
// The same pass tells, for every vertex on a boundary of the cut mesh (a real
// boundary or a crease), whether it is a corner: Sdc's corner rule, counting
// boundary edges as infinitely sharp and, with edge-and-corner interpolation,
// a real boundary vertex in one face as a sharp vertex.
#include <utility>
#include <vector>

#include "mesh/connectivity.hpp"
#include "mesh/polygon_links.hpp"
#include "mesh/sharpness.hpp"
#include "tables/patch_kind.hpp"

namespace stencil_runtime {

struct SharpCut {
  Connectivity mesh;             // the same faces; vertices split along infinitely sharp edges
  std::vector<int> origin;       // per vertex of `mesh`: the vertex of the uncut mesh it copies (itself for the first copy)
  std::vector<SectorRule> rule;  // per vertex of `mesh`: crease (or none inside), corner, dart, cone (inside)
  bool cut = false;              // whether any vertex was split
};

// A dart or a corner: the end of an infinitely sharp crease's slit, which the
// cut puts on the cut mesh's boundary. Where the crease is one edge between
// two such vertices nothing is cut (no vertex has two sharp edges): both stay
// inside until a step splits the edge, so a mesh with one is not isolated yet,
// and its sector's tables are needed all the same.
inline bool ends_slit(SectorRule rule) { return rule == SectorRule::Dart || rule == SectorRule::Corner; }
inline bool slit_end_inside(SectorRule rule, bool on_cut_boundary) { return ends_slit(rule) && !on_cut_boundary; }

// `links`: of `mesh`. A crease that ends inside the mesh (a vertex on one such
// edge, a dart) leaves its end one vertex, in all its faces, on the boundary
// of the cut mesh (the slit), with the dart rule. An infinitely sharp vertex
// inside the mesh on no infinitely sharp edge (a cone point) stays inside the
// cut mesh, with the cone rule.
SharpCut cut_along_sharp_edges(const Connectivity& mesh, const PolygonLinks& links, const LevelSharpness& sharpness,
                               bool edge_and_corner);

// The rows of the cut mesh's extra vertices (copies of those on infinitely
// sharp edges, after the `uncut` vertices), each its vertex of the uncut mesh.
inline std::vector<std::vector<std::pair<int, double>>> copy_rows(const SharpCut& cut, std::size_t uncut) {
  std::vector<std::vector<std::pair<int, double>>> out;
  for (std::size_t v = uncut; v < cut.mesh.vertex_count; ++v) out.push_back({{cut.origin[v], 1.0}});
  return out;
}

// With boundary interpolation `none`, per vertex of a mesh (`links` over
// `mesh`): whether the faces at it have no surface. OpenSubdiv (Far's
// makeBoundaryFacesHoles) takes the surface away from the faces at a boundary
// vertex unless every boundary edge there is tagged infinitely sharp; the
// tags' sharpness carries over to the edges' children, so the same test holds
// at every level of the preparation.
std::vector<char> surfaceless_vertices(const Connectivity& mesh, const PolygonLinks& links, const LevelSharpness& sharpness);

// The same per vertex of `cut` (each copy as the vertex it copies, `uncut`
// its mesh, `uncut_links` its links); empty without `none`.
inline std::vector<char> no_surface_vertices(bool no_boundary_surface, const Connectivity& uncut, const PolygonLinks& uncut_links,
                                             const LevelSharpness& sharpness, const SharpCut& cut) {
  std::vector<char> out;
  if (!no_boundary_surface) return out;
  const std::vector<char> own = surfaceless_vertices(uncut, uncut_links, sharpness);
  out.resize(cut.mesh.vertex_count);
  for (std::size_t v = 0; v < out.size(); ++v) out[v] = own[static_cast<std::size_t>(cut.origin[v])];
  return out;
}

}  // namespace stencil_runtime
