#pragma once
// A parallel loop over faces, edges or vertices with a fixed number of threads.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <cstddef>
#include <memory>

namespace stencil_runtime::detail {

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
