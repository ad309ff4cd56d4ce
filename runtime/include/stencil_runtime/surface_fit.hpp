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
#include "tables.hpp"

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
  std::size_t control_points = 0;  // of the control mesh fitted in this iteration
  double seconds = 0;    // since the fit started
};

struct FitOptions {
  FitMethod method = FitMethod::SquaredDistance;
  int iterations = 20;  // at most
  // lambda of the first iteration (seed 003's schedule: 1e-3, reduced as the
  // fit proceeds); each iteration multiplies it by smoothing_decay, down to
  // smoothing * smoothing_floor. 0: no smoothing term. smoothing is at most
  // 1000 (above, the smoothing term alone would decide the fit), the decay
  // and the floor are factors in 0..1.
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
  // Per control-mesh face, the largest distance of a point whose foot lies on
  // it, for the final surface (absolute; 0 where no foot lies).
  std::vector<double> face_max_error;
  // The sparse Cholesky's work: numeric factorisations, and the symbolic
  // analyses among them (the rest reused the previous analysis: the warm start).
  int factorizations = 0, symbolic_analyses = 0;
};

// The fit from `initial` control positions on `topology` (any scheme: a
// triangle scheme needs a triangle control mesh). Throws FitError
// for no points, a point or initial position that is not finite or beyond
// limits::kMaxCoordinate, an option outside its range (FitOptions), a control
// count other than the topology's, or a control mesh the closest-point query
// refuses (e.g. collapsed to a point). A step that would throw control points
// beyond the coordinate limit is rejected and damped, like one that raises
// the objective.
FitResult fit_surface(std::shared_ptr<const SurfaceTopology> topology, const std::vector<Point>& initial,
                      const std::vector<Point>& points, const FitOptions& options);

// Red-green refinement of a triangle control mesh (seed 003, section II-F):
// the marked triangles split 1-to-4, a triangle with two or more split edges
// split too (repeated until none is left), a triangle with one split edge
// bisected towards its opposite corner (green), so that no T-vertex remains;
// where a green bisection would raise a vertex's valence above max_valence
// the triangle splits red instead.
// New vertices sit at their edges' midpoints and follow the old ones; the
// orientation is kept. Throws FitError for a face that is not a triangle, an
// index naming no vertex, a mark count other than the face count, or a
// max_valence outside 3..limits::kMaxValence.
Mesh refine_red_green(const Mesh& mesh, const std::vector<bool>& marked, int max_valence);

// Adaptive fitting (seeds 002, 003): fit_surface on `mesh` (a triangle mesh),
// then, while the max error is above options.max_error (which must be > 0)
// and the control points are below max_control_points: split the faces whose
// points are farther than options.max_error (the worst first, as many as the
// budget allows; red-green, valences kept within the tables') and fit again
// from the refined mesh. Returns the
// last mesh with the fitted positions and the iterations of every round.
// Throws FitError for a budget below the mesh's vertex count, and for a mesh
// with crease, corner or hole tags, which the splits do not carry yet (the
// whole-mesh options, such as interpolateboundary, go with every round).
struct AdaptiveFit {
  Mesh mesh;
  FitResult fit;
  int rounds = 0;
  std::string stopped;  // why the refinement stopped: the max error met, or the budget
};
AdaptiveFit fit_adaptively(const std::shared_ptr<const Tables>& tables, const Mesh& mesh,
                           const std::vector<Point>& points, const FitOptions& options,
                           std::size_t max_control_points);

// One linear least-squares solve at given samples (no parameter correction):
// the control positions minimising (1/m) sum |S(sample_k) - points_k|^2 +
// (smoothing / n) sum |P_i - mean of neighbours|^2. With smoothing 0 and
// enough samples this recovers control points whose surface the samples lie on.
// Throws FitError for no samples, a count other than the points', a point
// that is not finite or beyond limits::kMaxCoordinate, a sample off the
// surface (naming it), or smoothing outside 0..1000.
std::vector<Point> fit_at_samples(const SurfaceTopology& topology, const std::vector<RealSample>& samples,
                                  const std::vector<Point>& points, double smoothing);

}  // namespace stencil_runtime
