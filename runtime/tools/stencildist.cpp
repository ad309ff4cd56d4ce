// stencildist: closest points on, and distances to, the exact limit surface of
// a control mesh, for a file of query points.
#include <chrono>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <string>

#include "points_file.hpp"
#include "stencil_runtime/closest_point.hpp"
#include "stencil_runtime/error.hpp"
#include "stencil_runtime/mesh_io.hpp"
#include "stencil_runtime/surface.hpp"
#include "tool_support.hpp"

namespace {

// Why a mesh's surface is open: an edge in one face (a boundary), or, where
// every edge is in two faces or more, an edge in three or more or two faces
// that run it the same way (non-manifold: the surface is cut open there).
std::string open_edge_reason(const stencil_runtime::Mesh& mesh) {
  std::map<std::pair<int, int>, int> faces;  // undirected edge -> faces
  std::set<std::pair<int, int>> directed;
  std::optional<std::pair<int, int>> twice;  // an edge two faces run the same way
  std::size_t corner = 0;
  for (const int size : mesh.face_sizes) {
    for (int c = 0; c < size; ++c) {
      const int a = mesh.face_vertices[corner + static_cast<std::size_t>(c)];
      const int b = mesh.face_vertices[corner + static_cast<std::size_t>((c + 1) % size)];
      ++faces[{std::min(a, b), std::max(a, b)}];
      if (!directed.insert({a, b}).second && !twice) twice = std::pair{a, b};
    }
    corner += static_cast<std::size_t>(size);
  }
  for (const auto& [edge, count] : faces)
    if (count == 1)
      return "has a boundary (edge " + std::to_string(edge.first) + "-" + std::to_string(edge.second) +
             " is in one face; vertices numbered from 0)";
  const std::string cut = "), where the surface is cut open as OpenSubdiv cuts it (vertices numbered from 0)";
  for (const auto& [edge, count] : faces)
    if (count > 2)
      return "has non-manifold edges (edge " + std::to_string(edge.first) + "-" + std::to_string(edge.second) + " is in " +
             std::to_string(count) + " faces" + cut;
  if (twice)
    return "has non-manifold edges (two faces run edge " + std::to_string(twice->first) + "-" + std::to_string(twice->second) +
           " the same way: one is flipped against the other" + cut;
  return "has a boundary";
}

using namespace stencil_runtime;

// The result lines: `face u v x y z distance [nx ny nz]`, or `none`.
std::string result_lines(const std::vector<ClosestPoint>& results, bool normals, bool signed_distance) {
  std::string out;
  char line[512];
  for (const ClosestPoint& r : results) {
    if (!r.found) {
      out += "none\n";
      continue;
    }
    int n = std::snprintf(line, sizeof line, "%zu %.17g %.17g %.17g %.17g %.17g %.17g", r.face, r.u, r.v, r.point[0],
                          r.point[1], r.point[2], signed_distance ? r.signed_distance : r.distance);
    if (normals) n += std::snprintf(line + n, sizeof line - n, " %.17g %.17g %.17g", r.normal[0], r.normal[1], r.normal[2]);
    out.append(line, static_cast<std::size_t>(n)).push_back('\n');
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "stencildist: closest points on the exact limit surface of a control mesh, and the distances to it,\n"
      "from stencilgen's tables (a quad scheme's .sgs with a polygon mesh, a triangle scheme's .sgt with a triangle\n"
      "mesh). One line per query point, in input order: `face u v x y z distance` (face numbered from 0 in file\n"
      "order, (u, v) in that face's domain as stencileval --help describes), plus `nx ny nz` (the unit normal) with\n"
      "--normals; `none` for a point farther than --max-distance. A summary goes to stderr (and, on a long run,\n"
      "a progress line every few seconds). Each distance is at\n"
      "most --tolerance above the true distance to the limit surface (docs/runtime.md, \"Closest points\").\n\n"
      "  stencildist --tables tables/catmull-clark --mesh meshes/chess-piece.obj --points queries.xyz --out d.txt\n"
      "  stencildist --tables tables/nonpoly --mesh meshes/cube.obj --points scan.ply --signed --normals",
      "stencildist"};
  std::string tables_spec, mesh_path, points_path, out_path;
  bool signed_distance = false, normals = false;
  double tolerance = 1e-9, max_distance = INFINITY;
  int threads = 0;
  app.add_option("--tables", tables_spec, "a .sgs or .sgt table file, or the directory stencilgen wrote it to")->required();
  app.add_option("--mesh", mesh_path, "control mesh (.obj, or .off or .ply by its extension): closed, or with boundaries for a quad scheme or Loop (no --signed then)")->required();
  app.add_option("--points", points_path, "query points: .ply or .off (vertices; either case), any other name `x y z` or `x y z nx ny nz` lines (.xyz, .txt)")->required();
  app.add_option("--out", out_path, "result file (default: standard output)");
  app.add_flag("--signed", signed_distance, "signed distances: negative inside the surface (outward-oriented faces)");
  app.add_flag("--normals", normals, "append the unit normal at the closest point");
  app.add_option("--tolerance", tolerance,
                 "largest amount a distance may exceed the true one, as a fraction of the control mesh's bounding-box "
                 "diagonal (default 1e-9)");
  app.add_option("--max-distance", max_distance, "points farther than this (absolute) give `none` (default: no limit)");
  app.add_option("--threads", threads, "threads for the queries (default 0: all cores)");
  stencil_tools::BoundaryOption boundary;
  boundary.add(app);
  return stencil_tools::run_tool(app, argc, argv, [&] {
    if (!(tolerance > 0) || !std::isfinite(tolerance)) throw std::runtime_error("--tolerance must be a positive finite number");
    if (tolerance < 1e-14)
      throw std::runtime_error("--tolerance must be at least 1e-14 (a fraction of the diagonal; doubles resolve about "
                               "1e-16 of it)");
    if (!(max_distance > 0)) throw std::runtime_error("--max-distance must be a positive number");
    if (threads < 0 || threads > 256) throw std::runtime_error("--threads must be 1..256 (or 0 for all cores)");
    const stencil_tools::TableInput read = stencil_tools::table_input(tables_spec);
    stencil_tools::check_output_is_not_input(out_path, {read.file, mesh_path, points_path}, {read.folder});
    stencil_tools::check_output_can_be_written(out_path);
    const auto tables = Tables::load(tables_spec);
    Mesh mesh = read_mesh(mesh_path);
    boundary.apply(mesh);
    for (const std::string& warning : mesh.warnings) std::cerr << warning << '\n';
    const std::vector<Point> queries = stencil_tools::read_points(points_path);

    const auto topology = SurfaceTopology::create(tables, mesh);
    if (signed_distance && topology->has_boundary())
      throw std::runtime_error(mesh_path + ": --signed needs a closed surface, and this mesh " + open_edge_reason(mesh));
    if (signed_distance && topology->has_holes())
      throw std::runtime_error(mesh_path + ": --signed needs a closed surface, and this mesh has faces tagged `hole` "
                               "(line " + std::to_string(mesh.tags.holes.front().line) + ")");
    const Surface surface(topology, mesh.positions);
    ClosestPointOptions options;
    options.tolerance = tolerance * surface.control_diagonal();  // --tolerance is a fraction of the control mesh's diagonal
    options.max_distance = max_distance;
    options.threads = threads;
    const auto start_all = std::chrono::steady_clock::now();
    auto last = start_all;
    options.progress = [&](std::size_t done, std::size_t total) {  // long runs: a line every few seconds
      const auto now = std::chrono::steady_clock::now();
      if (now - last < std::chrono::seconds(3)) return;
      last = now;
      std::fprintf(stderr, "stencildist: %zu of %zu points (%.0f%%), %.0f s\n", done, total, 100.0 * done / total,
                   std::chrono::duration<double>(now - start_all).count());
    };
    const ClosestPointQuery query(surface, options);
    const auto start = std::chrono::steady_clock::now();
    const std::vector<ClosestPoint> results = query.find(queries);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    const std::string lines = result_lines(results, normals, signed_distance);
    if (out_path.empty()) std::fwrite(lines.data(), 1, lines.size(), stdout);
    else stencil_tools::write_text_file(out_path, lines);  // all or nothing
    double largest = 0, sum = 0;
    std::size_t found = 0;
    for (const ClosestPoint& r : results)
      if (r.found) largest = std::max(largest, r.distance), sum += r.distance, ++found;
    std::fprintf(stderr,
                 "%zu points (%zu within the maximum distance), %.3f s (%.0f queries/s; query structure built in %.3f s, "
                 "%.1f MB), distance max %.9g mean %.9g, tolerance %.3g\n",
                 queries.size(), found, seconds, seconds > 0 ? queries.size() / seconds : 0.0, query.build_seconds(),
                 query.memory_bytes() / 1e6, largest, found ? sum / found : 0.0, query.tolerance());
    return 0;
  });
}
