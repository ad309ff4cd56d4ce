// stencileval: limit points of a control mesh at exact rational parameters,
// from the binary tables written by stencilgen.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

#include <functional>
#include <memory>

#include "stencil_runtime/limit_surface.hpp"
#include "stencil_runtime/triangle_surface.hpp"
#include "table_location.hpp"

namespace {

using namespace stencil_runtime;

struct Query {
  long face;
  stencil_tools::Fraction u, v;
};

// A loaded surface of either kind, as the queries need it.
struct Evaluator {
  std::size_t faces = 0;
  bool triangles = false;
  std::vector<int> rates;
  std::function<Point(std::size_t, long, long, long)> at;  // face, i, j, n
};

// The smallest rate in the tables that both denominators divide.
long rate_for(const Evaluator& e, const Query& q, const std::string& scheme) {
  const long need = std::lcm(q.u.den, q.v.den);
  for (int n : e.rates)
    if (n % need == 0) return n;
  throw std::runtime_error("the parameter (" + std::to_string(q.u.num) + "/" + std::to_string(q.u.den) + ", " +
                           std::to_string(q.v.num) + "/" + std::to_string(q.v.den) + ") needs rate " +
                           std::to_string(need) + " or a multiple, which the tables do not hold; add it with: " +
                           "stencilgen --scheme " + scheme + " --valence <valences> --n " + std::to_string(need) +
                           " --out <dir>");
}

Point evaluate(const Evaluator& e, const Query& q, const std::string& scheme) {
  if (q.face < 0 || static_cast<std::size_t>(q.face) >= e.faces)
    throw std::runtime_error("face " + std::to_string(q.face) + " does not exist (the mesh has " +
                             std::to_string(e.faces) + " faces, numbered from 0)");
  if (e.triangles && q.u.num * q.v.den + q.v.num * q.u.den > q.u.den * q.v.den)
    throw std::runtime_error("the parameter (" + std::to_string(q.u.num) + "/" + std::to_string(q.u.den) + ", " +
                             std::to_string(q.v.num) + "/" + std::to_string(q.v.den) +
                             ") lies outside the triangle: u + v must be at most 1");
  const long n = rate_for(e, q, scheme);
  return e.at(static_cast<std::size_t>(q.face), q.u.num * (n / q.u.den), q.v.num * (n / q.v.den), n);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "stencileval: exact-stencil limit points of a control mesh at rational parameters: a quad mesh\n"
      "with a quad scheme's tables (.sgs), a triangle mesh with Loop or sqrt(3) tables (.sgt).\n"
      "Parameter convention: for face F (v0, v1, v2, v3) as listed in the OBJ file, (0,0) is at v0,\n"
      "u runs along v0->v1 and v runs along v0->v3; for a triangle (v0, v1, v2), u runs along v0->v1,\n"
      "v along v0->v2, and u + v <= 1. Prints the point as `x y z` on the last line.\n\n"
      "  stencileval --tables tables/nonpoly --mesh meshes/cube.obj --face 0 --uv 1/3,1/2\n"
      "  stencileval --tables tables/nonpoly --mesh meshes/cube.obj --batch queries.txt   (lines: F U V)\n"
      "  stencileval --tables tables/loop --mesh meshes/tri-torus.obj --face 0 --uv 1/3,1/3"};
  std::string tables_spec, mesh_path, uv, batch;
  long face = -1;
  app.add_option("--tables", tables_spec, "a .sgs or .sgt table file, the directory stencilgen wrote it to, or a directory of exact JSON quad tables")->required();
  app.add_option("--mesh", mesh_path, "closed control mesh (.obj): quads for .sgs tables, triangles for .sgt")->required();
  app.add_option("--face", face, "0-based face index in file order");
  app.add_option("--uv", uv, "exact parameters U,V in [0,1], e.g. 1/3,1/2");
  app.add_option("--batch", batch, "file of `F U V` lines; prints one `x y z` line per query");
  CLI11_PARSE(app, argc, argv);
  try {
    const auto file = stencil_tools::find_table_file(tables_spec);
    const std::string scheme = file.stem().string();
    Mesh mesh;  // read after the tables, so that a bad table file is reported first
    // Tables and surface live here; the evaluator refers to them.
    std::unique_ptr<SurfaceTables> quad_tables;
    std::unique_ptr<LimitSurface> quad_surface;
    std::unique_ptr<TriangleTables> triangle_tables;
    std::unique_ptr<TriangleSurface> triangle_surface;
    Evaluator surface;
    if (stencil_tools::is_triangle_table(file)) {
      triangle_tables = std::make_unique<TriangleTables>(TriangleTables::load(file.string()));
      mesh = read_obj(mesh_path);
      triangle_surface = std::make_unique<TriangleSurface>(*triangle_tables, mesh, scheme);
      surface = {mesh.face_count(), true, triangle_tables->rates(),
                 [s = triangle_surface.get()](std::size_t f, long i, long j, long n) { return s->evaluate(f, i, j, n); }};
    } else {
      quad_tables = std::make_unique<SurfaceTables>(SurfaceTables::load(file.string()));
      mesh = read_obj(mesh_path);
      quad_surface = std::make_unique<LimitSurface>(*quad_tables, mesh, scheme);
      surface = {mesh.face_count(), false, quad_tables->rates(),
                 [s = quad_surface.get()](std::size_t f, long i, long j, long n) { return s->evaluate(f, i, j, n); }};
    }
    if (!batch.empty()) {
      std::ifstream in(batch);
      if (!in) throw std::runtime_error(batch + ": cannot open");
      std::string line;
      long number = 0;
      while (std::getline(in, line)) {
        ++number;
        std::istringstream ls(line);
        std::string f, u, v;
        if (!(ls >> f)) continue;
        if (!(ls >> u >> v)) throw std::runtime_error(batch + ":" + std::to_string(number) + ": expected `F U V`");
        try {
          const Point p = evaluate(surface, {std::stol(f), stencil_tools::parse_parameter(u), stencil_tools::parse_parameter(v)}, scheme);
          std::printf("%.17g %.17g %.17g\n", p[0], p[1], p[2]);
        } catch (const std::exception& e) {
          throw std::runtime_error(batch + ":" + std::to_string(number) + ": " + e.what());
        }
      }
      return 0;
    }
    if (face < 0 || uv.empty()) throw std::runtime_error("give --face and --uv, or --batch (see --help)");
    const auto comma = uv.find(',');
    if (comma == std::string::npos) throw std::runtime_error("--uv expects U,V such as 1/3,1/2");
    const Query q{face, stencil_tools::parse_parameter(uv.substr(0, comma)), stencil_tools::parse_parameter(uv.substr(comma + 1))};
    const Point p = evaluate(surface, q, scheme);
    std::printf("face %ld at (%s): limit point of '%s'\n%.17g %.17g %.17g\n", face, uv.c_str(), scheme.c_str(), p[0], p[1], p[2]);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "stencileval: error: " << e.what() << "\n";
    return 1;
  }
}
