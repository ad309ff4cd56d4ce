#include "stencil_reconstruction/initial_mesh.hpp"

#include <chrono>
#include <cmath>
#include <algorithm>
#include <map>
#include <random>

#include "advancing_front.hpp"
#include "simplification.hpp"
#include "surface_repair.hpp"

namespace stencil_reconstruction {

using stencil_runtime::Mesh;
using stencil_runtime::Point;

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Whether the points span space (a closed surface through them needs four
// that are not coplanar), by CGAL's exact predicates.
bool spans_space(const std::vector<CgalPoint>& points) {
  std::size_t b = 1;
  while (b < points.size() && points[b] == points[0]) ++b;
  std::size_t c = b + 1;
  while (c < points.size() && CGAL::collinear(points[0], points[b], points[c])) ++c;
  for (std::size_t d = c + 1; d < points.size(); ++d)
    if (!CGAL::coplanar(points[0], points[b], points[c], points[d])) return true;
  return false;
}

Mesh to_mesh(const TriangleMesh& surface) {
  Mesh mesh;
  std::map<TriangleMesh::Vertex_index, int> index;
  for (const auto v : surface.vertices()) {
    index[v] = static_cast<int>(mesh.positions.size());
    const CgalPoint& p = surface.point(v);
    mesh.positions.push_back({p.x(), p.y(), p.z()});
  }
  for (const auto f : surface.faces()) {
    int size = 0;
    for (const auto v : CGAL::vertices_around_face(surface.halfedge(f), surface)) {
      mesh.face_vertices.push_back(index.at(v));
      ++size;
    }
    mesh.face_sizes.push_back(size);
  }
  return mesh;
}

}  // namespace

Mesh initial_control_mesh(const std::vector<Point>& points, const InitialMeshOptions& options, InitialMeshReport* report) {
  if (options.control_points < 4)
    throw ReconstructionError("the initial mesh needs at least 4 control points, not " + std::to_string(options.control_points));
  std::vector<CgalPoint> cgal_points;
  cgal_points.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (const double x : points[i])
      if (!std::isfinite(x)) throw ReconstructionError("point " + std::to_string(i) + " has a coordinate that is not finite");
    cgal_points.emplace_back(points[i][0], points[i][1], points[i][2]);
  }
  if (points.size() < 4) throw ReconstructionError("a surface needs at least 4 points, not " + std::to_string(points.size()));
  if (!spans_space(cgal_points))
    throw ReconstructionError("the points are coplanar (or collinear, or all equal): no closed surface passes through them");
  const auto say = [&](const std::string& stage) {
    if (options.progress) options.progress(stage);
  };
  InitialMeshReport local;
  InitialMeshReport& r = report ? *report : local;

  auto start = std::chrono::steady_clock::now();
  // A coarse control mesh does not need every point of a large scan: a fixed
  // pseudo-random subset (linear time) keeps the reconstruction and the
  // simplification, which grow faster than linearly, to a bounded size.
  const std::size_t kept = std::max(options.max_points_per_control_point * options.control_points, options.min_points);
  if (cgal_points.size() > kept) {
    std::mt19937_64 rng(20041);
    std::shuffle(cgal_points.begin(), cgal_points.end(), rng);
    cgal_points.resize(kept);
    cgal_points.shrink_to_fit();
  }
  r.points_used = cgal_points.size();
  say("advancing-front reconstruction of " + std::to_string(cgal_points.size()) + " points");
  TriangleMesh surface = advancing_front(cgal_points);
  r.reconstruction_seconds = seconds_since(start);
  say("closing the surface (" + std::to_string(surface.number_of_faces()) + " triangles)");
  start = std::chrono::steady_clock::now();
  const RepairCounts counts = close_surface(surface);
  r.repair_seconds = seconds_since(start);
  r.holes_filled = counts.holes_filled, r.components_dropped = counts.components_dropped;
  r.reconstructed_vertices = surface.number_of_vertices(), r.reconstructed_faces = surface.number_of_faces();
  if (options.control_points > surface.number_of_vertices())
    throw ReconstructionError("the reconstructed surface has " + std::to_string(surface.number_of_vertices()) +
                              " vertices, fewer than the " + std::to_string(options.control_points) +
                              " control points asked for");
  say("simplifying " + std::to_string(surface.number_of_vertices()) + " vertices to " +
      std::to_string(options.control_points));
  start = std::chrono::steady_clock::now();
  simplify_to_vertices(surface, options.control_points);
  r.simplification_seconds = seconds_since(start);
  return to_mesh(surface);
}

}  // namespace stencil_reconstruction
