#include "stencil_runtime/surface_fit.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include "fitting/control_laplacian.hpp"
#include "fitting/error_model.hpp"
#include "fitting/foot_frame.hpp"
#include "fitting/normal_equations.hpp"
#include "mesh/coordinates.hpp"
#include "stencil_runtime/closest_point.hpp"
#include "stencil_runtime/surface.hpp"

namespace stencil_runtime {

using fitting::FactorCache;
using fitting::NormalEquations;

const char* method_name(FitMethod method) {
  switch (method) {
    case FitMethod::PointDistance: return "pdm";
    case FitMethod::TangentDistance: return "tdm";
    case FitMethod::SquaredDistance: return "sdm";
  }
  return "?";
}

FitMethod parse_fit_method(const std::string& name) {
  if (name == "pdm") return FitMethod::PointDistance;
  if (name == "tdm") return FitMethod::TangentDistance;
  if (name == "sdm") return FitMethod::SquaredDistance;
  throw FitError("unknown fitting method " + quoted_excerpt(name) + " (pdm, tdm or sdm)");
}

namespace {

void check_points(const std::vector<Point>& points, const char* what) {
  if (const std::string fault = coordinate_fault(points.data(), points.size(), what); !fault.empty()) throw FitError(fault);
}

// Stencil rows exist at every parameter where the scheme's regular patches are
// polynomial; elsewhere only where the patch's descent reaches a stored grid.
// There a foot moves to the nearest node of the grid 1 / G, G = n d^k, n the
// largest stored rate and d^k = 2^18 (3^11 for sqrt(3), whose steps scale by
// 3): every such node is a stored node after at most k subdivision steps, and
// the move (below 4e-6 / n of a face) changes the model's point only along the
// tangent plane, to first order. The node is an exact fraction (a ternary one
// has no double). On a triangle it stays in u + v <= 1.
Sample grid_sample(const ClosestPoint& foot, std::int64_t grid, bool triangle) {
  const double g = static_cast<double>(grid);
  auto i = static_cast<std::int64_t>(std::llround(foot.u * g)), j = static_cast<std::int64_t>(std::llround(foot.v * g));
  if (triangle && i + j > grid) {  // both rounded up across the long edge: the one rounded up more goes down
    if (static_cast<double>(i) - foot.u * g > static_cast<double>(j) - foot.v * g) --i;
    else --j;
  }
  return {foot.face, ExactParameter{Fraction::make(i, grid), Fraction::make(j, grid)}};
}

double smoothing_energy(const Eigen::SparseMatrix<double>& laplacian, const std::vector<Point>& control) {
  Eigen::MatrixXd p(static_cast<Eigen::Index>(control.size()), 3);
  for (std::size_t i = 0; i < control.size(); ++i)
    for (int c = 0; c < 3; ++c) p(static_cast<Eigen::Index>(i), c) = control[i][c];
  return (laplacian * p).squaredNorm();
}

// The current surface's feet of all points, and their distances' statistics.
struct Feet {
  std::vector<ClosestPoint> feet;
  double mean_square = 0, max = 0;
};

Feet feet_of(const ClosestPointQuery& query, const std::vector<Point>& points) {
  Feet out;
  out.feet = query.find(points);
  for (const ClosestPoint& f : out.feet) {
    out.mean_square += f.distance * f.distance;
    out.max = std::max(out.max, f.distance);
  }
  out.mean_square /= static_cast<double>(points.size());
  return out;
}

// Far above the points' weight, the smoothing term alone (whose null space
// holds every translation) would decide the fit, and its system is singular.
void check_smoothing(double smoothing) {
  if (!(smoothing >= 0) || !(smoothing <= 1000))
    throw FitError("the smoothing weight must be a number from 0 to 1000 (got " + number_text(smoothing) +
                   "; a weight relative to the points': above it the smoothing term alone would decide the fit)");
}

// A control vertex in no face has no part in the surface: no fit can place it
// (the runtime evaluates such meshes, ignoring it, as OpenSubdiv does).
void check_every_vertex_used(const SurfaceTopology& topology) {
  std::vector<char> used(topology.vertex_count(), 0);
  for (int v : topology.face_vertices()) used[static_cast<std::size_t>(v)] = 1;
  const auto it = std::find(used.begin(), used.end(), 0);
  if (it != used.end())
    throw FitError("control vertex " + std::to_string(it - used.begin()) +
                   " (numbered from 0) belongs to no face: it has no part in the surface, so no fit can place it; remove it");
}

}  // namespace

std::vector<Point> fit_at_samples(const SurfaceTopology& topology, const std::vector<RealSample>& samples,
                                  const std::vector<Point>& points, double smoothing) {
  if (samples.empty()) throw FitError("no samples to fit");
  if (samples.size() != points.size())
    throw FitError(std::to_string(samples.size()) + " samples for " + std::to_string(points.size()) + " points");
  check_smoothing(smoothing);
  check_points(points, "point");
  check_every_vertex_used(topology);
  StencilRows rows;
  try {
    rows = topology.stencils(samples);
  } catch (const EvaluationError& e) {  // a sample off the surface: the fit's input, said as the fit's error
    throw FitError(std::string("a sample: ") + e.what());
  }
  const auto laplacian =
      fitting::control_laplacian(topology.vertex_count(), topology.face_sizes(), topology.face_vertices());
  NormalEquations equations(rows, {}, 1.0 / static_cast<double>(points.size()), points, laplacian,
                            smoothing / static_cast<double>(topology.vertex_count()));
  FactorCache cache;
  return equations.solve(0, std::vector<Point>(topology.vertex_count()), cache);
}

FitResult fit_surface(std::shared_ptr<const SurfaceTopology> topology, const std::vector<Point>& initial,
                      const std::vector<Point>& points, const FitOptions& options) {
  if (!topology) throw FitError("no surface topology to fit");
  if (points.empty()) throw FitError("no points to fit");
  if (initial.size() != topology->vertex_count())
    throw FitError(std::to_string(initial.size()) + " control positions for a control mesh of " +
                   std::to_string(topology->vertex_count()) + " vertices");
  check_points(points, "point");
  check_points(initial, "control vertex");
  check_every_vertex_used(*topology);
  if (options.method != FitMethod::PointDistance && options.method != FitMethod::TangentDistance &&
      options.method != FitMethod::SquaredDistance)
    throw FitError("unknown fit method " + std::to_string(static_cast<int>(options.method)) + " (FitMethod has pdm, tdm, sdm)");
  if (options.iterations < 0 || options.iterations > 100000)
    throw FitError("iterations must be 0..100000 (got " + std::to_string(options.iterations) + ")");
  check_smoothing(options.smoothing);
  for (const double x : {options.smoothing_decay, options.smoothing_floor})
    if (!(x >= 0) || !(x <= 1))
      throw FitError("the smoothing's decay and floor are factors from 0 to 1 (got " + number_text(x) + ")");
  if (!(options.max_error >= 0) || !std::isfinite(options.max_error))
    throw FitError("max_error must be finite and >= 0 (got " + number_text(options.max_error) + ")");
  if (!(options.tolerance > 0) || !std::isfinite(options.tolerance))
    throw FitError("the tolerance must be positive and finite (got " + number_text(options.tolerance) + ")");
  if (options.threads < 0 || options.threads > 256)
    throw FitError("threads must be 0 (all cores) to 256 (got " + std::to_string(options.threads) + ")");

  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  FitResult result;
  result.diagonal = box_diagonal(points.data(), points.size());
  if (!(result.diagonal > 0)) throw FitError("the points are all equal: nothing to fit");
  const double m = static_cast<double>(points.size()), n = static_cast<double>(topology->vertex_count());
  const auto laplacian =
      fitting::control_laplacian(topology->vertex_count(), topology->face_sizes(), topology->face_vertices());

  Surface surface(topology, initial);  // the positions are checked above
  ClosestPointOptions query_options;
  query_options.tolerance = options.tolerance * result.diagonal;
  query_options.threads = options.threads;
  std::optional<ClosestPointQuery> searched;
  try {
    searched.emplace(surface, query_options);
  } catch (const EvaluationError& e) {  // e.g. a control mesh collapsed to a point
    throw FitError(std::string("the initial control mesh: ") + e.what());
  }
  ClosestPointQuery& query = *searched;
  // Catmull-Clark's and Loop's regular patches are polynomial: exact second
  // derivatives and exact rows everywhere.
  const bool exact_second = fitting::has_second_derivatives(surface);
  const Tables& tables = topology->tables();
  const bool rows_anywhere = tables.polynomial_regular();
  const bool triangle = tables.family() == SchemeFamily::Triangle;
  const std::int64_t grid = static_cast<std::int64_t>(tables.rates().back()) * (tables.dilation() == 3 ? 177147 : 262144);  // 3^11, 2^18
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);

  std::vector<Point> control = initial;
  Feet current = feet_of(query, points);
  const auto record = [&](int iteration, double lambda, double mu, int rejected) {
    FitIteration it;
    it.iteration = iteration;
    it.rms = std::sqrt(current.mean_square) / result.diagonal;
    it.max = current.max / result.diagonal;
    it.smoothing = lambda, it.damping = mu, it.rejected = rejected;
    it.control_points = topology->vertex_count();
    it.seconds = elapsed();
    result.history.push_back(it);
    if (options.progress) options.progress(it);
  };
  record(0, 0, 0, 0);

  // PDM's model lies above the objective (the foot parameters are fixed), so
  // its undamped steps never increase it; TDM and SDM start damped.
  double mu = options.method == FitMethod::PointDistance ? 0 : 1e-3;
  double lambda = options.smoothing;
  FactorCache factors;  // the symbolic analysis carried from one iteration to the next
  for (int iteration = 1; iteration <= options.iterations; ++iteration) {
    if (options.max_error > 0 && current.max / result.diagonal <= options.max_error) break;
    StencilRows rows;
    if (rows_anywhere) {
      std::vector<RealSample> samples(points.size());
      for (std::size_t k = 0; k < points.size(); ++k) samples[k] = {current.feet[k].face, current.feet[k].u, current.feet[k].v};
      rows = topology->stencils(samples);
    } else {
      std::vector<Sample> samples(points.size());
      for (std::size_t k = 0; k < points.size(); ++k) samples[k] = grid_sample(current.feet[k], grid, triangle);
      rows = topology->stencils(samples);
    }
    std::vector<Eigen::Matrix3d> weights;
    if (options.method != FitMethod::PointDistance) {
      weights.resize(points.size());
      arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points.size(), 64), [&](const auto& range) {
          for (std::size_t k = range.begin(); k != range.end(); ++k) {
            const ClosestPoint& foot = current.feet[k];
            fitting::FootFrame frame;
            if (options.method == FitMethod::SquaredDistance)
              frame = fitting::foot_frame(surface, foot, exact_second, query_options.tolerance);
            weights[k] = fitting::error_weight(options.method, points[k], foot, frame) / m;
          }
        });
      });
    }
    NormalEquations equations(rows, weights, 1 / m, points, laplacian, lambda / n);
    const double objective = current.mean_square + lambda / n * smoothing_energy(laplacian, control);
    int rejected = 0;
    bool accepted = false;
    for (; rejected < 12; ++rejected) {
      std::vector<Point> trial = equations.solve(mu / n, control, factors);
      // A step that throws control points beyond the coordinate limit (or to
      // NaN) is rejected like one that raises the objective: damped further.
      if (coordinate_fault(trial.data(), trial.size()).empty()) {
        surface.set_positions(trial);
        query.update(surface);
        Feet next = feet_of(query, points);
        if (next.mean_square + lambda / n * smoothing_energy(laplacian, trial) <= objective) {
          control = std::move(trial);
          current = std::move(next);
          accepted = true;
          break;
        }
      }
      mu = mu > 0 ? 8 * mu : 1e-6;
    }
    if (!accepted) {  // no damped step lowers the objective: a minimum to the model's accuracy
      surface.set_positions(control);
      query.update(surface);
      break;
    }
    record(iteration, lambda, mu, rejected);
    mu = mu / 4 < 1e-12 ? 0 : mu / 4;
    lambda = std::max(lambda * options.smoothing_decay, options.smoothing * options.smoothing_floor);
  }
  result.control = std::move(control);
  result.factorizations = factors.factorizations(), result.symbolic_analyses = factors.analyses();
  result.face_max_error.assign(topology->face_count(), 0.0);
  for (const ClosestPoint& foot : current.feet)
    result.face_max_error[foot.face] = std::max(result.face_max_error[foot.face], foot.distance);
  return result;
}

}  // namespace stencil_runtime
