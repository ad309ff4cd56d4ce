// stencilfit: fits the control positions of a control mesh so that its exact
// limit surface approximates a set of points (PDM, TDM or SDM with parameter
// correction by exact closest points; docs/fitting.md). The control mesh is
// given, or made from the points (CGAL reconstruction and simplification).
#include <iostream>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "convergence_plot.hpp"
#include "points_file.hpp"
#include "stencil_runtime/error.hpp"
#include "stencil_runtime/mesh_io.hpp"
#include "stencil_reconstruction/initial_mesh.hpp"
#include "stencil_runtime/surface_fit.hpp"
#include "tool_support.hpp"

namespace {

using namespace stencil_runtime;

nlohmann::json report_of(const FitResult& fit, const FitOptions& options, const std::string& tables,
                         const std::string& points, std::size_t point_count, const Mesh& mesh) {
  nlohmann::json iterations = nlohmann::json::array();
  for (const FitIteration& it : fit.history)
    iterations.push_back({{"iteration", it.iteration}, {"rms", it.rms}, {"max", it.max}, {"smoothing", it.smoothing},
                          {"damping", it.damping}, {"rejected_steps", it.rejected}, {"seconds", it.seconds},
                          {"control_points", it.control_points}});
  return {{"tables", tables},
          {"points", points},
          {"point_count", point_count},
          {"control_points", mesh.vertex_count()},
          {"faces", mesh.face_count()},
          {"method", method_name(options.method)},
          {"error_unit", "fraction of the points' bounding-box diagonal"},
          {"diagonal", fit.diagonal},
          {"iterations", iterations}};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "stencilfit: fits a control mesh's positions to points, so that its exact limit surface under the tables'\n"
      "scheme approximates them. The control mesh is --control, or, with --control-points N, made from the points\n"
      "alone: CGAL's advancing-front reconstruction, its holes filled, simplified by edge collapses to N vertices (a\n"
      "triangle mesh; quad schemes take it through their polygon step, so the tables need its valences). Every\n"
      "scheme: Catmull-Clark, nonpoly, Loop and sqrt(3) (a triangle scheme needs a triangle control mesh).\n"
      "Without --max-control-points the fitted mesh keeps the control mesh's connectivity and vertex order. Each\n"
      "iteration finds every point's closest point on the current surface (its foot), solves a sparse\n"
      "least-squares problem in the control positions with the chosen error model and a smoothing term, and keeps\n"
      "the step only if the mean squared distance (plus smoothing) went down (Levenberg-Marquardt). Progress per\n"
      "iteration on stderr: RMS and max distance of the points to the surface as fractions of the points'\n"
      "bounding-box diagonal. Nothing is written unless the fit completes. docs/fitting.md describes the method.\n\n"
      "  stencilfit --tables tables/catmull-clark --points scan.xyz --control start.obj --out fitted.obj\n"
      "  stencilfit --tables tables/catmull-clark --points bunny.off --control-points 1000 --out bunny.obj\n"
      "  stencilfit --tables tables/loop --points bunny.off --control-points 1000 --out bunny-loop.obj\n"
      "  stencilfit --tables tables/nonpoly --points scan.ply --control start.obj --method tdm --iterations 30 \\\n"
      "             --smoothing 0 --report fit.json --plot fit.svg --out fitted.obj",
      "stencilfit"};
  std::string tables_spec, points_path, control_path, out_path, report_path, plot_path, method = "sdm";
  FitOptions options;
  app.add_option("--tables", tables_spec, "a .sgs (quad scheme) or .sgt (triangle scheme) table file, or the directory stencilgen wrote it to")
      ->required();
  app.add_option("--points", points_path, "the points: .ply or .off (vertices; either case), any other name `x y z` or `x y z nx ny nz` lines (.xyz, .txt)")
      ->required();
  long long control_points = 0;  // signed, so that a negative count is named rather than wrapped
  auto* control = app.add_option("--control", control_path, "the initial control mesh (.obj, or .off or .ply by its extension) near the points; closed, or with boundaries as docs/runtime.md allows for the scheme");
  auto* made = app.add_option("--control-points", control_points,
                              "make the initial control mesh from the points, with this many vertices (at least 4)");
  control->excludes(made);
  app.add_option("--out", out_path, "the fitted control mesh (.obj)")->required();
  app.add_option("--method", method,
                 "error model: pdm (point distance), tdm (tangent distance) or sdm (squared distance, default)");
  app.add_option("--iterations", options.iterations,
                 "at most this many iterations (default 20; with --max-control-points, per refinement round)");
  app.add_option("--smoothing", options.smoothing,
                 "weight of the smoothing term in the first iteration, halved each iteration down to 1/100 of it "
                 "(default 1e-3; 0: none; at most 1000)");
  app.add_option("--max-error", options.max_error,
                 "stop once the largest distance is at most this fraction of the diagonal (default 0: run all "
                 "iterations)");
  long long max_control_points = 0;
  app.add_option("--max-control-points", max_control_points,
                 "adaptive refinement: while the max error is above --max-error, split the triangles with points "
                 "farther than half of it (red-green, the worst first) and fit again (--iterations per round), up to "
                 "this many control points; the refined mesh's new vertices follow the old ones (a triangle control "
                 "mesh without crease, corner or hole tags; needs --max-error)");
  app.add_option("--tolerance", options.tolerance,
                 "closest-point tolerance, as a fraction of the diagonal (default 1e-9)");
  app.add_option("--threads", options.threads, "threads (default 0: all cores)");
  app.add_option("--report", report_path, "write the per-iteration errors and times as JSON");
  app.add_option("--plot", plot_path, "draw error against iteration as SVG");
  return stencil_tools::run_tool(app, argc, argv, [&] {
    options.method = parse_fit_method(method);
    if (options.iterations < 0 || options.iterations > 100000) throw std::runtime_error("--iterations must be 0..100000");
    // Far above the points' weight, the smoothing term alone (whose null
    // space is the translations) decides the fit, and the system is singular.
    if (!(options.smoothing >= 0) || !(options.smoothing <= 1000))
      throw std::runtime_error("--smoothing must be a number from 0 to 1000 (a weight relative to the points': above "
                               "it the smoothing term alone would decide the fit)");
    if (!(options.max_error >= 0) || !std::isfinite(options.max_error))
      throw std::runtime_error("--max-error must be a number >= 0");
    if (!(options.tolerance > 0) || !std::isfinite(options.tolerance))
      throw std::runtime_error("--tolerance must be a positive finite number");
    if (options.threads < 0 || options.threads > 256) throw std::runtime_error("--threads must be 1..256 (or 0 for all cores)");
    if (stencil_runtime::lowercase_extension(out_path) != ".obj") throw std::runtime_error(out_path + ": --out must end in .obj");

    if (options.tolerance < 1e-14)
      throw std::runtime_error("--tolerance must be at least 1e-14 (a fraction of the diagonal; doubles resolve about "
                               "1e-16 of it)");
    if (app.count("--control-points") && control_points < 4)
      throw std::runtime_error("--control-points must be at least 4, got " + std::to_string(control_points));
    if (app.count("--max-control-points") && max_control_points < 4)
      throw std::runtime_error("--max-control-points must be at least 4, got " + std::to_string(max_control_points));
    {  // three outputs, three files: one must not overwrite another
      const auto same = stencil_tools::same_path;
      if (same(out_path, report_path) || same(out_path, plot_path) || same(report_path, plot_path))
        throw std::runtime_error("--out, --report and --plot must name three different files");
      const stencil_tools::TableInput read = stencil_tools::table_input(tables_spec);
      stencil_tools::check_outputs_are_not_inputs({out_path, report_path, plot_path}, {read.file, points_path, control_path},
                                                  {read.folder});
    }
    for (const std::string& output : {out_path, report_path, plot_path}) stencil_tools::check_output_can_be_written(output);
    if (max_control_points > 0 && !(options.max_error > 0))
      throw std::runtime_error("--max-control-points needs --max-error (the split threshold)");
    if (control_path.empty() && !app.count("--control-points"))
      throw std::runtime_error("give the initial control mesh (--control) or its size (--control-points)");
    const auto tables = Tables::load(tables_spec);
    const std::vector<Point> points = stencil_tools::read_points(points_path);
    Mesh mesh;
    if (!control_path.empty()) {
      mesh = read_mesh(control_path);
      for (const std::string& warning : mesh.warnings) std::cerr << warning << '\n';
    } else {
      stencil_reconstruction::InitialMeshOptions initial;
      initial.control_points = static_cast<std::size_t>(control_points);
      initial.progress = [](const std::string& stage) { std::fprintf(stderr, "initial mesh: %s\n", stage.c_str()); };
      stencil_reconstruction::InitialMeshReport made_report;
      mesh = stencil_reconstruction::initial_control_mesh(points, initial, &made_report);
      std::fprintf(stderr,
                   "initial mesh: %zu vertices, %zu triangles (reconstruction from %zu points %.2f s, %zu holes filled, "
                   "simplification %.2f s)\n",
                   mesh.vertex_count(), mesh.face_count(), made_report.points_used, made_report.reconstruction_seconds,
                   made_report.holes_filled, made_report.simplification_seconds);
    }
    const auto topology = SurfaceTopology::create(tables, mesh);
    // The header goes out with the first iteration, after the fit's own checks of its inputs.
    bool started = false;
    options.progress = [&](const FitIteration& it) {
      if (!started)
        std::fprintf(stderr, "%zu points, %zu control points (%zu faces), %s, %s\n", points.size(), mesh.vertex_count(),
                     mesh.face_count(), tables->scheme().c_str(), method_name(options.method));
      started = true;
      std::fprintf(stderr, "iteration %3d  rms %.3e  max %.3e  (of the diagonal)  %zu control points  %.2f s%s\n",
                   it.iteration, it.rms, it.max, it.control_points, it.seconds,
                   it.rejected > 0 ? ("  (" + std::to_string(it.rejected) + " damped retries)").c_str() : "");
    };
    FitResult fit;
    if (max_control_points > 0) {
      AdaptiveFit adaptive = fit_adaptively(tables, mesh, points, options, static_cast<std::size_t>(max_control_points));
      std::fprintf(stderr, "%d refinement rounds: %zu control points (stopped: %s)\n", adaptive.rounds,
                   adaptive.mesh.vertex_count(), adaptive.stopped.c_str());
      mesh = std::move(adaptive.mesh);
      fit = std::move(adaptive.fit);
    } else {
      fit = fit_surface(topology, mesh.positions, points, options);
      mesh.positions = fit.control;
    }

    // Everything is formatted before anything is written; a failed write removes what went before.
    const std::string report =
        report_path.empty() ? "" : report_of(fit, options, tables_spec, points_path, points.size(), mesh).dump(2) + "\n";
    const std::string plot =
        plot_path.empty() ? ""
                          : stencil_tools::convergence_svg(fit.history, std::string("stencilfit ") + method_name(options.method) +
                                                                            ", " + tables->scheme() + ", " +
                                                                            std::to_string(points.size()) + " points");
    write_obj(mesh, out_path);
    std::vector<std::string> written{out_path};
    try {
      if (!report_path.empty()) stencil_tools::write_text_file(report_path, report), written.push_back(report_path);
      if (!plot_path.empty()) stencil_tools::write_text_file(plot_path, plot);
    } catch (...) {
      for (const std::string& path : written) std::remove(path.c_str());
      throw;
    }
    const FitIteration& last = fit.history.back();
    std::fprintf(stderr, "fitted in %d iterations, %.2f s: rms %.3e, max %.3e of the diagonal %.6g, %zu control points\n",
                 last.iteration, last.seconds, last.rms, last.max, fit.diagonal, mesh.vertex_count());
    return 0;
  });
}
