#pragma once
// Watertight adaptive tessellation of a triangle mesh (the dual of the
// quad tessellation in tessellation.hpp): one limit point at the centre of
// every small triangle of each face's grid at that face's own rate (n^2 points
// per face, exact-stencil evaluated once each); inside a face, the hexagon of
// centres around every interior grid node (two quads) and, along each edge,
// the triangle of centres around every boundary node; a zipper of triangles
// (quads where the rows line up) between the rows of centres of two faces
// along every mesh edge; one polygon around every mesh vertex. The result is a
// closed, consistently oriented 2-manifold for every mix of rates.
#include <vector>

#include "tessellation.hpp"
#include "triangle_surface.hpp"

namespace stencil_runtime {

inline std::vector<int> prepared_rates(const TriangleSurface& surface, const std::vector<int>& original_rates) {
  return prepared_rates(surface.prepared(), original_rates);
}

// `rates[f]` for every face of the *prepared* mesh; each must be in the tables.
PolygonSoup tessellate(const TriangleSurface& surface, const std::vector<int>& rates, const TessellationOptions& options = {});
void tessellate_into(const TriangleSurface& surface, const std::vector<int>& rates, PolygonSoup& out,
                     const TessellationOptions& options = {});

}  // namespace stencil_runtime
