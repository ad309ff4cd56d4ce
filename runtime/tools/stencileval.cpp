// stencileval: limit points of a control mesh at exact rational parameters,
// from the tables written by stencilgen, for any scheme family.
#include <iostream>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "stencil_runtime/error.hpp"
#include "stencil_runtime/mesh_io.hpp"
#include "stencil_runtime/surface.hpp"
#include "tool_support.hpp"

namespace {

using namespace stencil_runtime;
using stencil_tools::ParameterText;

// The diagonal of the bounding box of a face's control points (its corners).
double face_extent(const Mesh& mesh, std::size_t face) {
  std::size_t first = 0;
  for (std::size_t f = 0; f < face; ++f) first += static_cast<std::size_t>(mesh.face_sizes[f]);
  Point lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (int c = 0; c < mesh.face_sizes[face]; ++c) {
    const Point& p = mesh.positions[static_cast<std::size_t>(mesh.face_vertices[first + static_cast<std::size_t>(c)])];
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  }
  return std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) + (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

void check_face(const Mesh& mesh, std::size_t face) {
  if (face >= mesh.face_count())
    throw EvaluationError("face " + std::to_string(face) + " does not exist (the mesh has " + std::to_string(mesh.face_count()) +
                          " faces, numbered from 0)");
}

// Exact rationals stay exact where the tables reach them; decimals (and
// rationals they do not reach) are evaluated within `relative` of the face's
// control-point extent, and the bound comes back.
Evaluation evaluate(const Surface& surface, const Mesh& mesh, std::size_t face, const ParameterText& u, const ParameterText& v,
                    double relative) {
  check_face(mesh, face);
  const double tolerance = relative * face_extent(mesh, face);
  const Evaluation e = u.exact && v.exact ? surface.evaluate(face, ExactParameter{u.fraction, v.fraction}, tolerance)
                                          : surface.evaluate(face, u.value, v.value, tolerance);
  if (!e.exact && e.bound > tolerance) {  // a promise the output cannot keep is an error, not a footnote
    char text[160];
    std::snprintf(text, sizeof text, "face %zu: the error bound reached, %.3g, is above the tolerance %.3g", face, e.bound, tolerance);
    throw std::runtime_error(std::string(text) + (surface.topology().tables().single_precision()
                                                      ? " (these tables are single precision: their weights' rounding "
                                                        "alone is about 2^-20 of the coordinates); give a larger "
                                                        "--tolerance, or tables made without --binary-precision single"
                                                      : " (doubles resolve no more here); give a larger --tolerance"));
  }
  return e;
}

// First derivatives, and second ones where asked for (zero otherwise).
// What a query prints besides the point.
struct Columns {
  bool derivatives = false, second = false, normal = false;
  bool any() const { return derivatives || second || normal; }
};

struct Query {
  SecondDerivatives d;  // the point, and the derivatives asked for
  Point normal{0, 0, 0};
};

// With --normal alone the normal comes from Surface::normal, which also
// answers at an extraordinary vertex (tangent stencils); with derivatives it is
// theirs.
Query derivatives(const Surface& surface, const Mesh& mesh, std::size_t face, const ParameterText& u,
                  const ParameterText& v, const Columns& columns, double tolerance) {
  check_face(mesh, face);
  const bool exact = u.exact && v.exact;
  const ExactParameter at{u.fraction, v.fraction};
  Query q;
  if (columns.second) {
    q.d = exact ? surface.second_derivatives(face, at) : surface.second_derivatives(face, u.value, v.value);
  } else if (columns.derivatives) {
    static_cast<Derivatives&>(q.d) = exact ? surface.derivatives(face, at) : surface.derivatives(face, u.value, v.value);
  } else {
    q.d.point = evaluate(surface, mesh, face, u, v, tolerance).point;
    q.normal = exact ? surface.normal(face, at) : surface.normal(face, u.value, v.value);
    return q;
  }
  q.normal = q.d.normal();
  return q;
}

// The last line of a query: the point, then du and dv (--derivatives), duu,
// duv and dvv (--second-derivatives), then the unit normal (--normal).
std::string result_line(const Query& q, const Columns& columns) {
  const SecondDerivatives& d = q.d;
  const bool with_derivatives = columns.derivatives, with_normal = columns.normal;
  std::string out;
  char text[80];
  auto put = [&](const Point& p) {
    std::snprintf(text, sizeof text, "%s%.17g %.17g %.17g", out.empty() ? "" : " ", p[0], p[1], p[2]);
    out += text;
  };
  put(d.point);
  if (with_derivatives) put(d.du), put(d.dv);
  if (columns.second) put(d.duu), put(d.duv), put(d.dvv);
  if (with_normal) put(q.normal);
  return out + "\n";
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "stencileval: exact limit points of a control mesh at rational parameters, from stencilgen's tables\n"
      "(a quad scheme's .sgs with a polygon mesh, a triangle scheme's .sgt with a triangle mesh).\n"
      "Faces are numbered from 0 in file order. What (u, v) means on face F (v0, v1, ...) as listed in the OBJ file,\n"
      "as in OpenSubdiv's Bfr:\n"
      "  quad (quad scheme): (0,0) at v0, u along v0->v1, v along v0->v3, 0 <= u, v <= 1;\n"
      "  triangle (triangle scheme): u along v0->v1, v along v0->v2, u + v <= 1;\n"
      "  N-gon (quad scheme, N != 4): sub-face s (the quad at corner s after the scheme's polygon step) is the tile\n"
      "  [s % U, s % U + 1/2] x [s / U, s / U + 1/2], U = 2 (N = 3), 3 (N = 5..9), 1 + floor(sqrt(N - 1)) above.\n"
      "U and V are exact rationals (1/3) or decimals (0.3). Exact where the tables hold the parameter, directly or\n"
      "after the scheme's own subdivision of the patch (most decimals are exact binary fractions and are reached);\n"
      "otherwise within --tolerance times the face's control-point extent, and the line before the point says\n"
      "how far it may be from the exact one. Prints the point as `x y z` on the last line.\n"
      "--derivatives adds d/du and d/dv along the face's (u, v), --normal the unit normal (du x dv, outward for\n"
      "counter-clockwise faces); every quad and triangle scheme. They are exact to rounding on polynomial schemes\n"
      "(Catmull-Clark, Loop), for nonpoly at any parameter (its regular curve's basis and derivative follow the\n"
      "parameter's halvings to a stored grid or round their cycle: docs/runtime.md), and for sqrt(3) at exact\n"
      "rationals k/n of a stored rate n and the thirds its subdivision reaches from them (other parameters are\n"
      "refused). The point printed with them is computed the same way: where the point alone would be evaluated\n"
      "within --tolerance (the line before it gives the bound), the two may differ by up to that bound. At an\n"
      "extraordinary vertex the surface has no parametric derivative and --derivatives is refused; --normal alone\n"
      "still answers there (the tables' tangent stencils: subdominant left eigenvectors).\n"
      "The last line then holds `x y z dux duy duz dvx dvy dvz` (and/or `nx ny nz`), the lines before it each\n"
      "vector by name.\n"
      "--second-derivatives adds d2/du2, d2/dudv and d2/dv2 (after du and dv, before the normal): exact to rounding\n"
      "where the scheme's regular patches are polynomial (Catmull-Clark, Loop), anywhere but an extraordinary\n"
      "vertex; refused for other schemes (their tables hold no second derivative).\n"
      "OpenSubdiv's OBJ tag lines (`t crease ...`, `t corner ...`, `t hole ...`, `t creasemethod ...`,\n"
      "`t smoothtriangles ...`) are read: a face tagged `hole` has no surface (evaluating it is an error; the faces\n"
      "round it are unchanged, as in OpenSubdiv); semi-sharp creases and corners (sharpness below 10; uniform or\n"
      "Chaikin) are resolved by a few subdivision steps with OpenSubdiv's sharp rules, then evaluated exactly\n"
      "(Catmull-Clark, nonpoly, Loop; not sqrt(3)); `smoothtriangles` is Catmull-Clark's triangle rule. Infinitely\n"
      "sharp creases, corners, darts and cone points (10 or more; a cone point is a sharp vertex on no sharp edge:\n"
      "--normal there says it has none) are exact for quad schemes (the patches of the mesh cut along them); Loop:\n"
      "creases, corners, darts and cone points exactly too; unknown tags are warned about.\n"
      "Meshes with boundaries (quad schemes and Loop; `t interpolateboundary` or --boundary\n"
      "edge-only|edge-and-corner|none): every boundary vertex, in any number of faces, as OpenSubdiv's rules make\n"
      "it, exactly (tables cover vertices in up to as many faces as their largest valence); with none the faces at\n"
      "boundary vertices have no surface (like holes). --normal at a boundary vertex where the rules give no\n"
      "tangent plane (a corner; Loop: a boundary vertex in six or more faces) says so. As in OpenSubdiv, vertices\n"
      "in no face are ignored, and a vertex where pieces of surface meet only at a point (its faces form several\n"
      "fans) is an infinitely sharp corner of each.\n\n"
      "  stencileval --tables tables/nonpoly --mesh meshes/cube.obj --face 0 --uv 1/3,1/2\n"
      "  stencileval --tables tables/nonpoly --mesh meshes/cube.obj --batch queries.txt   (lines: F U V)\n"
      "  stencileval --tables tables/nonpoly --mesh meshes/cube.obj --face 0 --uv 0.3,0.7\n"
      "  stencileval --tables tables/nonpoly --mesh meshes/cube.obj --face 0 --uv 1/3,1/2 --derivatives --normal\n"
      "  stencileval --tables tables/loop --mesh meshes/tri-torus.obj --face 0 --uv 1/3,1/3",
      "stencileval"};
  std::string tables_spec, mesh_path, uv, batch, face_text;
  double tolerance = 1e-12;
  app.add_option("--tables", tables_spec, "a .sgs or .sgt table file, the directory stencilgen wrote it to, or a directory of exact JSON quad tables")->required();
  app.add_option("--mesh", mesh_path, "control mesh (.obj, or .off or .ply by its extension): polygons for a quad scheme (closed, or with boundaries: see above), triangles for a triangle scheme (closed; Loop: or with boundaries)")->required();
  app.add_option("--face", face_text, "face number, from 0 in file order");
  app.add_option("--uv", uv, "parameters U,V: exact rationals (1/3,1/2) or decimals (0.3,0.7)");
  app.add_option("--tolerance", tolerance,
                 "where the tables do not reach the parameter: largest error as a fraction of the face's control-point "
                 "extent, 1e-14 or more (default 1e-12); a bound above it is an error");
  app.add_option("--batch", batch, "file of `F U V` lines; prints one `x y z` line per query (with the columns "
                                   "--derivatives and --normal add)");
  stencil_tools::BoundaryOption boundary;
  boundary.add(app);
  Columns columns;
  app.add_flag("--derivatives", columns.derivatives, "also d/du and d/dv (every scheme; sqrt(3) at the parameters its tables hold)");
  app.add_flag("--second-derivatives", columns.second, "also d2/du2, d2/dudv, d2/dv2 (Catmull-Clark, Loop)");
  app.add_flag("--normal", columns.normal, "also the unit normal (every scheme; sqrt(3) at the parameters its tables hold)");
  return stencil_tools::run_tool(app, argc, argv, [&] {
    if (!(tolerance > 0) || !std::isfinite(tolerance)) throw std::runtime_error("--tolerance must be a positive finite number");
    if (tolerance < 1e-14)
      throw std::runtime_error("--tolerance must be at least 1e-14 (a fraction of the face's extent; doubles resolve about "
                               "1e-16 of it)");
    if (batch.empty() && (face_text.empty() || uv.empty()))
      throw std::runtime_error("give --face and --uv, or --batch (see --help)");
    if (!batch.empty() && (!face_text.empty() || !uv.empty()))
      throw std::runtime_error("--batch replaces --face and --uv; give one or the other");
    const auto tables = Tables::load(tables_spec);
    Mesh mesh = read_mesh(mesh_path);  // after the tables, so that a bad table file is reported first
    boundary.apply(mesh);
    for (const std::string& warning : mesh.warnings) std::cerr << warning << '\n';
    const Surface surface(SurfaceTopology::create(tables, mesh),
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
          if (!(ls >> u >> v) || (ls >> extra)) throw std::runtime_error("expected `F U V`, got " + stencil_runtime::quoted_excerpt(line));
          const std::size_t face = stencil_tools::parse_index(f, "face");
          const ParameterText pu = stencil_tools::parse_parameter(u), pv = stencil_tools::parse_parameter(v);
          if (columns.any()) {
            out += result_line(derivatives(surface, mesh, face, pu, pv, columns, tolerance), columns);
          } else {
            Query q;
            q.d.point = evaluate(surface, mesh, face, pu, pv, tolerance).point;
            out += result_line(q, columns);
          }
        } catch (const std::exception& e) {
          throw std::runtime_error(batch + ":" + std::to_string(number) + ": " + e.what());
        }
      }
      if (out.empty()) throw std::runtime_error(batch + ": no queries (expected lines `F U V`)");
      std::fputs(out.c_str(), stdout);  // all or nothing
      return 0;
    }
    const std::size_t face = stencil_tools::parse_index(face_text, "--face");
    const auto [u, v] = stencil_tools::split_pair(uv, "--uv");
    if (columns.any()) {
      const Query q = derivatives(surface, mesh, face, stencil_tools::parse_parameter(u), stencil_tools::parse_parameter(v),
                                  columns, tolerance);
      const SecondDerivatives& d = q.d;
      std::printf("face %zu at (%s): limit point of '%s'%s%s%s\n", face, uv.c_str(), tables->scheme().c_str(),
                  columns.derivatives ? ", its derivatives d/du and d/dv" : "",
                  columns.second ? ", its second derivatives" : "", columns.normal ? ", the unit normal" : "");
      auto line = [](const char* name, const Point& p) { std::printf("%s %.17g %.17g %.17g\n", name, p[0], p[1], p[2]); };
      line("point", d.point);
      if (columns.derivatives) line("du", d.du), line("dv", d.dv);
      if (columns.second) line("duu", d.duu), line("duv", d.duv), line("dvv", d.dvv);
      if (columns.normal) line("normal", q.normal);
      std::fputs(result_line(q, columns).c_str(), stdout);
      return 0;
    }
    const Evaluation e = evaluate(surface, mesh, face, stencil_tools::parse_parameter(u), stencil_tools::parse_parameter(v), tolerance);
    if (e.exact)
      std::printf("face %zu at (%s): limit point of '%s'\n", face, uv.c_str(), tables->scheme().c_str());
    else
      std::printf("face %zu at (%s): limit point of '%s', within %.3g of the exact one (bound; tolerance %.3g)\n", face,
                  uv.c_str(), tables->scheme().c_str(), e.bound, tolerance * face_extent(mesh, face));
    std::printf("%.17g %.17g %.17g\n", e.point[0], e.point[1], e.point[2]);
    return 0;
  });
}
