// stenciltess: watertight adaptive tessellation of a quad control mesh from
// exact stencil tables.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "rate_choice.hpp"
#include "stencil_runtime/tessellation.hpp"
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

}  // namespace

int main(int argc, char** argv) {
  using namespace stencil_runtime;
  CLI::App app{
      "stenciltess: watertight adaptive tessellation of a quad control mesh (the paper's dual scheme):\n"
      "one exact limit point per grid cell of each face at its own rate, quads inside faces, triangle\n"
      "zippers along edges, a polygon around every vertex. The output is closed and consistently oriented\n"
      "for any mix of rates.\n\n"
      "  stenciltess --tables tables/nonpoly --mesh meshes/chess-piece.obj --rate 8 --out piece.ply\n"
      "  stenciltess --tables tables/nonpoly --mesh meshes/torus-3-5.obj --tolerance 1e-3 --out torus.obj\n"
      "  stenciltess --tables tables/nonpoly --mesh M.obj --camera 0,0,6,0,0,0 --pixels 8 --out view.ply"};
  std::string tables_spec, mesh_path, out, rates_file, camera;
  int rate = 0, threads = 0, width = 1920;
  double tolerance = 0, pixels = 0, fov = 60;
  app.add_option("--tables", tables_spec, "a .sgs table file, the directory stencilgen wrote it to, or a directory of exact JSON tables")->required();
  app.add_option("--mesh", mesh_path, "closed quad control mesh (.obj)")->required();
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
    const SurfaceTables tables = SurfaceTables::load(file.string());
    const Mesh mesh = read_obj(mesh_path);
    std::vector<int> rates;
    if (rate > 0) rates.assign(mesh.face_count(), rate);
    else if (!rates_file.empty()) rates = stencil_tools::rates_from_file(rates_file, mesh.face_count());
    else if (tolerance > 0) rates = stencil_tools::rates_for_tolerance(mesh, tolerance);
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
    const LimitSurface surface(tables, mesh, scheme);
    std::vector<int> prepared = prepared_rates(surface, rates);
    const int wanted = *std::max_element(prepared.begin(), prepared.end());
    stencil_tools::snap_to_tables(prepared, tables);
    if (wanted > tables.rates().back())
      std::fprintf(stderr,
                   "stenciltess: warning: rates up to %d were asked for; the tables stop at %d, which is used instead "
                   "(more: stencilgen --scheme %s --valence <valences> --n %d --out <dir>)\n",
                   wanted, tables.rates().back(), scheme.c_str(), wanted);
    const auto t1 = std::chrono::steady_clock::now();
    const PolygonSoup soup = tessellate(surface, prepared, {threads});
    const auto t2 = std::chrono::steady_clock::now();
    write_polygons(soup, out);
    const auto [lo, hi] = std::minmax_element(prepared.begin(), prepared.end());
    const double tess = std::chrono::duration<double>(t2 - t1).count();
    std::printf("%zu faces (%zu after %d subdivision step%s to isolate extraordinary vertices), rates %d..%d\n",
                mesh.face_count(), prepared.size(), surface.prepared().steps, surface.prepared().steps == 1 ? "" : "s",
                *lo, *hi);
    std::printf("%zu limit points, %zu quads + %zu triangles (%zu triangles), tessellated in %.4f s (%.1f M triangles/s), "
                "setup %.4f s\n",
                soup.positions.size(), soup.quads.size(), soup.triangles.size(), soup.triangle_count(), tess,
                soup.triangle_count() / tess / 1e6, std::chrono::duration<double>(t1 - t0).count());
    std::printf("wrote %s\n", out.c_str());
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "stenciltess: error: " << e.what() << "\n";
    return 1;
  }
}
