#include "stencil_runtime/triangle_surface.hpp"

#include <stdexcept>

namespace stencil_runtime {

TriangleSurface::TriangleSurface(const TriangleTables& tables, const Mesh& mesh, const std::string& scheme_name)
    : TriangleSurface(tables, mesh.face_count(), prepare_triangle_mesh(mesh, tables, scheme_name)) {}

TriangleSurface::TriangleSurface(const TriangleTables& tables, std::size_t original_faces, PreparedTriangleMesh&& prepared)
    : tables_(tables),
      original_faces_(original_faces),
      prepared_(std::move(prepared.prepared)),
      topology_(std::move(prepared.topology)),
      patches_(std::move(prepared.patches)) {}

namespace {

// The weights at patch point (a/(3n), b/(3n)) of the face, from its grid.
const double* weights_at(const TriangleTables::Grid& grid, const TrianglePatch& p, long a, long b, long n) {
  long pa = 0, pb = 0;
  p.to_patch(a, b, 3 * n, pa, pb);
  if (pa < 0 || pb < 0 || pb % 3 != pa % 3 || pa + pb > 3 * n)
    throw std::out_of_range("a stencil point must be a node or the centre of a small triangle of the face");
  return grid.weights(static_cast<TriangleTables::GridPoint>(pa % 3), pa / 3, pb / 3);
}

}  // namespace

const double* TriangleSurface::stencil(std::size_t face, long a, long b, long n) const {
  const TrianglePatch& p = patches_.at(face);
  return weights_at(tables_.grid(p.valence, static_cast<int>(n), p.region), p, a, b, n);
}

void TriangleSurface::evaluate_centres(std::size_t face, int n, std::array<float, 3>* out) const {
  const TrianglePatch& p = patches_[face];
  const auto& pos = prepared_.mesh.positions;
  const std::size_t m = p.points.size();
  thread_local std::vector<std::array<double, 3>> local;
  local.resize(m);
  for (std::size_t h = 0; h < m; ++h) local[h] = pos[static_cast<std::size_t>(p.points[h])];
  const TriangleTables::Grid grid = tables_.grid(p.valence, n, p.region);
  auto put = [&](long a, long b) {
    const double* w = weights_at(grid, p, a, b, n);
    double x = 0, y = 0, z = 0;
    for (std::size_t h = 0; h < m; ++h) x += w[h] * local[h][0], y += w[h] * local[h][1], z += w[h] * local[h][2];
    *out++ = {static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)};
  };
  for (long j = 0; j < n; ++j)
    for (long i = 0; i + j <= n - 1; ++i) put(3 * i + 1, 3 * j + 1);
  for (long j = 0; j + 1 < n; ++j)
    for (long i = 0; i + j <= n - 2; ++i) put(3 * i + 2, 3 * j + 2);
}

Point TriangleSurface::evaluate(std::size_t face, long i, long j, long n) const {
  if (face >= original_faces_)
    throw std::out_of_range("face " + std::to_string(face) + " does not exist (the mesh has " +
                            std::to_string(original_faces_) + " faces)");
  if (n < 1 || i < 0 || j < 0 || i + j > n) throw std::out_of_range("parameter outside the triangle (u, v >= 0, u + v <= 1)");
  if (!tables_.has_rate(static_cast<int>(n)))
    throw std::out_of_range("rate " + std::to_string(n) + " is not in the tables");
  const FaceParameter at = locate_triangle(prepared_, face, i, j, n);
  const TrianglePatch& p = patches_[at.face];
  return apply_stencil(stencil(at.face, 3 * at.i, 3 * at.j, n), p.points, prepared_.mesh.positions);
}

}  // namespace stencil_runtime
