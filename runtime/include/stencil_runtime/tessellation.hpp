#pragma once
// Watertight adaptive tessellation (the paper's section 4.4), planned once and
// evaluated every frame. One limit point per grid cell of every prepared face
// at that face's own rate (quads: the cell centres; triangles: the centres of
// the small triangles), each from its exact stencil; polygons between them
// inside a face, a zipper along every mesh edge and a polygon round every mesh
// vertex. The result is a closed, consistently oriented 2-manifold for every
// mix of rates; faces tagged as holes (SurfaceTopology) get no points and no
// polygons, and their rims become the output's boundary loops, one per hole
// (the surface stays a consistently oriented 2-manifold with boundary).
//
// The plan holds everything that does not depend on positions (rates, counts,
// connectivity); evaluate() fills the positions of one frame.
#include <array>
#include <cstddef>
#include <memory>
#include <vector>

#include "mesh.hpp"
#include "surface.hpp"
#include "surface_topology.hpp"

namespace stencil_runtime {

struct TessellationOptions {
  int threads = 0;  // 0: all cores
};

class TessellationPlan {
 public:
  // `rates`: one per original face (>= 1). A face refined by the preparation
  // covers prepared faces s times smaller across per step; they get
  // ceil(rate / s), rounded up to a stored rate (the largest stored rate where
  // none is large enough: see largest_wanted_rate()). Throws EvaluationError
  // for a wrong count or a rate outside 1..limits::kMaxRate.
  TessellationPlan(std::shared_ptr<const SurfaceTopology> topology, const std::vector<int>& rates,
                   const TessellationOptions& options = {});
  ~TessellationPlan();
  TessellationPlan(TessellationPlan&&) noexcept;
  TessellationPlan& operator=(TessellationPlan&&) noexcept;

  // A plan moved from holds no plan: every call on it throws EvaluationError
  // (assigning a plan to it makes it usable again).
  const SurfaceTopology& topology() const;
  // Per prepared face, as used (stored rates).
  const std::vector<int>& prepared_rates() const;
  // The largest prepared rate before rounding to a stored one (above the
  // tables' largest rate when they could not give what was asked for).
  int largest_wanted_rate() const;

  std::size_t point_count() const;
  const std::vector<std::array<int, 4>>& quads() const;
  const std::vector<std::array<int, 3>>& triangles() const;
  std::size_t triangle_count() const { return triangles().size() + 2 * quads().size(); }

  // A soup with the plan's polygons and room for its positions (made once).
  PolygonSoup make_soup() const;
  // The positions of one frame into `positions` (point_count() entries, e.g.
  // make_soup()'s). Throws EvaluationError when the surface has no positions
  // or another topology, or `positions` is null.
  void evaluate(const Surface& surface, std::array<float, 3>* positions) const;
  // The unit normals at the same points (du x dv, outward for counter-clockwise
  // faces; docs/runtime.md "Derivatives and normals"), e.g. into make_soup()'s
  // normals resized to point_count().
  void evaluate_normals(const Surface& surface, std::array<float, 3>* normals) const;
  // Both in one pass over the faces (cheaper than the two calls above), or
  // the positions alone where `normals` is null.
  void evaluate(const Surface& surface, std::array<float, 3>* positions, std::array<float, 3>* normals) const;

 private:
  struct Impl;
  const Impl& planned() const;  // *impl_, or EvaluationError for a plan moved from
  std::shared_ptr<const SurfaceTopology> topology_;
  std::unique_ptr<Impl> impl_;
};

// Plan and evaluate in one call (with the unit normals when `normals`).
PolygonSoup tessellate(const Surface& surface, const std::vector<int>& rates, const TessellationOptions& options = {},
                       bool normals = false);

}  // namespace stencil_runtime
