#pragma once
// Pieces shared by the quad and the triangle tessellations: the zipper between
// two rows of limit points along a mesh edge, and the parallel loop over
// faces, edges and vertices.
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <cstddef>
#include <memory>

namespace stencil_runtime::detail {

// The zipper between two rows along one edge, both given in the edge's
// direction: A (na points) on the left, B (nb points) on the right. Equal rows
// give na - 1 quads quad(a, b); others na + nb - 2 triangles tri(a, b, advance_a).
template <class EmitQuad, class EmitTri>
void zipper(int na, int nb, const EmitQuad& quad, const EmitTri& tri) {
  if (na == nb) {
    for (int t = 0; t + 1 < na; ++t) quad(t, t);
    return;
  }
  int a = 0, b = 0;
  while (a + 1 < na || b + 1 < nb) {
    // Advance the row whose next point comes first along the edge:
    // compare (a + 1.5)/na with (b + 1.5)/nb exactly.
    const bool advance_a = b + 1 >= nb || (a + 1 < na && (2 * a + 3) * nb <= (2 * b + 3) * na);
    tri(a, b, advance_a);
    if (advance_a) ++a;
    else ++b;
  }
}

// Runs body(begin, end) over [0, count): in parallel on `threads` threads for
// large jobs, as one plain call otherwise (task scheduling would cost more
// than it saves).
class RangeRunner {
 public:
  RangeRunner(int threads, std::size_t work) {
    const int t = threads > 0 ? threads : tbb::this_task_arena::max_concurrency();
    if (t > 1 && work >= 4096) arena_ = std::make_unique<tbb::task_arena>(t);
  }
  template <class Body>
  void operator()(std::size_t count, const Body& body) const {
    if (!arena_) {
      body(std::size_t(0), count);
      return;
    }
    arena_->execute([&] {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count),
                        [&](const tbb::blocked_range<std::size_t>& r) { body(r.begin(), r.end()); });
    });
  }

 private:
  std::unique_ptr<tbb::task_arena> arena_;
};

}  // namespace stencil_runtime::detail
