// stenciltess: watertight adaptive tessellation of a control mesh from exact
// stencil tables, for any scheme family; one mesh, or an animation (a sequence
// of meshes with the same connectivity) planned once and evaluated per frame.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "stencil_runtime/error.hpp"
#include "rate_choice.hpp"
#include "stencil_runtime/limits.hpp"
#include "stencil_runtime/mesh_io.hpp"
#include "stencil_runtime/tessellation.hpp"
#include "staged_files.hpp"
#include "tool_support.hpp"

namespace {

using namespace stencil_runtime;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "stenciltess: watertight adaptive tessellation of a control mesh (the paper's dual scheme), from\n"
      "stencilgen's tables: a quad scheme's .sgs with a polygon mesh, a triangle scheme's .sgt with a triangle mesh.\n"
      "One exact limit point per grid cell (quads) or small grid triangle (triangles) of each face at its own rate;\n"
      "quads (triangles: hexagons as two quads) inside faces, triangle zippers along edges, a polygon around every\n"
      "vertex. The output is closed and consistently oriented for any mix of rates.\n"
      "Animation: --frames names a sequence of OBJ files with the mesh's connectivity and new positions (sorted by\n"
      "file name); the topology and the tessellation plan are made once from --mesh (rates from its positions), and\n"
      "frame k is written to --out with %d replaced by k (from 0). A frame's tag lines, if it has any, must be the\n"
      "mesh's (a frame without them takes the mesh's creases, corners and holes); every frame's output then equals\n"
      "what a run on that frame alone, with the mesh's tags, writes with the same rates (--rate or --rates).\n"
      "The mesh's OpenSubdiv tag lines are honoured: faces tagged `hole` are left out (their rims become the\n"
      "output's boundaries); semi-sharp creases and corners (`t crease`, `t corner`, sharpness below 10, and\n"
      "`t creasemethod chaikin`) and `t smoothtriangles` (Catmull-Clark) as in OpenSubdiv; the output stays closed\n"
      "along creases. Infinitely sharp creases, corners, darts and cone points (10 or more) too, for quad schemes; Loop:\n"
      "creases, corners, darts and cone points too.\n"
      "Meshes with boundaries (quad schemes and Loop): every boundary vertex, in any number of faces, with --boundary\n"
      "edge-only (the default), edge-and-corner (or `t interpolateboundary 1/0/0 1`: corners in one face stay put)\n"
      "or none (the faces at boundary vertices are left out: no surface, like holes).\n"
      "The output reaches the surface's edge: its rim is the limit curve along the boundary (and round holes).\n\n"
      "  stenciltess --tables tables/nonpoly --mesh meshes/chess-piece.obj --rate 8 --out piece.ply\n"
      "  stenciltess --tables tables/nonpoly --mesh meshes/torus-3-5.obj --tolerance 1e-3 --out torus.obj\n"
      "  stenciltess --tables tables/nonpoly --mesh M.obj --camera 0,0,6,0,0,0 --pixels 8 --out view.ply\n"
      "  stenciltess --tables tables/loop --mesh meshes/tri-torus.obj --rate 6 --out torus.ply\n"
      "  stenciltess --tables tables/nonpoly --mesh meshes/chess-piece.obj --rate 8 --normals --out piece.ply\n"
      "  stenciltess --tables tables/catmull-clark --mesh creased.obj --rate 8 --out creased.ply   (t crease lines)\n"
      "  stenciltess --tables tables/nonpoly --mesh rest.obj --frames 'anim/frame*.obj' --rate 8 --out 'out/frame%04d.ply'",
      "stenciltess"};
  std::string tables_spec, mesh_path, out, rates_file, camera, frames;
  int rate = 0, threads = 0, width = 1920;
  double tolerance = 0, pixels = 0, fov = 60;
  app.add_option("--tables", tables_spec, "a .sgs or .sgt table file, the directory stencilgen wrote it to, or a directory of exact JSON quad tables")->required();
  app.add_option("--mesh", mesh_path, "control mesh (.obj, or .off or .ply by its extension): polygons for a quad scheme (closed, or with boundaries: see above), triangles for a triangle scheme (closed; Loop: or with boundaries)")->required();
  app.add_option("--out", out, "output .obj (text) or .ply (binary), written whole or not at all; with --frames a pattern such as out/f%04d.ply")->required();
  auto* r1 = app.add_option("--rate", rate, "uniform rate N (1..4096) for every face");
  auto* r2 = app.add_option("--rates", rates_file, "file with one rate per face (file order)");
  auto* r3 = app.add_option("--tolerance", tolerance, "curvature-based rates: target deviation in model units");
  auto* r4 = app.add_option("--camera", camera, "view-dependent rates: EX,EY,EZ,TX,TY,TZ (eye, target)");
  app.add_option("--pixels", pixels, "with --camera: target edge length in pixels");
  app.add_option("--fov", fov, "with --camera: horizontal field of view in degrees (default 60)");
  app.add_option("--width", width, "with --camera: image width in pixels (default 1920)");
  app.add_option("--threads", threads, "threads, 1..256, or 0 for all cores (the default)");
  app.add_option("--frames", frames, "animation: a pattern of OBJ files (quoted), e.g. 'anim/frame*.obj'");
  stencil_tools::BoundaryOption boundary;
  boundary.add(app);
  bool with_normals = false;
  app.add_flag("--normals", with_normals,
               "also write per-vertex unit normals of the limit surface (every scheme; PLY nx ny nz, OBJ vn)");
  r1->excludes(r2, r3, r4);
  r2->excludes(r3, r4);
  r3->excludes(r4);
  return stencil_tools::run_tool(app, argc, argv, [&] {
    if (threads < 0 || threads > 256) throw std::runtime_error("--threads must be 1..256 (or 0 for all cores)");
    if (app.count("--rate") && (rate < 1 || rate > limits::kMaxRate))
      throw std::runtime_error("--rate must be 1.." + std::to_string(limits::kMaxRate));
    const stencil_tools::TableInput read = stencil_tools::table_input(tables_spec);
    if (!frames.empty()) stencil_tools::check_frame_pattern(out);
    else stencil_tools::check_output_is_not_input(out, {read.file, mesh_path, rates_file}, {read.folder});
    stencil_tools::check_output_can_be_written(frames.empty() ? out : stencil_tools::frame_name(out, 0));
    {  // the format, before the work (write_polygons would refuse it only at the end)
      const std::string ext = stencil_runtime::lowercase_extension(out);
      if (ext != ".obj" && ext != ".ply") throw std::runtime_error(out + ": --out must end in .obj or .ply");
    }
    if (camera.empty())
      for (const char* option : {"--pixels", "--fov", "--width"})
        if (app.count(option)) throw std::runtime_error(std::string(option) + " applies to --camera rates only");
    const auto t0 = Clock::now();
    const auto tables = Tables::load(tables_spec);
    Mesh mesh = read_mesh(mesh_path);
    boundary.apply(mesh);
    for (const std::string& warning : mesh.warnings) std::cerr << warning << '\n';
    std::vector<int> rates;
    if (app.count("--rate")) rates.assign(mesh.face_count(), rate);
    else if (!rates_file.empty()) rates = stencil_tools::rates_from_file(rates_file, mesh.face_count());
    else if (app.count("--tolerance")) rates = stencil_tools::rates_for_tolerance(mesh, tolerance);
    else if (!camera.empty()) {
      if (!app.count("--pixels")) throw std::runtime_error("--camera needs --pixels (target edge length in pixels)");
      stencil_tools::Camera cam = stencil_tools::parse_camera(camera);
      cam.fov_degrees = fov;
      cam.width_pixels = width;
      rates = stencil_tools::rates_for_view(mesh, cam, pixels);
    } else {
      throw std::runtime_error("choose the rates: --rate N, --rates FILE, --tolerance T or --camera ... --pixels P");
    }
    const auto topology = SurfaceTopology::create(tables, mesh);
    const TessellationPlan plan(topology, rates, {threads});
    const double setup = seconds_since(t0);
    if (plan.largest_wanted_rate() > tables->rates().back()) {
      // Rates are the mesh's; a face that the preparation split k times has
      // its rate divided by 2^k on each part, which is what the tables serve.
      const bool split = topology->prepared_face_count() != mesh.face_count();
      // stencilgen makes surface tables up to this rate (generator/base/limits.hpp).
      constexpr int kGeneratorLargestRate = 128;
      const int more = std::min(plan.largest_wanted_rate(), kGeneratorLargestRate);
      std::fprintf(stderr, "stenciltess: warning: rates up to %d were asked for%s; the tables stop at %d, which is used instead",
                   plan.largest_wanted_rate(),
                   split ? " on the prepared faces (a rate on a face that the preparation splits is divided among its parts)" : "",
                   tables->rates().back());
      if (tables->rates().back() < more)
        std::fprintf(stderr, " (more%s: stencilgen --scheme %s --valence <valences> --n %d --out <dir>)\n",
                     more < plan.largest_wanted_rate() ? ", up to stencilgen's largest rate" : "", tables->scheme().c_str(), more);
      else
        std::fprintf(stderr, " (stencilgen makes surface tables up to rate %d)\n", kGeneratorLargestRate);
    }
    const auto [lo, hi] = std::minmax_element(plan.prepared_rates().begin(), plan.prepared_rates().end());
    std::printf("%zu faces (%zu after %s to isolate extraordinary vertices), rates %d..%d\n", mesh.face_count(),
                topology->prepared_face_count(), topology->preparation().c_str(), *lo, *hi);
    if (!mesh.tags.holes.empty())
      std::printf("%zu faces tagged `hole` left out (their rims are the output's boundary)\n", mesh.tags.holes.size());
    Surface surface(topology);
    PolygonSoup soup = plan.make_soup();
    if (frames.empty()) {
      const auto t1 = Clock::now();
      surface.set_positions(mesh.positions);
      if (with_normals) soup.normals.resize(soup.positions.size());
      plan.evaluate(surface, soup.positions.data(), with_normals ? soup.normals.data() : nullptr);
      const double tess = seconds_since(t1);
      write_polygons(soup, out);
      std::printf("%zu limit points, %zu quads + %zu triangles (%zu triangles), tessellated in %.4f s (%.1f M triangles/s), "
                  "setup %.4f s\n",
                  soup.positions.size(), soup.quads.size(), soup.triangles.size(), soup.triangle_count(), tess,
                  soup.triangle_count() / tess / 1e6, setup);
      std::printf("wrote %s\n", out.c_str());
      return 0;
    }
    // Animation: check every frame's connectivity, and that no output would
    // replace an input, before writing anything.
    const std::vector<std::string> files = stencil_tools::expand_pattern(frames);
    if (files.size() > 1000000) throw std::runtime_error(stencil_runtime::quoted_excerpt(frames) + " names more than 1000000 frames");
    std::vector<std::string> inputs = files, names;
    inputs.push_back(mesh_path);
    inputs.push_back(read.file);
    inputs.push_back(rates_file);
    for (std::size_t k = 0; k < files.size(); ++k) names.push_back(stencil_tools::frame_name(out, k));
    stencil_tools::check_outputs_are_not_inputs(names, inputs, {read.folder});
    for (std::size_t k = 0; k < files.size(); ++k) {
      Mesh frame = read_mesh(files[k]);
      if (!topology->same_connectivity(frame.vertex_count(), frame.face_sizes, frame.face_vertices))
        throw std::runtime_error(files[k] + ": frame " + std::to_string(k) + " has another connectivity than " + mesh_path);
      // The plan and the topology are the mesh's: a frame's own tags would
      // be ignored, so they must be the mesh's (or absent).
      const bool bare = stencil_tools::untagged(frame.tags);
      boundary.apply(frame);  // --boundary overrides a frame's tag as the mesh's
      if (!bare && !stencil_tools::same_tags(frame.tags, mesh.tags))
        throw std::runtime_error(files[k] + ": frame " + std::to_string(k) + " has other tag lines (creases, corners, holes or "
                                 "subdivision options) than " + mesh_path + "; a frame moves the vertices only: give it the "
                                 "mesh's tags or none");
    }
    // Every frame is staged beside its output and moved into place once all
    // are written: a failure leaves the outputs as they were.
    stencil_tools::StagedFiles written;
    double per_frame = 0;
    for (std::size_t k = 0; k < files.size(); ++k) {
      const Mesh frame = read_mesh(files[k]);
      const auto t1 = Clock::now();
      try {
        surface.set_positions(frame.positions);
        if (with_normals) soup.normals.resize(soup.positions.size());
        plan.evaluate(surface, soup.positions.data(), with_normals ? soup.normals.data() : nullptr);
      } catch (const std::exception& e) {
        throw std::runtime_error(files[k] + ": frame " + std::to_string(k) + ": " + e.what());
      }
      per_frame += seconds_since(t1);
      write_polygons(soup, written.stage(names[k]));
      std::fprintf(stderr, "frame %zu/%zu: %s -> %s\n", k + 1, files.size(), files[k].c_str(), names[k].c_str());
    }
    written.commit();
    std::printf("%zu %s of %zu limit points, %zu quads + %zu triangles each; %.4f s per frame (%.1f M triangles/s), "
                "setup %.4f s\n",
                files.size(), files.size() == 1 ? "frame" : "frames", soup.positions.size(), soup.quads.size(), soup.triangles.size(), per_frame / files.size(),
                soup.triangle_count() * files.size() / per_frame / 1e6, setup);
    if (names.size() == 1) std::printf("wrote %s\n", names.front().c_str());
    else std::printf("wrote %s .. %s\n", names.front().c_str(), names.back().c_str());
    return 0;
  });
}
