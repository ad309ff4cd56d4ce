#include "stencil_runtime/limit_surface.hpp"

#include <stdexcept>
#include <vector>

namespace stencil_runtime {

LimitSurface::LimitSurface(const SurfaceTables& tables, const Mesh& mesh, const std::string& scheme_name)
    : tables_(tables),
      original_faces_(mesh.face_count()),
      prepared_(prepare_mesh(mesh, tables, scheme_name)),
      topology_(prepared_.mesh) {
  patches_.reserve(topology_.faces());
  for (std::size_t f = 0; f < topology_.faces(); ++f) patches_.push_back(gather_patch(topology_, f));
}

void LimitSurface::stencil(std::size_t face, long a, long b, long n, double* weights) const {
  const Patch& p = patches_.at(face);
  long pa = 0, pb = 0;
  p.to_patch(a, b, 2 * n, pa, pb);
  const bool centre = (pa & 1) != 0;
  if (((pa ^ pb) & 1) != 0) throw std::out_of_range("a stencil point must be a node or a cell centre");
  if (centre)
    tables_.centre_stencil(p.valence, static_cast<int>(n), static_cast<int>(pa / 2), static_cast<int>(pb / 2), weights);
  else
    tables_.node_stencil(p.valence, static_cast<int>(n), static_cast<int>(pa / 2), static_cast<int>(pb / 2), weights);
}

void LimitSurface::evaluate_centres(std::size_t face, int n, std::array<float, 3>* out) const {
  const Patch& p = patches_[face];
  const auto& pos = prepared_.mesh.positions;
  if (p.valence == 4) {
    // Rows first: R[q][i] = sum_p wx(i)[p] P(p, q), then each point sums 4 rows.
    thread_local std::vector<double> wx;
    thread_local std::vector<std::array<double, 3>> rows;
    wx.resize(4 * static_cast<std::size_t>(n));
    rows.resize(4 * static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) tables_.regular_weights(n, 2L * i + 1, wx.data() + 4 * i);
    for (int q = 0; q < 4; ++q)
      for (int i = 0; i < n; ++i) {
        std::array<double, 3> acc{0, 0, 0};
        for (int c = 0; c < 4; ++c) {
          const auto& P = pos[static_cast<std::size_t>(p.points[static_cast<std::size_t>(q * 4 + c)])];
          const double s = wx[static_cast<std::size_t>(4 * i + c)];
          acc[0] += s * P[0], acc[1] += s * P[1], acc[2] += s * P[2];
        }
        rows[static_cast<std::size_t>(q * n + i)] = acc;
      }
    for (int j = 0; j < n; ++j) {
      const double* wy = wx.data() + 4 * j;  // same weights: the grid is square
      for (int i = 0; i < n; ++i) {
        double x = 0, y = 0, z = 0;
        for (int q = 0; q < 4; ++q) {
          const auto& r = rows[static_cast<std::size_t>(q * n + i)];
          x += wy[q] * r[0], y += wy[q] * r[1], z += wy[q] * r[2];
        }
        out[static_cast<std::size_t>(j * n + i)] = {static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)};
      }
    }
    return;
  }
  const std::size_t m = p.points.size();
  // The control points, contiguous, and in reflected order for mirrored stencils.
  thread_local std::vector<std::array<double, 3>> local, reflected;
  local.resize(m);
  reflected.resize(m);
  const std::uint32_t* reflect = tables_.reflection(p.valence);
  for (std::size_t h = 0; h < m; ++h) local[h] = pos[static_cast<std::size_t>(p.points[h])];
  for (std::size_t h = 0; h < m; ++h) reflected[h] = local[reflect[h]];
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      long pa = 0, pb = 0;
      p.to_patch(2L * i + 1, 2L * j + 1, 2L * n, pa, pb);
      bool mirrored = false;
      const double* wt = tables_.centre_weights(p.valence, n, static_cast<int>(pa / 2), static_cast<int>(pb / 2), mirrored);
      const auto& P = mirrored ? reflected : local;
      double x = 0, y = 0, z = 0;
      for (std::size_t h = 0; h < m; ++h) x += wt[h] * P[h][0], y += wt[h] * P[h][1], z += wt[h] * P[h][2];
      out[static_cast<std::size_t>(j * n + i)] = {static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)};
    }
}

Point LimitSurface::evaluate(std::size_t face, long i, long j, long n) const {
  if (face >= original_faces_)
    throw std::out_of_range("face " + std::to_string(face) + " does not exist (the mesh has " +
                            std::to_string(original_faces_) + " faces)");
  if (n < 1 || i < 0 || j < 0 || i > n || j > n) throw std::out_of_range("parameter outside the face");
  if (!tables_.has_rate(static_cast<int>(n)))
    throw std::out_of_range("rate " + std::to_string(n) + " is not in the tables");
  const FaceParameter at = locate(prepared_, face, i, j, n);
  const Patch& p = patches_[at.face];
  double w[2 * 64 + 8];
  if (p.points.size() > sizeof w / sizeof w[0]) throw std::out_of_range("valence too large");
  stencil(at.face, 2 * at.i, 2 * at.j, n, w);
  return apply_stencil(w, p.points, prepared_.mesh.positions);
}

}  // namespace stencil_runtime
