#pragma once
// Watertight adaptive tessellation (the paper's section 4.4): one limit point
// per grid cell of every face at that face's own rate (the cell centres,
// exact-stencil evaluated once each), quads between them inside a face, a
// zipper of triangles (quads where the rows line up) along every mesh edge,
// and one polygon around every mesh vertex. The result is a closed,
// consistently oriented 2-manifold for every mix of rates.
#include <vector>

#include "limit_surface.hpp"
#include "mesh.hpp"

namespace stencil_runtime {

struct TessellationOptions {
  int threads = 0;  // 0: all
};

// `rates[f]` for every face of the *prepared* mesh; each must be in the tables.
PolygonSoup tessellate(const LimitSurface& surface, const std::vector<int>& rates, const TessellationOptions& options = {});

// The same into `out`, reusing its storage: repeated tessellations (animation,
// changing view) then allocate nothing once the arrays are large enough.
void tessellate_into(const LimitSurface& surface, const std::vector<int>& rates, PolygonSoup& out,
                     const TessellationOptions& options = {});

// Rates of the prepared mesh from rates of the original faces: a face refined
// s times covers 4^s prepared faces of half the size per step, which get
// ceil(rate / 2^s) (at least 1), rounded up to a rate the tables hold.
std::vector<int> prepared_rates(const PreparedMesh& prepared, const std::vector<int>& original_rates);
inline std::vector<int> prepared_rates(const LimitSurface& surface, const std::vector<int>& original_rates) {
  return prepared_rates(surface.prepared(), original_rates);
}

// The smallest of the tables' rates (ascending) that is >= wanted (the largest if none is).
int table_rate_at_least(const std::vector<int>& table_rates, int wanted);

}  // namespace stencil_runtime
