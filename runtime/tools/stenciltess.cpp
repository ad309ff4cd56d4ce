// stenciltess: watertight adaptive tessellation of a quad control mesh from
// exact stencil tables.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "rate_choice.hpp"
#include <memory>

#include "stencil_runtime/tessellation.hpp"
#include "stencil_runtime/triangle_tessellation.hpp"
#include "table_location.hpp"

namespace {

std::array<double, 6> parse_six(const std::string& text) {
  std::array<double, 6> v{};
  std::istringstream in(text);
  char comma = 0;
  for (int k = 0; k < 6; ++k) {
    if (!(in >> v[static_cast<std::size_t>(k)]) || (k < 5 && !(in >> comma && comma == ',')))
      throw std::runtime_error("--camera expects EX,EY,EZ,TX,TY,TZ (eye and target), got '" + text + "'");
  }
  return v;
}

// The prepared mesh's rates, the tessellation and its timing, for either kind of surface.
struct Tessellated {
  stencil_runtime::PolygonSoup soup;
  std::vector<int> rates;  // of the prepared faces, snapped to the tables
  int wanted = 0, steps = 0;
  double seconds = 0, setup_seconds = 0;
};

template <class Surface>
Tessellated run(const Surface& surface, const std::vector<int>& rates, const std::vector<int>& table_rates, int threads) {
  using namespace stencil_runtime;
  Tessellated out;
  const auto t0 = std::chrono::steady_clock::now();
  out.rates = prepared_rates(surface, rates);
  out.wanted = *std::max_element(out.rates.begin(), out.rates.end());
  out.steps = surface.prepared().steps;
  stencil_tools::snap_to_tables(out.rates, table_rates);
  const auto t1 = std::chrono::steady_clock::now();
  out.soup = tessellate(surface, out.rates, {threads});
  const auto t2 = std::chrono::steady_clock::now();
  out.seconds = std::chrono::duration<double>(t2 - t1).count();
  out.setup_seconds = std::chrono::duration<double>(t1 - t0).count();
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace stencil_runtime;
  CLI::App app{
      "stenciltess: watertight adaptive tessellation of a control mesh (the paper's dual scheme): a quad\n"
      "mesh with a quad scheme's tables (.sgs), a triangle mesh with Loop or sqrt(3) tables (.sgt). One exact limit\n"
      "point per grid cell (quads) or small grid triangle (triangles) of each face at its own rate; quads\n"
      "(triangles: hexagons as two quads) inside faces, triangle zippers along edges, a polygon around every\n"
      "vertex. The output is closed and consistently oriented for any mix of rates.\n\n"
      "  stenciltess --tables tables/nonpoly --mesh meshes/chess-piece.obj --rate 8 --out piece.ply\n"
      "  stenciltess --tables tables/nonpoly --mesh meshes/torus-3-5.obj --tolerance 1e-3 --out torus.obj\n"
      "  stenciltess --tables tables/nonpoly --mesh M.obj --camera 0,0,6,0,0,0 --pixels 8 --out view.ply\n"
      "  stenciltess --tables tables/loop --mesh meshes/tri-torus.obj --rate 6 --out torus.ply"};
  std::string tables_spec, mesh_path, out, rates_file, camera;
  int rate = 0, threads = 0, width = 1920;
  double tolerance = 0, pixels = 0, fov = 60;
  app.add_option("--tables", tables_spec, "a .sgs or .sgt table file, the directory stencilgen wrote it to, or a directory of exact JSON quad tables")->required();
  app.add_option("--mesh", mesh_path, "closed control mesh (.obj): quads for .sgs tables, triangles for .sgt")->required();
  app.add_option("--out", out, "output .obj (text) or .ply (binary); written whole or not at all")->required();
  auto* r1 = app.add_option("--rate", rate, "uniform rate N for every face");
  auto* r2 = app.add_option("--rates", rates_file, "file with one rate per face (file order)");
  auto* r3 = app.add_option("--tolerance", tolerance, "curvature-based rates: target deviation in model units");
  auto* r4 = app.add_option("--camera", camera, "view-dependent rates: EX,EY,EZ,TX,TY,TZ (eye, target)");
  app.add_option("--pixels", pixels, "with --camera: target edge length in pixels");
  app.add_option("--fov", fov, "with --camera: horizontal field of view in degrees (default 60)");
  app.add_option("--width", width, "with --camera: image width in pixels (default 1920)");
  app.add_option("--threads", threads, "threads (default: all cores)");
  r1->excludes(r2, r3, r4);
  r2->excludes(r3, r4);
  r3->excludes(r4);
  CLI11_PARSE(app, argc, argv);
  try {
    const auto file = stencil_tools::find_table_file(tables_spec);
    const std::string scheme = file.stem().string();
    const auto t0 = std::chrono::steady_clock::now();
    const bool triangles = stencil_tools::is_triangle_table(file);
    std::unique_ptr<SurfaceTables> quad_tables;
    std::unique_ptr<TriangleTables> triangle_tables;
    if (triangles) triangle_tables = std::make_unique<TriangleTables>(TriangleTables::load(file.string()));
    else quad_tables = std::make_unique<SurfaceTables>(SurfaceTables::load(file.string()));
    const std::vector<int>& table_rates = triangles ? triangle_tables->rates() : quad_tables->rates();
    const Mesh mesh = read_obj(mesh_path);
    std::vector<int> rates;
    if (rate > 0) rates.assign(mesh.face_count(), rate);
    else if (!rates_file.empty()) rates = stencil_tools::rates_from_file(rates_file, mesh.face_count());
    else if (tolerance > 0) rates = stencil_tools::rates_for_tolerance(mesh, tolerance, triangles ? 3 : 4);
    else if (!camera.empty()) {
      if (pixels <= 0) throw std::runtime_error("--camera needs --pixels (target edge length in pixels)");
      const auto c = parse_six(camera);
      stencil_tools::Camera cam;
      cam.eye = {c[0], c[1], c[2]};
      cam.target = {c[3], c[4], c[5]};
      cam.fov_degrees = fov;
      cam.width_pixels = width;
      rates = stencil_tools::rates_for_view(mesh, cam, pixels);
    } else {
      throw std::runtime_error("choose the rates: --rate N, --rates FILE, --tolerance T or --camera ... --pixels P");
    }
    const auto t1 = std::chrono::steady_clock::now();
    const Tessellated result = triangles ? run(TriangleSurface(*triangle_tables, mesh, scheme), rates, table_rates, threads)
                                         : run(LimitSurface(*quad_tables, mesh, scheme), rates, table_rates, threads);
    const PolygonSoup& soup = result.soup;
    const auto& prepared = result.rates;
    const int wanted = result.wanted;
    if (wanted > table_rates.back())
      std::fprintf(stderr,
                   "stenciltess: warning: rates up to %d were asked for; the tables stop at %d, which is used instead "
                   "(more: stencilgen --scheme %s --valence <valences> --n %d --out <dir>)\n",
                   wanted, table_rates.back(), scheme.c_str(), wanted);
    write_polygons(soup, out);
    const auto [lo, hi] = std::minmax_element(prepared.begin(), prepared.end());
    const double tess = result.seconds;
    const bool double_steps = triangles && triangle_tables->refinement() == TriangleRefinement::Sqrt3;
    std::printf("%zu faces (%zu after %d %s step%s to isolate extraordinary vertices), rates %d..%d\n",
                mesh.face_count(), prepared.size(), result.steps, double_steps ? "double sqrt(3)" : "subdivision",
                result.steps == 1 ? "" : "s", *lo, *hi);
    std::printf("%zu limit points, %zu quads + %zu triangles (%zu triangles), tessellated in %.4f s (%.1f M triangles/s), "
                "setup %.4f s\n",
                soup.positions.size(), soup.quads.size(), soup.triangles.size(), soup.triangle_count(), tess,
                soup.triangle_count() / tess / 1e6,
                std::chrono::duration<double>(t1 - t0).count() + result.setup_seconds);
    std::printf("wrote %s\n", out.c_str());
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "stenciltess: error: " << e.what() << "\n";
    return 1;
  }
}
