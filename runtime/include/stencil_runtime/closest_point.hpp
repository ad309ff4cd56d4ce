#pragma once
// Closest points on, and distances to, the exact limit surface (docs/runtime.md,
// "Closest points"). A ClosestPointQuery is built once for a surface's current
// positions (update() after set_positions) and answers queries in parallel.
// For a point q it returns the original face and (u, v) of the nearest surface
// point, the point, the distance, the unit normal there and how far the
// reported distance may be above the true one. The method is a
// branch-and-bound over the scheme's own subdivision of each patch, whose
// control points bound the surface (all weights non-negative), so no part of
// the surface closer by more than the tolerance can be missed. Faces tagged
// as holes (SurfaceTopology) have no surface and are never answered.
#include <cstddef>
#include <functional>
#include <limits>
#include <memory>
#include <vector>

#include "mesh.hpp"
#include "surface.hpp"

namespace stencil_runtime {

struct ClosestPointOptions {
  // The largest amount by which a reported distance may exceed the true one
  // (absolute); 0: 1e-9 of the diagonal of the control points' bounding box
  // (Surface::control_diagonal; the prepared points' where that is smaller).
  // At least 1e-14 of the prepared points' diagonal (a smaller one is raised
  // to it: doubles resolve no finer); tolerance() says what is used.
  double tolerance = 0;
  // Points farther than this from the surface come back with found == false.
  double max_distance = std::numeric_limits<double>::infinity();
  int threads = 0;  // batch queries: 0 for all cores
  // Batch queries: called about once a second with how many of how many are
  // done, from one query thread at a time (for a long run's progress lines).
  // It must not start parallel work itself (a query thread calls it).
  std::function<void(std::size_t done, std::size_t total)> progress;
};

struct ClosestPoint {
  bool found = false;
  std::size_t face = 0;  // the original face
  double u = 0, v = 0;   // its parameter there (FaceDomain)
  Point point{0, 0, 0};
  double distance = 0;
  // Signed: negative inside a closed, consistently oriented (outward) surface.
  // On a surface with holes it is only the side of the nearest point's
  // tangent plane (there is no inside): stencildist refuses --signed there.
  double signed_distance = 0;
  Point normal{0, 0, 0};  // unit, the surface's orientation (outward for outward-facing faces)
  // The reported distance is at most this much above the true one (the
  // branch-and-bound's remaining gap plus the evaluation's bound).
  double accuracy = 0;
};

class ClosestPointQuery {
 public:
  // Copies the surface's prepared positions and shares its topology. Throws
  // EvaluationError for a surface without positions or a scheme whose tables
  // give no bounds (negative weights).
  explicit ClosestPointQuery(const Surface& surface, const ClosestPointOptions& options = {});
  ~ClosestPointQuery();
  ClosestPointQuery(const ClosestPointQuery&) = delete;
  ClosestPointQuery& operator=(const ClosestPointQuery&) = delete;

  // New positions of the same topology (after Surface::set_positions): the
  // spatial index is refitted, nothing else rebuilt.
  void update(const Surface& surface);

  // Throws EvaluationError for a query point with a coordinate that is not
  // finite or beyond +-limits::kMaxCoordinate (the control points' limit, so
  // that squared distances stay far from overflow).
  ClosestPoint find(const Point& q) const;
  // In parallel, in input order; an EvaluationError names the query (its index and point).
  std::vector<ClosestPoint> find(const std::vector<Point>& queries) const;

  double tolerance() const;
  // Memory the query structure holds (bytes) and the time its last build took (seconds).
  std::size_t memory_bytes() const;
  double build_seconds() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace stencil_runtime
