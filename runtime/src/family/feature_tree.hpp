#pragma once
// The tree a family hangs below its prepared faces refined round semi-sharp
// features (semi_sharp_levels.hpp): nodes numbered after the prepared faces,
// level by level; an inner node's four children (the scheme's split of it)
// are consecutive. What the quad and triangle families' trees share.
#include <cstdint>
#include <string>
#include <vector>

#include "family/semi_sharp_levels.hpp"
#include "family/sub_domain.hpp"
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
