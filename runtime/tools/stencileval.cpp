// stencileval: limit points of a control mesh at exact rational parameters,
// from the tables written by stencilgen, for any scheme family.
#include <cmath>
#include <cstdio>
#include <sstream>

#include "stencil_runtime/mesh_io.hpp"
#include "stencil_runtime/surface.hpp"
#include "tool_support.hpp"

namespace {

using namespace stencil_runtime;
using stencil_tools::ParameterText;

Point evaluate(const Surface& surface, std::size_t face, const ParameterText& u, const ParameterText& v) {
  if (!u.exact || !v.exact)
    throw EvaluationError("decimal parameters are not supported yet; give exact rationals such as 1/3");
  const Point p = surface.evaluate(face, {u.fraction, v.fraction});
  for (double x : p)
    if (!std::isfinite(x)) throw EvaluationError("the limit point is not finite (coordinates too large)");
  return p;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "stencileval: exact limit points of a closed control mesh at rational parameters, from stencilgen's tables\n"
      "(a quad scheme's .sgs with a polygon mesh, a triangle scheme's .sgt with a triangle mesh).\n"
      "Faces are numbered from 0 in file order. What (u, v) means on face F (v0, v1, ...) as listed in the OBJ file,\n"
      "as in OpenSubdiv's Bfr:\n"
      "  quad (quad scheme): (0,0) at v0, u along v0->v1, v along v0->v3, 0 <= u, v <= 1;\n"
      "  triangle (triangle scheme): u along v0->v1, v along v0->v2, u + v <= 1;\n"
      "  N-gon (quad scheme, N != 4): sub-face s (the quad at corner s after the scheme's polygon step) is the tile\n"
      "  [s % U, s % U + 1/2] x [s / U, s / U + 1/2], U = 2 (N = 3), 3 (N = 5..9), 1 + floor(sqrt(N - 1)) above.\n"
      "Prints the point as `x y z` on the last line.\n\n"
      "  stencileval --tables tables/nonpoly --mesh meshes/cube.obj --face 0 --uv 1/3,1/2\n"
      "  stencileval --tables tables/nonpoly --mesh meshes/cube.obj --batch queries.txt   (lines: F U V)\n"
      "  stencileval --tables tables/loop --mesh meshes/tri-torus.obj --face 0 --uv 1/3,1/3",
      "stencileval"};
  std::string tables_spec, mesh_path, uv, batch, face_text;
  app.add_option("--tables", tables_spec, "a .sgs or .sgt table file, the directory stencilgen wrote it to, or a directory of exact JSON quad tables")->required();
  app.add_option("--mesh", mesh_path, "closed control mesh (.obj): polygons for a quad scheme, triangles for a triangle scheme")->required();
  app.add_option("--face", face_text, "face number, from 0 in file order");
  app.add_option("--uv", uv, "parameters U,V as exact rationals, e.g. 1/3,1/2");
  app.add_option("--batch", batch, "file of `F U V` lines; prints one `x y z` line per query");
  return stencil_tools::run_tool(app, argc, argv, [&] {
    if (batch.empty() && (face_text.empty() || uv.empty()))
      throw std::runtime_error("give --face and --uv, or --batch (see --help)");
    if (!batch.empty() && (!face_text.empty() || !uv.empty()))
      throw std::runtime_error("--batch replaces --face and --uv; give one or the other");
    const auto tables = Tables::load(tables_spec);
    const Mesh mesh = read_obj(mesh_path);  // after the tables, so that a bad table file is reported first
    const Surface surface(SurfaceTopology::create(tables, mesh.vertex_count(), mesh.face_sizes, mesh.face_vertices),
                          mesh.positions);
    if (!batch.empty()) {
      std::istringstream in(stencil_tools::read_text_file(batch));
      std::string line;
      long number = 0;
      std::string out;
      while (std::getline(in, line)) {
        ++number;
        std::istringstream ls(line);
        std::string f, u, v, extra;
        if (!(ls >> f) || f[0] == '#') continue;
        try {
          if (!(ls >> u >> v) || (ls >> extra)) throw std::runtime_error("expected `F U V`, got '" + line + "'");
          const Point p = evaluate(surface, stencil_tools::parse_index(f, "face"), stencil_tools::parse_parameter(u),
                                   stencil_tools::parse_parameter(v));
          char text[96];
          std::snprintf(text, sizeof text, "%.17g %.17g %.17g\n", p[0], p[1], p[2]);
          out += text;
        } catch (const std::exception& e) {
          throw std::runtime_error(batch + ":" + std::to_string(number) + ": " + e.what());
        }
      }
      std::fputs(out.c_str(), stdout);  // all or nothing
      return 0;
    }
    const std::size_t face = stencil_tools::parse_index(face_text, "--face");
    const auto [u, v] = stencil_tools::split_pair(uv, "--uv");
    const Point p = evaluate(surface, face, stencil_tools::parse_parameter(u), stencil_tools::parse_parameter(v));
    std::printf("face %zu at (%s): limit point of '%s'\n%.17g %.17g %.17g\n", face, uv.c_str(), tables->scheme().c_str(), p[0],
                p[1], p[2]);
    return 0;
  });
}
