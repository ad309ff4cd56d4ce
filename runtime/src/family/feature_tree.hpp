#pragma once
// The tree a family hangs below its prepared faces refined round semi-sharp
// features (semi_sharp_levels.hpp): nodes numbered after the prepared faces,
// level by level; an inner node's four children (the scheme's split of it)
// are consecutive. What the quad and triangle families' trees share.
#include <cstdint>
#include <string>
#include <vector>

#include "family/refinement.hpp"
#include "family/semi_sharp_levels.hpp"
#include "family/sharp_cut.hpp"
#include "family/sub_domain.hpp"
#include "mesh/polygon_links.hpp"
#include "stencil_runtime/error.hpp"

namespace stencil_runtime {

struct FeatureTree {
  static constexpr std::uint32_t kLeaf = UINT32_MAX;
  std::vector<std::uint32_t> children;  // by node: its first child, or kLeaf; empty: no tree
  std::vector<std::uint32_t> parent;    // by node below the prepared faces: the node it is a child of

  bool refined(std::size_t node) const { return !children.empty() && children[node] != kLeaf; }
  std::size_t child(std::size_t node, int c) const { return children[node] + static_cast<std::size_t>(c); }
  // Which child of its parent a node below the prepared faces is.
  int which(std::size_t node) const { return static_cast<int>(node - children[parent[node]]); }

  // The prepared faces, all leaves so far.
  void start(std::size_t prepared_faces) {
    children.assign(prepared_faces, kLeaf);
    parent.assign(prepared_faces, kLeaf);
  }
  // A level's faces as nodes [base, base + its faces): its exact faces become
  // the children of the nodes they split, those of the level before (whose
  // first node is before_base, the prepared faces' 0).
  void add_level(const SemiSharpLevel& level, std::size_t base, std::size_t before_base) {
    const std::size_t faces = level.mesh.face_count();
    if (base + faces >= kLeaf) throw MeshError("the refinement round the semi-sharp features makes more than 2^32 faces");
    children.resize(base + faces, kLeaf);
    parent.resize(base + faces, kLeaf);
    for (std::size_t f = 0; f < faces; f += 4) {
      if (!level.exact[f]) continue;  // a child of the region's margin: no node of the tree
      const std::size_t p = before_base + level.parent[f];
      children[p] = static_cast<std::uint32_t>(base + f);
      for (std::size_t c = 0; c < 4; ++c) parent[base + f + c] = static_cast<std::uint32_t>(p);
    }
  }
};

// The levels of `r` hung below a family's prepared faces (patches[0 ..
// prepared faces)): the tree's nodes, each level's points appended to
// `refinement` (from the level before's), and each exact face's patch,
// gathered as on the prepared mesh: on the level cut along its infinitely
// sharp edges, the cut's copies and then the phantoms after its vertices.
// `gather(cut, no_surface, exact, level_patches)` fills level_patches[f] for
// every face f marked in `exact` with its patch over the cut level's vertices
// (throwing where there is none) and returns its phantom points' rows
// (numbered from cut.mesh.vertex_count on). An inner node's patch is only the
// hull of the surface below it (closest points): unturned, so that its
// sub-patch coordinates are the node's own, as its children's are.
// Patch: points (prepared vertices) and rotation.
template <class Patch, class Gather>
void hang_levels(SemiSharpRefinement& r, bool boundary_corners, bool no_boundary_surface, Refinement& refinement,
                 FeatureTree& tree, std::vector<Patch>& patches, Gather gather) {
  const std::size_t prepared_faces = r.refined.size();
  tree.start(prepared_faces);
  for (std::size_t f = 0; f < prepared_faces; ++f)
    if (r.refined[f]) patches[f].rotation = 0;
  std::size_t before_base = 0, before_vertices = 0;  // the level before: its first node and prepared vertex
  for (SemiSharpLevel& level : r.levels) {
    const std::size_t base = patches.size(), faces = level.mesh.face_count();
    tree.add_level(level, base, before_base);
    patches.resize(base + faces);
    const std::size_t offset = refinement.prepared_vertices();
    refinement.append(std::move(level.step), before_vertices);
    const PolygonLinks links = link_polygons(level.mesh, true);
    const SharpCut cut = cut_along_sharp_edges(level.mesh, links, level.sharpness, boundary_corners);
    const std::vector<char> no_surface = no_surface_vertices(no_boundary_surface, level.mesh, links, level.sharpness, cut);
    if (cut.cut) refinement.append(rows_over(level.mesh.vertex_count, copy_rows(cut, level.mesh.vertex_count)), offset);
    std::vector<Patch> level_patches(faces);
    const std::vector<std::vector<std::pair<int, double>>> phantoms = gather(cut, no_surface, level.exact, level_patches);
    for (std::size_t f = 0; f < faces; ++f) {
      if (!level.exact[f]) continue;  // a child of the region's margin: no node
      Patch& p = level_patches[f];
      for (int& i : p.points) i += static_cast<int>(offset);
      if (level.refined[f]) p.rotation = 0;  // a hull, as above
      patches[base + f] = std::move(p);
    }
    if (!phantoms.empty()) refinement.append(rows_over(cut.mesh.vertex_count, phantoms), offset);
    before_base = base;
    before_vertices = offset;
  }
  if (refinement.prepared_vertices() > static_cast<std::size_t>(INT32_MAX))
    throw MeshError("the refinement round the semi-sharp features makes more than 2^31 points");
}

// The domain of a node's child as seen through its parent's domain: `map`
// takes the child's own coordinates (X, Y) to the parent node's (u, v).
template <class Map>
SubDomain mapped_domain(const SubDomain& parent, Map map) {
  const auto at = [&](double X, double Y) {
    const auto uv = map(X, Y);
    return parent.at(uv[0], uv[1]);
  };
  SubDomain out = parent;
  const auto o = at(0, 0), x = at(1, 0), y = at(0, 1);
  out.origin = o;
  out.x_axis = {x[0] - o[0], x[1] - o[1]};
  out.y_axis = {y[0] - o[0], y[1] - o[1]};
  return out;
}

}  // namespace stencil_runtime
