#pragma once
// Fitting a subdivision surface to points (docs/fitting.md): the control
// positions of a fixed control mesh whose exact limit surface comes nearest
// to the points. The unknowns are the control positions; the surface point of
// a sample at (face, u, v) is its stencil row (SurfaceTopology::stencils)
// times them, so each iteration is a sparse linear least-squares problem:
//  - PDM (point distance): |S(P) - X|^2 with S the sample's foot point;
//  - TDM (tangent distance): ((S(P) - X) . N)^2, N the normal at the foot;
//  - SDM (squared distance): the second-order approximation of the squared
//    distance at the foot, (S(P) - X) in the principal frame weighted by
//    d / (d - rho_i) along each principal direction (seed 003, eq. 6),
// plus a smoothing term (lambda / n) sum |P_i - mean of P_i's neighbours|^2
// and a Levenberg-Marquardt term that keeps each step where the model holds.
// After each solve every point's foot is found again by the exact closest
// point (parameter correction).
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "mesh.hpp"
#include "surface_topology.hpp"

namespace stencil_runtime {

enum class FitMethod { PointDistance, TangentDistance, SquaredDistance };
// "pdm", "tdm", "sdm"; parse throws FitError for anything else.
const char* method_name(FitMethod method);
FitMethod parse_fit_method(const std::string& name);

// A failure of a fit's inputs or options.
struct FitError : Error {
  using Error::Error;
};

struct FitIteration {
  int iteration = 0;     // 0: the initial control mesh
  double rms = 0;        // of the points' distances to the surface, over the points' bounding-box diagonal
  double max = 0;        // the largest of them, same unit
  double smoothing = 0;  // lambda used in this iteration
  double damping = 0;    // the Levenberg-Marquardt weight of the accepted step
  int rejected = 0;      // steps tried and rejected (the objective grew) before the accepted one
  double seconds = 0;    // since the fit started
};

struct FitOptions {
  FitMethod method = FitMethod::SquaredDistance;
  int iterations = 20;  // at most
  // lambda of the first iteration (seed 003's schedule: 1e-3, reduced as the
  // fit proceeds); each iteration multiplies it by smoothing_decay, down to
  // smoothing * smoothing_floor. 0: no smoothing term.
  double smoothing = 1e-3;
  double smoothing_decay = 0.5;
  double smoothing_floor = 0.01;
  // Stop once the largest distance is at most this fraction of the diagonal (0: never).
  double max_error = 0;
  // Closest-point tolerance, as a fraction of the diagonal.
  double tolerance = 1e-9;
  int threads = 0;  // 0: all cores
  // Called after each iteration (and once for the initial mesh).
  std::function<void(const FitIteration&)> progress;
};

struct FitResult {
  std::vector<Point> control;        // the fitted control positions, in the control mesh's vertex order
  std::vector<FitIteration> history;  // the initial mesh, then one entry per accepted iteration
  double diagonal = 0;                // of the points' bounding box: the unit of rms and max
};

// The fit from `initial` control positions on `topology` (a quad scheme's:
// closest points are not available for triangle schemes yet). Throws FitError
// for no points, a point or option that is not finite, or a control count
// other than the topology's.
FitResult fit_surface(std::shared_ptr<const SurfaceTopology> topology, const std::vector<Point>& initial,
                      const std::vector<Point>& points, const FitOptions& options);

// One linear least-squares solve at given samples (no parameter correction):
// the control positions minimising (1/m) sum |S(sample_k) - points_k|^2 +
// (smoothing / n) sum |P_i - mean of neighbours|^2. With smoothing 0 and
// enough samples this recovers control points whose surface the samples lie on.
std::vector<Point> fit_at_samples(const SurfaceTopology& topology, const std::vector<RealSample>& samples,
                                  const std::vector<Point>& points, double smoothing);

}  // namespace stencil_runtime
