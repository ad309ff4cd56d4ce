#include <algorithm>
#include <numeric>
#include <string>

#include "stencil_runtime/surface_fit.hpp"

namespace stencil_runtime {

AdaptiveFit fit_adaptively(const std::shared_ptr<const Tables>& tables, const Mesh& mesh,
                           const std::vector<Point>& points, const FitOptions& options,
                           std::size_t max_control_points) {
  if (!tables) throw FitError("adaptive refinement needs tables (a null pointer was given)");
  if (!(options.max_error > 0)) throw FitError("adaptive refinement needs a max error above 0 (the split threshold)");
  if (max_control_points < mesh.vertex_count())
    throw FitError("the control-point budget " + std::to_string(max_control_points) + " is below the control mesh's " +
                   std::to_string(mesh.vertex_count()) + " vertices");
  for (std::size_t f = 0; f < mesh.face_count(); ++f)
    if (mesh.face_sizes[f] != 3)
      throw FitError("adaptive refinement splits triangles: face " + std::to_string(f) + " of the control mesh has " +
                     std::to_string(mesh.face_sizes[f]) +
                     " corners (give a triangle control mesh, or let --control-points make one)");
  // The splits below make a new mesh from the old one's faces alone: a tag on
  // an edge, a vertex or a face would be dropped or left naming the wrong
  // elements, and a fit that ignored it would answer for another surface than
  // the file asks for. The options that apply to the whole mesh
  // (interpolateboundary, creasemethod, smoothtriangles) go with every round.
  {
    const MeshTags& t = mesh.tags;
    long line = 0;
    const char* what = nullptr;
    for (const auto& c : t.creases)
      if (c.sharpness > 0 && !what) what = "a crease", line = c.line;
    for (const auto& c : t.corners)
      if (c.sharpness > 0 && !what) what = "a corner", line = c.line;
    if (!t.holes.empty() && !what) what = "a hole", line = t.holes.front().line;
    if (what)
      throw FitError((mesh.source.empty() ? std::string("the control mesh") : mesh.source) +
                     (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " + what +
                     " tag; adaptive refinement does not carry crease, corner or hole tags through its splits yet "
                     "(fit without it, or remove the tags)");
  }
  AdaptiveFit out;
  out.mesh = mesh;
  double elapsed = 0;
  for (;;) {
    const auto topology = SurfaceTopology::create(tables, out.mesh);  // with the whole-mesh options
    FitOptions round = options;
    const auto offset = out.fit.history.empty() ? 0 : out.fit.history.back().iteration;
    round.progress = [&](const FitIteration& it) {
      if (!options.progress || (it.iteration == 0 && offset > 0)) return;
      FitIteration shifted = it;
      shifted.iteration += offset, shifted.seconds += elapsed;
      options.progress(shifted);
    };
    FitResult fit = fit_surface(topology, out.mesh.positions, points, round);
    for (FitIteration& it : fit.history) it.iteration += offset, it.seconds += elapsed;
    elapsed = fit.history.back().seconds;
    // The histories join: a round's iteration 0 repeats the previous round's last state on a refined mesh.
    if (!out.fit.history.empty()) fit.history.erase(fit.history.begin());
    fit.history.insert(fit.history.begin(), out.fit.history.begin(), out.fit.history.end());
    out.fit = std::move(fit);
    out.mesh.positions = out.fit.control;
    // Faces above half the target split: those just below it would only need the next round.
    const double threshold = 0.5 * options.max_error * out.fit.diagonal;
    if (out.fit.history.back().max <= options.max_error) {
      out.stopped = "the max error is met";
      break;
    }
    if (out.mesh.vertex_count() >= max_control_points) {
      out.stopped = "the control-point budget is reached";
      break;
    }
    // The faces above the threshold, worst first; each split adds about 1.5 vertices (three shared midpoints).
    std::vector<std::size_t> order(out.mesh.face_count());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return out.fit.face_max_error[a] > out.fit.face_max_error[b];
    });
    const std::size_t room = max_control_points - out.mesh.vertex_count();
    std::size_t count = 0;
    while (count < order.size() && out.fit.face_max_error[order[count]] > threshold && 3 * (count + 1) <= 2 * room) ++count;
    if (count == 0) {
      out.stopped = out.fit.face_max_error[order[0]] > threshold ? "the control-point budget has no room for a split"
                                                                 : "no face is above half the max error";
      break;
    }
    // The red-green closure adds vertices beyond the split faces' own: where
    // it overshoots the budget, fewer (the worst) faces, halved until it fits.
    const std::vector<int> valences = tables->valences();
    Mesh refined;
    for (;;) {
      std::vector<bool> marked(out.mesh.face_count(), false);
      for (std::size_t k = 0; k < count; ++k) marked[order[k]] = true;
      refined = refine_red_green(out.mesh, marked, *std::max_element(valences.begin(), valences.end()));
      if (refined.vertex_count() <= max_control_points || count == 1) break;
      count /= 2;
    }
    if (refined.vertex_count() > max_control_points) {
      out.stopped = "the control-point budget has no room for a split with its closure";
      break;
    }
    refined.tags.boundary = mesh.tags.boundary;
    refined.tags.chaikin_creases = mesh.tags.chaikin_creases;
    refined.tags.smooth_triangles = mesh.tags.smooth_triangles;
    refined.source = mesh.source;
    out.mesh = std::move(refined);
    ++out.rounds;
  }
  return out;
}

}  // namespace stencil_runtime
